// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "Plausibility.H"

#include <cstdlib>
#include <string>

namespace brachDunn
{

namespace
{

//- "did you mean 3.2e+11 (320 GPa)?" for the first unit in which the value
//  lands in the model's range, else in the physical range, else nothing
std::string meant(const Magnitude& m, const double value)
{
    for (const bool strict : {true, false})
    {
        for (const Magnitude::Slip& slip : m.slips)
        {
            // The value's decimal text with the exponent added, read back:
            // the number meant, correctly rounded (4.9 um is 4.9e-06 m)
            const std::string text = toText(value);
            const auto e = text.find('e');
            const int exponent =
                slip.exponent
              + (e == std::string::npos ? 0 : std::stoi(text.substr(e + 1)));
            // (strtod: a result beyond the doubles is no error here)
            const double si = std::strtod
            (
                (text.substr(0, e) + "e" + std::to_string(exponent)).c_str(),
                nullptr
            );
            const bool inside =
                strict
              ? si >= m.validFrom && si <= m.validTo
              : si >= m.mistakeBelow && si <= m.mistakeAbove;
            if (slip.exponent != 0 && inside)
            {
                return "; did you mean " + toText(si) + " (" + toText(value)
                  + " " + slip.unit + ")?";
            }
        }
    }
    return "";
}

} // End anonymous namespace


std::string unitMistake
(
    const Magnitude& m,
    const std::string& keyword,
    const double value
)
{
    const bool below = value < m.mistakeBelow;
    if (!below && !(value > m.mistakeAbove))
    {
        return "";
    }
    return
        keyword + " = " + toText(value) + ": " + m.what + " in " + m.unit
      + "; " + toText(value) + " " + m.unit + " is "
      + (below ? m.softer : m.harder) + meant(m, value);
}


std::string outsideRange
(
    const Magnitude& m,
    const std::string& keyword,
    const double value
)
{
    if (value == 0 || (value >= m.validFrom && value <= m.validTo))
    {
        return "";
    }
    return
        keyword + " = " + toText(value) + " " + m.unit + ": " + m.what
      + " outside the range the model was made for, " + toText(m.validFrom)
      + " to " + toText(m.validTo) + " " + m.unit;
}


std::string checkMagnitude
(
    const Magnitude& m,
    const std::string& keyword,
    const double value,
    const bool extreme
)
{
    const std::string mistake = unitMistake(m, keyword, value);
    if (!mistake.empty())
    {
        if (!extreme)
        {
            const std::string prefix = keyword + " = " + toText(value) + ": ";
            throw InputError
            (
                keyword, toText(value), mistake.substr(prefix.size())
            );
        }
        return mistake + " (taken as given)";
    }
    return outsideRange(m, keyword, value);
}

} // End namespace brachDunn
