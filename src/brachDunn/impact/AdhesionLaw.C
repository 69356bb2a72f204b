// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "AdhesionLaw.H"

#include <algorithm>

namespace brachDunn
{
namespace adhesion
{

Constant Constant::make(double gamma)
{
    requireInRange("gamma", gamma, 0, maxGamma);
    return {gamma};
}


std::vector<double> Constant::initialGuess
(
    const std::vector<double>&,
    const std::vector<double>& gammas
)
{
    double sum = 0;
    for (const double gamma : gammas) sum += gamma;
    return {std::clamp(sum/gammas.size(), 0.0, maxGamma)};
}


PowerLaw PowerLaw::make(double c, double n)
{
    requireInRange("c", c, 0, maxGamma);
    requireInRange("n", n, 0, maxExponent);
    return {c, n};
}


std::vector<double> PowerLaw::initialGuess
(
    const std::vector<double>& speeds,
    const std::vector<double>& gammas
)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int count = 0;
    for (std::size_t i = 0; i < gammas.size(); ++i)
    {
        if (!(gammas[i] > 0)) continue;
        const double x = std::log(speeds[i]), y = std::log(gammas[i]);
        sx += x; sy += y; sxx += x*x; sxy += x*y; ++count;
    }
    const double slope =
        count > 1 && count*sxx - sx*sx > 0
      ? (count*sxy - sx*sy)/(count*sxx - sx*sx) : 0.5;
    const double intercept = count ? (sy - slope*sx)/count : -1;
    return
    {
        std::clamp(std::exp(intercept), 1e-300, maxGamma),
        std::clamp(slope, 0.0, maxExponent)
    };
}


VanDerWaals VanDerWaals::make(double h, double z, double f)
{
    requireAboveAtMost("h", h, 0, maxH);
    requireInRange("z", z, minZ, maxZ);
    requireInRange("f", f, 0, 1);
    return {h, z, f};
}


VanDerWaals VanDerWaals::read(const Parameters& parameters)
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
    if (A) requireAboveAtMost("A", *A, 0, maxHamaker);
    return make
    (
        h ? *h : 4*pi*(*A)/3,
        parameters.getOrDefault("z", 4e-10),
        parameters.get("f")
    );
}

} // End namespace adhesion
} // End namespace brachDunn
