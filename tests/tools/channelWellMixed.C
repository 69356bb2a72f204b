// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The well-mixed check of nearWallDispersion's own equations, without
// OpenFOAM: tracers (or particles of relaxation time tau+) started uniform
// in a half channel of 180 wall units (tests/unit/channelSlab.H's flow),
// reflected at the wall and at the centre plane, moved along their paths
// (SeenPath.H) in steps dt+; after the given steps, the concentration
// relative to the mean in the bins of case.nearWallDispersion (y+ 0-1,
// 1-3, 3-10, 10-30, 30-60, 60-100, 100-180) with its binomial SE.
//
//     channelWellMixed n dtPlus steps [tauPlus]
//
// A documented run (doc/guide/turbulent-dispersion.md), not a test.

#include "SeenPath.H"
#include "channelSlab.H"

#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace brachDunn;

int main(int argc, char** argv)
{
    if (argc < 4)
    {
        std::fprintf(stderr, "usage: channelWellMixed n dtPlus steps"
                     " [tauPlus]\n");
        return 1;
    }
    const int n = std::atoi(argv[1]);
    const double dt = std::atof(argv[2]);
    const int steps = std::atoi(argv[3]);
    const double tauP = argc > 4 ? std::atof(argv[4]) : 0;
    if (n < 1 || !(dt > 0) || steps < 0 || !(tauP >= 0))
    {
        std::fprintf(stderr, "channelWellMixed: n >= 1, dtPlus > 0, steps"
                     " >= 0 and tauPlus >= 0, not %s %s %s %g\n", argv[1],
                     argv[2], argv[3], tauP);
        return 1;
    }
    PathSettings path;
    path.lower = 0;
    path.upper = testCases::halfHeight;
    path.reflect = true;
    const NearWallSettings nearWall;
    const std::vector<double> edges{0, 1, 3, 10, 30, 60, 100, 180};
    std::vector<double> velocity(n, 0.0);
    const auto move = [&](double& y, Vector3& w, int step, int tracer)
    {
        CounterRandom random(5, std::uint64_t(tracer), std::uint64_t(step), 0);
        const PathStep r = seenVelocityPath
        (
            {w, velocity[tracer], tauP}, testCases::channelFlow(y),
            nearWall, path, dt, random
        );
        y = r.y;
        w = r.w;
        velocity[tracer] = r.normalVelocity;
    };
    const auto bins = testCases::slabConcentration
    (
        0, testCases::halfHeight, edges, n, steps, move
    );
    for (std::size_t b = 0; b < bins.size(); ++b)
    {
        std::printf
        (
            "y+ %g-%g: %.3f +- %.3f\n",
            edges[b], edges[b + 1], bins[b].first, bins[b].second
        );
    }
    return 0;
}
