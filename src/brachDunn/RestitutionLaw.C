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

//- The laws by type name, in the order of RestitutionLaw::Kind
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
    RestitutionLaw law(Kind::constant);
    law.a_ = R;
    return law;
}


RestitutionLaw RestitutionLaw::powerLaw(double k, double p)
{
    requirePositive("k", k);
    requireNonNegative("p", p);
    RestitutionLaw law(Kind::powerLaw);
    law.a_ = k;
    law.b_ = p;
    return law;
}


RestitutionLaw RestitutionLaw::viscousDamping(double zeta)
{
    requireFinite("zeta", zeta);
    if (!(zeta >= 0 && zeta < 1))
    {
        throw InputError("zeta", toText(zeta), "must be in [0, 1)");
    }
    RestitutionLaw law(Kind::viscousDamping);
    law.a_ = std::exp(-pi*zeta/std::sqrt(1 - zeta*zeta));
    law.b_ = zeta;
    return law;
}


RestitutionLaw RestitutionLaw::elasticPlasticYieldVelocity(double vy)
{
    requirePositive("yieldVelocity", vy);
    RestitutionLaw law(Kind::elasticPlastic);
    law.yieldVelocity_ = vy;
    return law;
}


RestitutionLaw RestitutionLaw::elasticPlasticYieldStress(double py)
{
    requirePositive("yieldStress", py);
    RestitutionLaw law(Kind::elasticPlastic);
    law.yieldStress_ = py;
    return law;
}


RestitutionLaw RestitutionLaw::table(const Table& speedAndR)
{
    if (speedAndR.empty())
    {
        throw InputError("values", "()", "needs at least one (speed R) pair");
    }
    RestitutionLaw law(Kind::table);
    for (const auto& [speed, R] : speedAndR)
    {
        requireNonNegative("values (speed)", speed);
        requireInRange("values (R)", R, 0, 1);
        if (!law.speeds_.empty() && !(speed > law.speeds_.back()))
        {
            throw InputError
            (
                "values (speed)",
                toText(speed),
                "speeds must increase strictly down the table"
            );
        }
        law.speeds_.push_back(speed);
        law.values_.push_back(R);
    }
    return law;
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
    return typeNames()[static_cast<int>(kind_)];
}


std::string RestitutionLaw::describe() const
{
    std::ostringstream os;
    os.precision(6);
    os << "type " << typeName() << ";";
    switch (kind_)
    {
        case Kind::constant: os << " R " << a_ << ";"; break;
        case Kind::powerLaw: os << " k " << a_ << "; p " << b_ << ";"; break;
        case Kind::viscousDamping: os << " zeta " << b_ << ";"; break;
        case Kind::elasticPlastic:
            if (yieldVelocity_ > 0)
            {
                os << " yieldVelocity " << yieldVelocity_ << ";";
            }
            else
            {
                os << " yieldStress " << yieldStress_ << ";";
            }
            break;
        case Kind::table:
            os << " values (";
            for (std::size_t i = 0; i < speeds_.size(); ++i)
            {
                os << (i ? " " : "") << "(" << speeds_[i] << " "
                   << values_[i] << ")";
            }
            os << ");";
            break;
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


double RestitutionLaw::evaluateSlow
(
    double un,
    double rho,
    double contactModulus
) const
{
    if (kind_ == Kind::elasticPlastic)
    {
        double vy = yieldVelocity_;
        if (vy <= 0)
        {
            const double E4 = std::pow(contactModulus, 4);
            vy = std::sqrt(pi*pi*pi*pi/40)
                *std::sqrt(std::pow(yieldStress_, 5)/(E4*rho));
        }
        if (!(un > vy))
        {
            return 1;
        }
        return std::min(1.0, thornton(vy/un));
    }

    // table
    if (un <= speeds_.front()) return values_.front();
    if (un >= speeds_.back()) return values_.back();
    const auto upper =
        std::upper_bound(speeds_.begin(), speeds_.end(), un) - speeds_.begin();
    const double s0 = speeds_[upper - 1], s1 = speeds_[upper];
    const double w = (un - s0)/(s1 - s0);
    return (1 - w)*values_[upper - 1] + w*values_[upper];
}

} // End namespace brachDunn
