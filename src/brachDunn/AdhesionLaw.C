#include "AdhesionLaw.H"
#include "Selection.H"

#include <sstream>

namespace brachDunn
{

namespace
{

AdhesionLaw vanDerWaalsFrom(const Parameters& parameters)
{
    const auto h = parameters.find("h");
    const auto A = parameters.find("A");
    if (h && A)
    {
        throw InputError
        (
            "A", toText(*A), "give either h or A (h = 4 pi A/3), not both"
        );
    }
    if (!h && !A)
    {
        throw InputError
        (
            "h",
            "missing",
            "vanDerWaals needs the Lifshitz - van der Waals constant h [J]"
            " or the Hamaker constant A [J]"
        );
    }
    if (A) requirePositive("A", *A);
    return AdhesionLaw::vanDerWaals
    (
        h ? *h : 4*pi*(*A)/3,
        parameters.getOrDefault("z", 4e-10),
        parameters.get("f")
    );
}

//- The laws by type name, in the order of AdhesionLaw::Kind
const Selector<AdhesionLaw> selectors[] =
{
    {"none", [](const Parameters&) { return AdhesionLaw::none(); }},
    {"constant", [](const Parameters& p)
        { return AdhesionLaw::constant(p.get("gamma")); }},
    {"powerLaw", [](const Parameters& p)
        { return AdhesionLaw::powerLaw(p.get("c"), p.get("n")); }},
    {"vanDerWaals", vanDerWaalsFrom},
};

} // End anonymous namespace


AdhesionLaw AdhesionLaw::none()
{
    return AdhesionLaw(Kind::none);
}


AdhesionLaw AdhesionLaw::constant(double gamma)
{
    requireNonNegative("gamma", gamma);
    AdhesionLaw law(Kind::constant);
    law.a_ = gamma;
    return law;
}


AdhesionLaw AdhesionLaw::powerLaw(double c, double n)
{
    requireNonNegative("c", c);
    requireNonNegative("n", n);
    AdhesionLaw law(Kind::powerLaw);
    law.a_ = c;
    law.b_ = n;
    return law;
}


AdhesionLaw AdhesionLaw::vanDerWaals(double h, double z, double f)
{
    requirePositive("h", h);
    requirePositive("z", z);
    requireInRange("f", f, 0, 1);
    AdhesionLaw law(Kind::vanDerWaals);
    law.a_ = h;
    law.b_ = z;
    law.fraction_ = f;
    return law;
}


AdhesionLaw AdhesionLaw::select
(
    const std::string& type,
    const Parameters& parameters
)
{
    return selectByName(selectors, "adhesion law", type, parameters);
}


const std::vector<std::string>& AdhesionLaw::typeNames()
{
    static const std::vector<std::string> names = selectorNames(selectors);
    return names;
}


const std::string& AdhesionLaw::typeName() const
{
    return typeNames()[static_cast<int>(kind_)];
}


std::string AdhesionLaw::describe() const
{
    std::ostringstream os;
    os.precision(6);
    os << "type " << typeName() << ";";
    switch (kind_)
    {
        case Kind::none: break;
        case Kind::constant: os << " gamma " << a_ << ";"; break;
        case Kind::powerLaw: os << " c " << a_ << "; n " << b_ << ";"; break;
        case Kind::vanDerWaals:
            os << " h " << a_ << "; z " << b_ << "; f " << fraction_ << ";";
            break;
    }
    return os.str();
}

} // End namespace brachDunn
