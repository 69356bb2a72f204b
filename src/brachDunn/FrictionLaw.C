// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "FrictionLaw.H"
#include "Selection.H"

#include <sstream>

namespace brachDunn
{

namespace
{

//- The laws by type name, in the order of FrictionLaw::Law
const Selector<FrictionLaw> selectors[] =
{
    {"sticking", [](const Parameters&) { return FrictionLaw::sticking(); }},
    {"coulomb", [](const Parameters& p)
        { return FrictionLaw::coulomb(p.get("mu")); }},
};

} // End anonymous namespace


FrictionLaw FrictionLaw::select
(
    const std::string& type,
    const Parameters& parameters
)
{
    return selectByName(selectors, "friction law", type, parameters);
}


const std::vector<std::string>& FrictionLaw::typeNames()
{
    static const std::vector<std::string> names = selectorNames(selectors);
    return names;
}


const std::string& FrictionLaw::typeName() const
{
    return typeNames()[law_.index()];
}


std::string FrictionLaw::describe() const
{
    std::ostringstream os;
    os.precision(6);
    os << "type " << typeName() << ";";
    if (const auto* law = as<Coulomb>()) os << " mu " << law->mu << ";";
    return os.str();
}

} // End namespace brachDunn
