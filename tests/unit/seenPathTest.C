// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The walk of the fluid velocity seen along the particle's wall-normal path
// (SeenPath.H):
// - well mixed at long steps: tracers started uniform in slabs of a channel
//   (y+ 0-10 and 10-100, reflected at their ends) stay uniform within
//   max(5 %, 3 SE) in every wall-distance bin at dt/T_L of 1 near the wall
//   (dt+ 10, T_L+ 10) and dt+ 30 beyond; one held step per time step (the
//   walk without sub-steps) does not: the test's power;
// - the mean fluctuation moves a tracer exactly as the sub-steps did (an
//   identity of the design), also when the path reaches the wall and the
//   fluctuation is held from there;
// - a particle of long relaxation time keeps its wall-normal velocity;
// - the noise keeps its direction in the global axes when the wall's frame
//   turns: a walk taken in a frame turned half round the streamwise axis
//   (the frame past a channel's centre plane) from the same global w is
//   the same walk (the noise drawn in the frame's own axes turned with it,
//   and the tracers that crossed the plane were sent back: 1.04 of the
//   mean at the centre of case.nearWallDispersion's channel);
// - where the time scales are tiny (a still region's RANS k) a step takes
//   at most maxSubSteps sub-steps and says so;
// - a step of zero length changes nothing; bad settings name themselves.

#include "SeenPath.H"
#include "channelSlab.H"
#include "inputErrorAssertions.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace brachDunn;
using brachDunn::testCases::channelFlow;
using brachDunn::testCases::throwsInputError;

namespace
{

//- Tracers of the slab lo-hi moved by steps dt along their paths,
//  reflected at the slab's ends
std::vector<std::pair<double, double>> pathConcentration
(
    const double lo,
    const double hi,
    const std::vector<double>& edges,
    const int n,
    const double time,
    const double dt,
    const PathSettings& settings
)
{
    PathSettings path = settings;
    path.lower = lo;
    path.upper = hi;
    path.reflect = true;
    const NearWallSettings nearWall;
    double subSteps = 0;
    const auto move = [&](double& y, Vector3& w, int step, int tracer)
    {
        CounterRandom random(5, std::uint64_t(tracer), std::uint64_t(step), 0);
        const PathStep r = seenVelocityPath
        (
            {w, 0, 0}, channelFlow(y), nearWall, path, dt, random
        );
        y = r.y;
        w = r.w;
        subSteps += r.subSteps;
    };
    const int steps = int(time/dt + 0.5);
    const auto bins =
        testCases::slabConcentration(lo, hi, edges, n, steps, move);
    std::printf
    (
        "y+ %g-%g, dt+ %g: %.1f sub-steps a step\n",
        lo, hi, dt, subSteps/(double(n)*steps)
    );
    return bins;
}

} // End namespace


TEST(SeenPath, TracersStayWellMixedAtLongSteps)
{
    // Near the wall, dt+ 10 = T_L+: 20000 tracers over 150 time units (SE
    // 2.1 % in y+ 0-1); beyond, dt+ 30 (T_L+ 12 to 50): 20000 over 300
    const std::vector<double> inner{0, 1, 3, 10}, outer{10, 30, 60, 80, 100};
    const PathSettings defaults;
    EXPECT_TRUE
    (
        testCases::wellMixed
        (
            inner, pathConcentration(0, 10, inner, 20000, 150, 10, defaults)
        )
    );
    EXPECT_TRUE
    (
        testCases::wellMixed
        (
            outer, pathConcentration(10, 100, outer, 20000, 300, 30, defaults)
        )
    );

    // One sub-step a step: the statistics held over the whole step gather
    // tracers in the sublayer
    PathSettings held;
    held.timeFraction = 1;
    held.rmsChange = 1;
    held.maxSubSteps = 1;
    const auto heldBins =
        pathConcentration(0, 10, inner, 10000, 150, 10, held);
    EXPECT_FALSE(testCases::wellMixed(inner, heldBins));
    EXPECT_GT(testCases::worstBin(heldBins), 0.2);
}


TEST(SeenPath, MeanFluctuationMovesATracerAsTheSubStepsDid)
{
    const NearWallSettings nearWall;
    for (const double lower : {0.0, 2.5})
    {
        PathSettings path;
        path.lower = lower;
        for (int k = 0; k < 200; ++k)
        {
            CounterRandom random(9, std::uint64_t(k), 0, 0);
            const double y0 = 3 + 0.05*k;
            const PathStep r = seenVelocityPath
            (
                {{0.3, -1.5, 0.2}, 0, 0}, channelFlow(y0), nearWall, path,
                20, random
            );
            EXPECT_NEAR(r.y - y0, 20*r.meanFluctuation.y, 1e-12*(1 + y0));
            EXPECT_GE(r.subSteps, 1);
        }
    }
}


TEST(SeenPath, HeavyParticleKeepsItsWallNormalVelocity)
{
    // tau_p 1e9 time units: over dt 10 the particle moves by v dt, to
    // 1e-8 of it (its response to the fluid is 1e-8 of the step)
    const NearWallSettings nearWall;
    const PathSettings path;
    CounterRandom random(3, 1, 2, 0);
    const PathStep r = seenVelocityPath
    (
        {{0, 0.5, 0}, 0.2, 1e9}, channelFlow(20), nearWall, path, 10, random
    );
    EXPECT_NEAR(r.y, 20 + 0.2*10, 1e-8*2);
    EXPECT_NEAR(r.normalVelocity, 0.2, 1e-8);
}


TEST(SeenPath, NoiseKeepsItsDirectionWhenTheFrameTurns)
{
    // At the channel's centre (y+ 180) k is level: the statistics are the
    // same on both sides, so the two frames see the same walk
    const NearWallSettings nearWall;
    const PathSettings path;
    const WallFrame turned{{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    for (int k = 0; k < 20; ++k)
    {
        const Vector3 w{0.3, 0.8 - 0.1*k, -0.2};
        CounterRandom random(4, std::uint64_t(k), 0, 0);
        const PathStep a = seenVelocityPath
        (
            {w, 0, 0}, channelFlow(180), nearWall, path, 10, random
        );
        CounterRandom again(4, std::uint64_t(k), 0, 0);
        const PathStep b = seenVelocityPath
        (
            {turned.local(w), 0, 0, turned}, channelFlow(180), nearWall,
            path, 10, again
        );
        const Vector3 d = a.meanFluctuation - turned.global(b.meanFluctuation);
        EXPECT_LT(std::abs(d.x) + std::abs(d.y) + std::abs(d.z), 1e-12);
        EXPECT_NEAR(b.y - 180, 180 - a.y, 1e-9);
    }
}


TEST(SeenPath, ZeroStepChangesNothing)
{
    const NearWallSettings nearWall;
    const PathSettings path;
    CounterRandom random(3, 1, 2, 0);
    const PathStep r = seenVelocityPath
    (
        {{0.1, -0.4, 0.7}, 0.3, 2}, channelFlow(7), nearWall, path, 0, random
    );
    EXPECT_EQ(r.y, 7);
    EXPECT_EQ(r.w.y, -0.4);
    EXPECT_EQ(r.normalVelocity, 0.3);
    EXPECT_EQ(r.subSteps, 0);
}


TEST(SeenPath, AStillRegionTakesAtMostMaxSubSteps)
{
    // Above the blend where the RANS k is a millionth of the channel's
    // (epsilon kept): T_L about 3e-5 wall time units, so that a step of 10
    // would want some 10^7 sub-steps of 0.025 T; it takes maxSubSteps of
    // dt/maxSubSteps, says so, and its fluctuation stays of the (tiny) rms
    const NearWallSettings nearWall;
    FlowAtParticle still = channelFlow(150);
    still.k *= 1e-6;
    still.gradK = {0, 0, 0};
    PathSettings path;
    CounterRandom random(3, 1, 2, 0);
    const PathStep r = seenVelocityPath
    (
        {{0.5, -1, 0.2}, 0, 0}, still, nearWall, path, 10, random
    );
    EXPECT_LE(r.subSteps, path.maxSubSteps + 1);
    EXPECT_GE(r.subSteps, path.maxSubSteps - 1);
    EXPECT_TRUE(r.atLeastSubStep);
    const double rms = std::sqrt(2*still.k/3);
    EXPECT_LT(mag(r.meanFluctuation), 5*rms);

    // The channel's own flow at the same place wants fewer: not bound
    CounterRandom again(3, 1, 2, 0);
    const PathStep free = seenVelocityPath
    (
        {{0.5, -1, 0.2}, 0, 0}, channelFlow(150), nearWall, path, 10, again
    );
    EXPECT_FALSE(free.atLeastSubStep);
    EXPECT_LT(free.subSteps, path.maxSubSteps);
}


TEST(SeenPath, BadInputNamesItsKeyword)
{
    const NearWallSettings nearWall;
    const auto step = [&](PathSettings path, double dt, double tauP)
    {
        CounterRandom random(3, 1, 2, 0);
        seenVelocityPath
        (
            {{0, 0, 0}, 0, tauP}, channelFlow(7), nearWall, path, dt, random
        );
    };
    PathSettings path;
    EXPECT_TRUE(throwsInputError([&] { step(path, -1, 0); }, "dt", "-1"));
    EXPECT_TRUE(throwsInputError([&] { step(path, 1, -2); }, "tauP", "-2"));
    path.timeFraction = 0;
    EXPECT_TRUE
    (
        throwsInputError([&] { step(path, 1, 0); }, "timeFraction", "0")
    );
    path = PathSettings();
    path.rmsChange = 2;
    EXPECT_TRUE(throwsInputError([&] { step(path, 1, 0); }, "rmsChange", "2"));
    path = PathSettings();
    path.maxSubSteps = 0;
    EXPECT_TRUE
    (
        throwsInputError([&] { step(path, 1, 0); }, "maxSubSteps", "0")
    );
    path = PathSettings();
    path.lower = 5;
    path.upper = 5;
    EXPECT_TRUE(throwsInputError([&] { step(path, 1, 0); }, "upper", "5"));
}


// ************************************************************************* //
