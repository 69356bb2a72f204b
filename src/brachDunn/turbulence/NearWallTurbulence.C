// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "NearWallTurbulence.H"
#include "InputError.H"

#include <algorithm>
#include <cmath>

namespace brachDunn
{

namespace
{

//- a y+^p and its slope
struct Power
{
    double value, slope;
};

Power power(double a, double yPlus, double p)
{
    if (yPlus <= 0)
    {
        return {0, p == 1 ? a : 0};
    }
    const double v = a*std::pow(yPlus, p);
    return {v, p*v/yPlus};
}

//- The fits' upper end: Kallio & Reeks' time is held above it
constexpr double fitsTo = 100;

//- The integral times of the fluid seen along crossing trajectories
//  (Csanady 1963; NearWallTurbulence.H): per component of the wall's
//  frame, TL/sqrt(1 + (4 - 3 cos^2) b^2 xi^2), xi = |slip|/(mean rms),
//  the mean rms taken as at least uStar
Vector3 crossingTimes
(
    const Vector3& sigma,
    const double TL,
    const Vector3& slip,
    const double b,
    const double uStar
)
{
    const double mean = std::max(std::sqrt(dot(sigma, sigma)/3), uStar);
    const double u = mag(slip);
    const double xi2 = mean > 0 ? u*u/(mean*mean) : 0;
    const auto seen = [&](double along)
    {
        const double cos2 = u > 0 ? along*along/(u*u) : 1;
        return TL/std::sqrt(1 + (4 - 3*cos2)*b*b*xi2);
    };
    return {seen(slip.x), seen(slip.y), seen(slip.z)};
}

} // End anonymous namespace


Vector3 wallRmsPlus(const double y)
{
    return
    {
        0.40*y/(1 + 0.0239*std::pow(y, 1.496)),
        0.0116*y*y/(1 + 0.203*y + 0.0014*std::pow(y, 2.421)),
        0.19*y/(1 + 0.0361*std::pow(y, 1.322))
    };
}


Vector3 wallRmsPlusSlope(const double y)
{
    // (f/g)' = (f' g - f g')/g^2 for each fit
    const auto ratio = [](Power f, Power g)
    {
        return (f.slope*g.value - f.value*g.slope)/(g.value*g.value);
    };
    const auto one = [](Power p) { return Power{1 + p.value, p.slope}; };
    const Power gu = one(power(0.0239, y, 1.496));
    const Power pv = power(0.0014, y, 2.421);
    const Power gv{1 + 0.203*y + pv.value, 0.203 + pv.slope};
    const Power gw = one(power(0.0361, y, 1.322));
    return
    {
        ratio({0.40*y, 0.40}, gu),
        ratio({0.0116*y*y, 2*0.0116*y}, gv),
        ratio({0.19*y, 0.19}, gw)
    };
}


double wallTimePlus(const double y)
{
    if (y <= 5)
    {
        return 10;
    }
    const double yc = std::min(y, fitsTo);
    return 7.122 + 0.5731*yc - 0.00129*yc*yc;
}


void NearWallSettings::check() const
{
    // (a blend narrower than a wall unit would be a jump in the rms,
    // whose drift the walk cannot carry)
    requireInRange("blendFrom", blendFrom, 1, fitsTo - 1);
    requireInRange("blendTo", blendTo, blendFrom + 1, fitsTo);
    requireInRange("C0", C0, 0.1, 20);
    requireInRange("crossing", crossing, 0, 10);
}


SeenStatistics seenStatistics
(
    const FlowAtParticle& flow,
    const NearWallSettings& settings
)
{
    requireNonNegative("yPlus", flow.yPlus);
    requirePositive("uStar", flow.uStar);
    requirePositive("nu", flow.nu);

    // The blend's weight b (0: the fits, 1: RANS) and its slope db/dy+
    const double y = flow.yPlus;
    double b = 1, bSlope = 0;
    if (y <= settings.blendFrom)
    {
        b = 0;
    }
    else if (y < settings.blendTo)
    {
        const double width = settings.blendTo - settings.blendFrom;
        const double t = (y - settings.blendFrom)/width;
        b = t*t*(3 - 2*t);
        bSlope = 6*t*(1 - t)/width;
    }

    const double perY = flow.uStar/flow.nu;        // dy+/dy [1/m]
    const double timeUnit = flow.nu/(flow.uStar*flow.uStar);
    Vector3 fit{0, 0, 0}, fitSlope{0, 0, 0};
    double fitTime = 0;
    if (b < 1)
    {
        fit = flow.uStar*wallRmsPlus(y);
        fitSlope = (flow.uStar*perY)*wallRmsPlusSlope(y);
        fitTime = timeUnit*wallTimePlus(y);
    }
    double rans = 0, ransTime = 0;
    Vector3 ransGrad{0, 0, 0};
    if (b > 0)
    {
        requirePositive("k", flow.k);
        requirePositive("epsilon", flow.epsilon);
        rans = std::sqrt(2*flow.k/3);
        ransGrad = (1/(3*rans))*flow.gradK;
        ransTime = flow.k/flow.epsilon/(0.5 + 0.75*settings.C0);
    }

    SeenStatistics stats;
    const double dbdn = bSlope*perY;
    stats.sigma = (1 - b)*fit + b*Vector3{rans, rans, rans};
    stats.drift =
    {
        b*ransGrad.x,
        (1 - b)*fitSlope.y + b*ransGrad.y + (rans - fit.y)*dbdn,
        b*ransGrad.z
    };
    stats.TL = (1 - b)*fitTime + b*ransTime;

    stats.T = crossingTimes
    (
        stats.sigma, stats.TL, flow.slip, settings.crossing, flow.uStar
    );
    return stats;
}

} // End namespace brachDunn

// ************************************************************************* //
