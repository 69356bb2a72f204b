// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
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
    if (A) requireAboveAtMost("A", *A, 0, AdhesionLaw::maxHamaker);
    return AdhesionLaw::vanDerWaals
    (
        h ? *h : 4*pi*(*A)/3,
        parameters.getOrDefault("z", 4e-10),
        parameters.get("f")
    );
}

//- The laws by type name, in the order of AdhesionLaw::Law
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
    return AdhesionLaw(None{});
}


AdhesionLaw AdhesionLaw::constant(double gamma)
{
    requireInRange("gamma", gamma, 0, maxGamma);
    return AdhesionLaw(Constant{gamma});
}


AdhesionLaw AdhesionLaw::powerLaw(double c, double n)
{
    requireInRange("c", c, 0, maxGamma);
    requireInRange("n", n, 0, maxExponent);
    return AdhesionLaw(PowerLaw{c, n});
}


AdhesionLaw AdhesionLaw::vanDerWaals(double h, double z, double f)
{
    requireAboveAtMost("h", h, 0, maxH);
    requireInRange("z", z, minZ, maxZ);
    requireInRange("f", f, 0, 1);
    return AdhesionLaw(VanDerWaals{h, z, f});
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
    return typeNames()[law_.index()];
}


std::string AdhesionLaw::describe() const
{
    std::ostringstream os;
    os.precision(6);
    os << "type " << typeName() << ";";
    if (const auto* law = as<Constant>())
    {
        os << " gamma " << law->gamma << ";";
    }
    else if (const auto* law = as<PowerLaw>())
    {
        os << " c " << law->c << "; n " << law->n << ";";
    }
    else if (const auto* law = as<VanDerWaals>())
    {
        os << " h " << law->h << "; z " << law->z << "; f " << law->f << ";";
    }
    return os.str();
}

} // End namespace brachDunn
