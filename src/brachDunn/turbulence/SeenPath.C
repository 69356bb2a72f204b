// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SeenPath.H"
#include "InputError.H"

#include <algorithm>
#include <cmath>

namespace brachDunn
{

void PathSettings::check() const
{
    requireAboveAtMost("timeFraction", timeFraction, 0, 1);
    requireAboveAtMost("rmsChange", rmsChange, 0, 1);
    requirePositive("maxSubSteps", maxSubSteps);
    requireNonNegative("lower", lower);
    if (!(upper > lower))
    {
        throw InputError("upper", toText(upper), "must be > lower");
    }
}


namespace
{

//- The flow at wall distance y [m] along the normal from the start, where
//  it is y0: the start's wall units and epsilon, k extrapolated by its
//  wall-normal gradient (kept above a thousandth of the start's)
FlowAtParticle flowAlong
(
    const FlowAtParticle& start,
    const double y0,
    const double y
)
{
    FlowAtParticle f = start;
    f.yPlus = y*start.uStar/start.nu;
    f.k = std::max(start.k + start.gradK.y*(y - y0), 1e-3*start.k);
    return f;
}


//- The particle's wall-normal velocity v and displacement over h, as it
//  relaxes with tauP towards the fluid's fluctuation u held over h (a
//  tracer, tauP 0, moves with it)
double move(double& v, const double u, const double tauP, const double h)
{
    if (!(tauP > 0))
    {
        v = u;
        return u*h;
    }
    const double decay = -std::expm1(-h/tauP);
    const double dy = u*h + (v - u)*tauP*decay;
    v = u + (v - u)*(1 - decay);
    return dy;
}


//- The sub-step from the statistics s: at most what is left of the step,
//  the fraction timeFraction of the shortest time met, and rmsChange over
//  the wall-normal rms's slope (the sub-step over which a fluctuation of
//  the rms itself changes the rms by rmsChange of it)
double subStep
(
    const SeenStatistics& s,
    const PathSettings& path,
    const double left
)
{
    const double shortest = std::min({s.T.x, s.T.y, s.T.z});
    double h = std::min(left, path.timeFraction*shortest);
    const double slope = std::abs(s.drift.y);
    if (slope > 0)
    {
        h = std::min(h, path.rmsChange/slope);
    }
    return h;
}

} // End anonymous namespace


PathStep seenVelocityPath
(
    const PathStart& start,
    const FlowAtParticle& flow,
    const NearWallSettings& settings,
    const PathSettings& path,
    const double dt,
    CounterRandom& random
)
{
    path.check();
    requireNonNegative("dt", dt);
    requireNonNegative("tauP", start.tauP);
    requirePositive("uStar", flow.uStar);
    requirePositive("nu", flow.nu);

    const double y0 = flow.yPlus*flow.nu/flow.uStar;
    PathStep r{start.w, {0, 0, 0}, y0, start.normalVelocity, 0, false};
    const double least = dt/path.maxSubSteps;
    SeenStatistics s = seenStatistics(flow, settings);
    Vector3 u{s.sigma.x*r.w.x, s.sigma.y*r.w.y, s.sigma.z*r.w.z};
    bool followed = y0 >= path.lower && y0 <= path.upper;
    double t = 0;
    while (t < dt)
    {
        double h = dt - t;
        if (followed)
        {
            s = seenStatistics(flowAlong(flow, y0, r.y), settings);
            const double wanted = subStep(s, path, h);
            r.atLeastSubStep =
                r.atLeastSubStep || (wanted < least && least < h);
            h = std::min(h, std::max(wanted, least));
            const Vector3 xi = start.axes.local
            (
                {random.normal(), random.normal(), random.normal()}
            );
            r.w = seenVelocityStep(r.w, s, start.tauP, h, xi);
            u = {s.sigma.x*r.w.x, s.sigma.y*r.w.y, s.sigma.z*r.w.z};
            // The wall-normal fluctuation at the middle of the sub-step's
            // displacement, where the rms has changed by its slope
            double v = r.normalVelocity;
            u.y += 0.5*s.drift.y*r.w.y*move(v, u.y, start.tauP, h);
            ++r.subSteps;
        }
        r.meanFluctuation = r.meanFluctuation + h*u;
        r.y += move(r.normalVelocity, u.y, start.tauP, h);
        t += h;
        if (path.reflect)
        {
            while (r.y < path.lower || r.y > path.upper)
            {
                r.y = 2*(r.y < path.lower ? path.lower : path.upper) - r.y;
                r.w.y = -r.w.y;
                u.y = -u.y;
                r.normalVelocity = -r.normalVelocity;
            }
        }
        else
        {
            followed = followed && r.y >= path.lower && r.y <= path.upper;
        }
    }
    if (dt > 0)
    {
        r.meanFluctuation = (1/dt)*r.meanFluctuation;
    }
    return r;
}

} // End namespace brachDunn

// ************************************************************************* //
