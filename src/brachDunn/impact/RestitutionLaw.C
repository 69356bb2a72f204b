// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "RestitutionLaw.H"
#include "Materials.H"

#include <algorithm>

namespace brachDunn
{
namespace restitution
{

namespace
{

//- The median of values (not empty)
double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size()/2];
}

} // End anonymous namespace


Constant Constant::make(double R)
{
    requireInRange("R", R, 0, 1);
    return {R};
}


std::vector<double> Constant::initialGuess
(
    const std::vector<double>&,
    const std::vector<double>& ratios
)
{
    return {std::clamp(median(ratios), 0.0, 1.0)};
}


PowerLaw PowerLaw::make(double k, double p)
{
    requirePositive("k", k);
    // Larger exponents have no physical meaning and would overflow un^p
    requireInRange("p", p, 0, maxExponent);
    return {k, p};
}


std::vector<double> PowerLaw::initialGuess
(
    const std::vector<double>& speeds,
    const std::vector<double>& ratios
)
{
    const double R = std::clamp(median(ratios), 0.05, 0.99);
    const double p = 0.7;
    return {R*std::pow(median(speeds), p)/(1 - R), p};
}


ViscousDamping ViscousDamping::make(double zeta)
{
    requireFinite("zeta", zeta);
    if (!(zeta >= 0 && zeta < 1))
    {
        throw InputError("zeta", toText(zeta), "must be in [0, 1)");
    }
    return {zeta, std::exp(-pi*zeta/std::sqrt(1 - zeta*zeta))};
}


ElasticPlastic ElasticPlastic::fromYieldVelocity(double vy)
{
    requirePositive("yieldVelocity", vy);
    return {vy, 0};
}


ElasticPlastic ElasticPlastic::fromYieldStress(double py)
{
    requireAboveAtMost("yieldStress", py, 0, ElasticMaterial::maxE);
    return {0, py};
}


ElasticPlastic ElasticPlastic::read(const Parameters& parameters)
{
    const auto vy = parameters.find("yieldVelocity");
    const auto py = parameters.find("yieldStress");
    if (vy && py)
    {
        throw InputError
        (
            "yieldStress",
            toText(*py),
            "give either yieldVelocity or yieldStress, not both"
        );
    }
    if (vy) return fromYieldVelocity(*vy);
    if (py) return fromYieldStress(*py);
    throw InputError
    (
        "yieldVelocity",
        "missing",
        "elasticPlastic needs yieldVelocity [m/s] or yieldStress [Pa]"
    );
}


void ElasticPlastic::write(std::ostream& os) const
{
    if (yieldStress > 0)
    {
        os << " yieldStress " << yieldStress << ";";
    }
    else
    {
        os << " yieldVelocity " << yieldVelocity << ";";
    }
}


double ElasticPlastic::velocity
(
    double yieldStress,
    double rho,
    double contactModulus
)
{
    // sqrt(pi^4/40) sqrt(py^5/(E*^4 rho)), as py (py/E*)^4 so that no power
    // of a pressure overflows
    const double ratio = yieldStress/contactModulus;
    const double ratio2 = ratio*ratio;
    return std::sqrt(pi*pi*pi*pi/40)*std::sqrt(yieldStress*ratio2*ratio2/rho);
}


double ElasticPlastic::restitution(double yieldVelocity, double un)
{
    if (!(un > yieldVelocity))
    {
        return 1;
    }
    // Thornton (1997): R = 1 at x = 1, falling as (x)^(1/4) for x -> 0
    const double x = yieldVelocity/un;
    const double first = std::sqrt(6*std::sqrt(3.0)/5);
    const double second = std::sqrt(1 - x*x/6);
    const double third =
        std::pow(x/(x + 2*std::sqrt(6.0/5 - x*x/5)), 0.25);
    return std::min(1.0, first*second*third);
}


Tabulated Tabulated::make(const Table& speedAndR)
{
    if (speedAndR.empty())
    {
        throw InputError("values", "()", "needs at least one (speed R) pair");
    }
    Tabulated table;
    for (const auto& [speed, R] : speedAndR)
    {
        requireNonNegative("values (speed)", speed);
        requireInRange("values (R)", R, 0, 1);
        if (!table.speeds.empty() && !(speed > table.speeds.back()))
        {
            throw InputError
            (
                "values (speed)",
                toText(speed),
                "speeds must increase strictly down the table"
            );
        }
        table.speeds.push_back(speed);
        table.values.push_back(R);
    }
    return table;
}


void Tabulated::write(std::ostream& os) const
{
    os << " values (";
    for (std::size_t i = 0; i < speeds.size(); ++i)
    {
        os << (i ? " " : "") << "(" << speeds[i] << " " << values[i] << ")";
    }
    os << ");";
}


double Tabulated::operator()(double un, double, double) const
{
    if (un <= speeds.front()) return values.front();
    if (un >= speeds.back()) return values.back();
    const auto upper =
        std::upper_bound(speeds.begin(), speeds.end(), un) - speeds.begin();
    const double s0 = speeds[upper - 1], s1 = speeds[upper];
    const double w = (un - s0)/(s1 - s0);
    return (1 - w)*values[upper - 1] + w*values[upper];
}

} // End namespace restitution
} // End namespace brachDunn
