// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Cost of one impact evaluation of the core, per restitution x adhesion law
// combination, beside the classical rebound arithmetic of OpenFOAM's
// standardWallInteraction (U -= (1 + e) Un n; U -= mu Ut) as the baseline.
// Timings are printed, never asserted.

#include "ImpactModel.H"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

using namespace brachDunn;

namespace
{

const ElasticMaterial fluorescein{1.2e9, 0.33};
const ElasticMaterial molybdenum{3.2e11, 0.30};

//- Impact velocities spread over 0.5-20 m/s and 0-60 degrees
std::vector<Vector3> impactVelocities()
{
    std::vector<Vector3> U;
    for (int i = 0; i < 1024; ++i)
    {
        const double speed = 0.5 + 19.5*((i*37) % 1024)/1024.0;
        const double angle = 1.05*((i*101) % 1024)/1024.0;
        U.push_back({speed*std::sin(angle), 0.1*speed, -speed*std::cos(angle)});
    }
    return U;
}

void classicalRebound(benchmark::State& state)
{
    const std::vector<Vector3> velocities = impactVelocities();
    const Vector3 nw{0, 0, -1};
    const double e = 0.9, mu = 0.1;
    std::size_t i = 0;
    for (auto _ : state)
    {
        Vector3 U = velocities[i++ & 1023];
        const double Un = dot(U, nw);
        const Vector3 Ut = U - Un*nw;
        if (Un > 0) U = U - ((1 + e)*Un)*nw;
        U = U - mu*Ut;
        benchmark::DoNotOptimize(U);
    }
}
BENCHMARK(classicalRebound);

//- The costs an impact is made of, on the same speeds: what any evaluation
//  of the power laws must pay at least
template<class Function>
void primitive(benchmark::State& state, Function function)
{
    std::vector<double> speeds;
    for (const Vector3& U : impactVelocities())
    {
        speeds.push_back(mag(U));
    }
    std::size_t i = 0;
    for (auto _ : state)
    {
        double result = function(speeds[i++ & 1023]);
        benchmark::DoNotOptimize(result);
    }
}
BENCHMARK_CAPTURE(primitive, pow, [](double x) { return std::pow(x, 0.718); });
BENCHMARK_CAPTURE(primitive, log, [](double x) { return std::log(x); });
BENCHMARK_CAPTURE(primitive, exp, [](double x) { return std::exp(x); });
BENCHMARK_CAPTURE(primitive, sqrt, [](double x) { return std::sqrt(x); });
BENCHMARK_CAPTURE(primitive, division, [](double x) { return 1/x; });

void brachDunnImpact
(
    benchmark::State& state,
    const RestitutionLaw& restitution,
    const AdhesionLaw& adhesion
)
{
    const ImpactModel model
    (
        fluorescein, molybdenum, restitution, adhesion, FrictionLaw::sticking()
    );
    const std::vector<Vector3> velocities = impactVelocities();
    const Particle particle{4.9e-6, 1350};
    const Vector3 n{0, 0, 1};
    std::size_t i = 0;
    for (auto _ : state)
    {
        Impact3D out = model.impact(particle, velocities[i++ & 1023], n);
        benchmark::DoNotOptimize(out);
    }
}

const std::pair<const char*, RestitutionLaw> restitutions[] =
{
    {"constant", RestitutionLaw::constant(0.9)},
    {"powerLaw", RestitutionLaw::powerLaw(45.3, 0.718)},
    {"viscousDamping", RestitutionLaw::viscousDamping(0.05)},
    {"elasticPlastic", RestitutionLaw::elasticPlasticYieldVelocity(0.5)},
    {"table", RestitutionLaw::table({{0, 1}, {1, 0.97}, {10, 0.9}, {100, 0.7}})},
};

const std::pair<const char*, AdhesionLaw> adhesions[] =
{
    {"none", AdhesionLaw::none()},
    {"constant", AdhesionLaw::constant(0.5)},
    {"powerLaw", AdhesionLaw::powerLaw(0.34, 0.5)},
    {"vanDerWaals", AdhesionLaw::vanDerWaals(7.3e-19, 4e-10, 0.1)},
};

const int registered = []
{
    for (const auto& [rName, r] : restitutions)
    {
        for (const auto& [aName, a] : adhesions)
        {
            benchmark::RegisterBenchmark
            (
                (std::string("impact/") + rName + "/" + aName).c_str(),
                brachDunnImpact, r, a
            );
        }
    }
    return 0;
}();

} // End anonymous namespace

BENCHMARK_MAIN();
