// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// A million impacts over wide ranges of every input and every law: no NaN
// or infinity, no negative energy loss, no outgoing speed above the incoming.

#include "testCases.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace brachDunn;

namespace
{

class Sampler
{
    std::mt19937_64 rng_;

public:

    explicit Sampler(unsigned seed) : rng_(seed) {}

    double uniform(double a, double b)
    {
        return std::uniform_real_distribution<double>(a, b)(rng_);
    }

    double logUniform(double a, double b)
    {
        return std::exp(uniform(std::log(a), std::log(b)));
    }

    int pick(int n)
    {
        return std::uniform_int_distribution<int>(0, n - 1)(rng_);
    }

    //- A speed from 1e-12 to 1e4 m/s, sometimes exactly 0
    double speed()
    {
        return pick(20) == 0 ? 0 : logUniform(1e-12, 1e4);
    }

    ElasticMaterial material()
    {
        return {logUniform(1e5, 1e12), uniform(-0.999, 0.5)};
    }

    RestitutionLaw restitution()
    {
        switch (pick(6))
        {
            case 0: return RestitutionLaw::constant(uniform(0, 1));
            case 1: return RestitutionLaw::powerLaw
                (logUniform(1e-3, 1e4), uniform(0, 2));
            case 2: return RestitutionLaw::viscousDamping(uniform(0, 0.999));
            case 3: return RestitutionLaw::elasticPlasticYieldVelocity
                (logUniform(1e-4, 1e3));
            case 4: return RestitutionLaw::elasticPlasticYieldStress
                (logUniform(1e5, 1e10));
            default:
            {
                Table table;
                double s = 0;
                for (int i = 0, n = 1 + pick(5); i < n; ++i)
                {
                    s += logUniform(1e-3, 1e3);
                    table.push_back({s, uniform(0, 1)});
                }
                return RestitutionLaw::table(table);
            }
        }
    }

    AdhesionLaw adhesion()
    {
        switch (pick(4))
        {
            case 0: return AdhesionLaw::none();
            case 1: return AdhesionLaw::constant(logUniform(1e-4, 10));
            case 2: return AdhesionLaw::powerLaw
                (logUniform(1e-4, 10), uniform(0, 1.5));
            default: return AdhesionLaw::vanDerWaals
                (logUniform(1e-21, 1e-17), logUniform(1e-10, 1e-8), uniform(0, 1));
        }
    }

    FrictionLaw friction()
    {
        return
            pick(2)
          ? FrictionLaw::sticking()
          : FrictionLaw::coulomb(pick(4) ? uniform(0, 2) : 0);
    }
};

} // End anonymous namespace


TEST(RandomSweep, MillionImpactsStayPhysical)
{
    const testCases::TrapFloatingPointErrors trap;
    Sampler s(2026);
    long impacts = 0, rebounds = 0, captures = 0;

    for (int modelI = 0; modelI < 2000; ++modelI)
    {
        const ImpactModel model
        (
            s.material(), s.material(), s.restitution(), s.adhesion(),
            s.friction(), s.uniform(-1, 1), s.pick(3) ? 1e-6 : 0
        );

        for (int i = 0; i < 500; ++i, ++impacts)
        {
            const Particle p{s.logUniform(1e-8, 1e-2), s.logUniform(1, 2e4)};
            const double un = s.pick(10) ? s.speed() : -s.speed();
            const double ut = s.speed();
            const double spin = s.uniform(-1e6, 1e6);

            const ImpactResult r = model.impact(p, un, ut, spin);

            const double outputs[] =
            {
                r.unOut, r.utOut, r.spinOut, r.R, r.gamma, r.WA,
                r.impulseRatio, r.normalImpulse, r.tangentialImpulse,
                r.energyLoss, r.deformationLoss, r.adhesionLoss, r.frictionLoss
            };
            for (double v : outputs)
            {
                ASSERT_TRUE(std::isfinite(v))
                    << "model " << modelI << " impact " << i
                    << ": d " << p.d << " rho " << p.rho
                    << " un " << un << " ut " << ut;
            }

            ASSERT_GE(r.energyLoss, 0);
            ASSERT_GE(r.deformationLoss, 0);
            ASSERT_GE(r.adhesionLoss, 0);
            ASSERT_GE(r.frictionLoss, 0);
            ASSERT_LE(r.WA, 0);
            ASSERT_GE(r.R, 0);
            ASSERT_LE(r.R, 1);
            ASSERT_GE(r.unOut, 0);
            ASSERT_GE(r.utOut, 0);
            ASSERT_LE
            (
                r.unOut*r.unOut + r.utOut*r.utOut,
                (un*un + ut*ut)*(1 + 1e-12)
            );

            if (r.outcome == Fate::rebound) ++rebounds;
            if (r.outcome == Fate::capture) ++captures;
        }
    }

    EXPECT_EQ(impacts, 1000000);
    // The sweep exercises both fates
    EXPECT_GT(rebounds, 10000);
    EXPECT_GT(captures, 10000);
}
