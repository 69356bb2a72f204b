// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "Plausibility.H"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace brachDunn
{

namespace
{

//- The value in SI units had it been typed in the slip's unit (the
//  decimal text with the exponent added, read back: the number meant,
//  correctly rounded, 4.9 um is 4.9e-06 m; strtod: a result beyond the
//  doubles is no error here), plus the unit's offset
double inSI(const double value, const Magnitude::Slip& slip)
{
    if (slip.offset != 0)
    {
        // The sum to twelve digits: 21.7 degC is 294.85 K, not the
        // binary sum's 294.84999999999997
        char sum[32];
        std::snprintf(sum, sizeof(sum), "%.12g", value + slip.offset);
        return std::strtod(sum, nullptr);
    }
    const std::string text = toText(value);
    const auto e = text.find('e');
    const int exponent =
        slip.exponent
      + (e == std::string::npos ? 0 : std::stoi(text.substr(e + 1)));
    return std::strtod
    (
        (text.substr(0, e) + "e" + std::to_string(exponent)).c_str(),
        nullptr
    );
}


} // End anonymous namespace


//- "did you mean 3.2e+11 (320 GPa)?" for the first units (in the slips'
//  order, the likelier first; as many as the magnitude's suggestions) in
//  which the value lands in the model's range, else the first in which it
//  lands in the physical range, else nothing. A likelier unit in which it
//  lands in the physical range only is named first: a diameter of 150 is
//  150 um (beyond the model's range) as likely as 150 nm
std::string meant(const Magnitude& m, const double value)
{
    std::vector<const Magnitude::Slip*> named;
    const Magnitude::Slip* physical = nullptr;
    for (const Magnitude::Slip& slip : m.slips)
    {
        if (slip.exponent == 0 && slip.offset == 0)
        {
            continue;
        }
        const double si = inSI(value, slip);
        if
        (
            si >= m.validFrom && si <= m.validTo
         && int(named.size()) < m.suggestions
        )
        {
            named.push_back(&slip);
        }
        if (!physical && si >= m.mistakeBelow && si <= m.mistakeAbove)
        {
            physical = &slip;
        }
    }
    // Of those in the model's range the nearest to the typical value first
    // (101.325 is kPa before bar)
    if (m.typical > 0)
    {
        std::stable_sort
        (
            named.begin(), named.end(),
            [&](const Magnitude::Slip* a, const Magnitude::Slip* b)
            {
                return
                    std::abs(std::log(inSI(value, *a)/m.typical))
                  < std::abs(std::log(inSI(value, *b)/m.typical));
            }
        );
    }
    const Magnitude::Slip* likeliest =
        named.empty()
      ? nullptr : *std::min_element(named.begin(), named.end());
    if (physical && (!likeliest || physical < likeliest))
    {
        named.insert(named.begin(), physical);
    }
    std::string text;
    for (std::size_t i = 0; i < named.size(); ++i)
    {
        text +=
            std::string(i == 0 ? "; did you mean " : " or ")
          + toText(inSI(value, *named[i])) + " (" + toText(value) + " "
          + named[i]->unit + ")";
    }
    return text.empty() ? text : text + "?";
}


std::string unitMistake
(
    const Magnitude& m,
    const std::string& keyword,
    const double value
)
{
    const bool below = value < m.mistakeBelow;
    // (a quantity with no unit mistake below, a surface energy, leaves a
    // negative value to its own sign check)
    if ((!below && !(value > m.mistakeAbove)) || (below && !*m.softer))
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
