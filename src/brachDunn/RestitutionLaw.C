// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "RestitutionLaw.H"
#include "Selection.H"
#include "Materials.H"

#include <algorithm>
#include <sstream>

namespace brachDunn
{

namespace
{

RestitutionLaw elasticPlasticFrom(const Parameters& parameters)
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
    if (vy) return RestitutionLaw::elasticPlasticYieldVelocity(*vy);
    if (py) return RestitutionLaw::elasticPlasticYieldStress(*py);
    throw InputError
    (
        "yieldVelocity",
        "missing",
        "elasticPlastic needs yieldVelocity [m/s] or yieldStress [Pa]"
    );
}

//- The laws by type name
const Selector<RestitutionLaw> selectors[] =
{
    {"constant", [](const Parameters& p)
        { return RestitutionLaw::constant(p.get("R")); }},
    {"powerLaw", [](const Parameters& p)
        { return RestitutionLaw::powerLaw(p.get("k"), p.get("p")); }},
    {"viscousDamping", [](const Parameters& p)
        { return RestitutionLaw::viscousDamping(p.get("zeta")); }},
    {"elasticPlastic", elasticPlasticFrom},
    {"table", [](const Parameters& p)
        { return RestitutionLaw::table(p.getTable("values")); }},
};

} // End anonymous namespace


RestitutionLaw RestitutionLaw::constant(double R)
{
    requireInRange("R", R, 0, 1);
    return RestitutionLaw(Constant{R});
}


RestitutionLaw RestitutionLaw::powerLaw(double k, double p)
{
    requirePositive("k", k);
    // Larger exponents have no physical meaning and would overflow un^p
    requireInRange("p", p, 0, maxExponent);
    return RestitutionLaw(PowerLaw{k, p});
}


RestitutionLaw RestitutionLaw::viscousDamping(double zeta)
{
    requireFinite("zeta", zeta);
    if (!(zeta >= 0 && zeta < 1))
    {
        throw InputError("zeta", toText(zeta), "must be in [0, 1)");
    }
    return RestitutionLaw
    (
        ViscousDamping{zeta, std::exp(-pi*zeta/std::sqrt(1 - zeta*zeta))}
    );
}


RestitutionLaw RestitutionLaw::elasticPlasticYieldVelocity(double vy)
{
    requirePositive("yieldVelocity", vy);
    return RestitutionLaw(ElasticPlastic{vy});
}


RestitutionLaw RestitutionLaw::elasticPlasticYieldStress(double py)
{
    requireAboveAtMost("yieldStress", py, 0, ElasticMaterial::maxE);
    return RestitutionLaw(ElasticPlasticFromStress{py});
}


RestitutionLaw RestitutionLaw::table(const Table& speedAndR)
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
    return RestitutionLaw(std::move(table));
}


RestitutionLaw RestitutionLaw::select
(
    const std::string& type,
    const Parameters& parameters
)
{
    return selectByName(selectors, "restitution law", type, parameters);
}


const std::vector<std::string>& RestitutionLaw::typeNames()
{
    static const std::vector<std::string> names = selectorNames(selectors);
    return names;
}


const std::string& RestitutionLaw::typeName() const
{
    // Both elasticPlastic forms are one type name
    static const std::size_t index[] = {0, 1, 2, 3, 3, 4};
    return typeNames()[index[law_.index()]];
}


std::string RestitutionLaw::describe() const
{
    std::ostringstream os;
    os.precision(6);
    os << "type " << typeName() << ";";
    if (const auto* law = as<Constant>())
    {
        os << " R " << law->R << ";";
    }
    else if (const auto* law = as<PowerLaw>())
    {
        os << " k " << law->k << "; p " << law->p << ";";
    }
    else if (const auto* law = as<ViscousDamping>())
    {
        os << " zeta " << law->zeta << ";";
    }
    else if (const auto* law = as<ElasticPlastic>())
    {
        os << " yieldVelocity " << law->yieldVelocity << ";";
    }
    else if (const auto* law = as<ElasticPlasticFromStress>())
    {
        os << " yieldStress " << law->yieldStress << ";";
    }
    else if (const auto* law = as<Tabulated>())
    {
        os << " values (";
        for (std::size_t i = 0; i < law->speeds.size(); ++i)
        {
            os << (i ? " " : "") << "(" << law->speeds[i] << " "
               << law->values[i] << ")";
        }
        os << ");";
    }
    return os.str();
}


double RestitutionLaw::thornton(double x)
{
    // Thornton (1997): R = 1 at x = 1, falling as (x)^(1/4) for x -> 0
    const double first = std::sqrt(6*std::sqrt(3.0)/5);
    const double second = std::sqrt(1 - x*x/6);
    const double third =
        std::pow(x/(x + 2*std::sqrt(6.0/5 - x*x/5)), 0.25);
    return first*second*third;
}


double RestitutionLaw::yieldVelocity
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


double RestitutionLaw::elasticPlastic(double yieldVelocity, double un)
{
    if (!(un > yieldVelocity))
    {
        return 1;
    }
    return std::min(1.0, thornton(yieldVelocity/un));
}


double RestitutionLaw::tabulated(const Tabulated& table, double un)
{
    const std::vector<double>& speeds = table.speeds;
    const std::vector<double>& values = table.values;
    if (un <= speeds.front()) return values.front();
    if (un >= speeds.back()) return values.back();
    const auto upper =
        std::upper_bound(speeds.begin(), speeds.end(), un) - speeds.begin();
    const double s0 = speeds[upper - 1], s1 = speeds[upper];
    const double w = (un - s0)/(s1 - s0);
    return (1 - w)*values[upper - 1] + w*values[upper];
}

} // End namespace brachDunn
