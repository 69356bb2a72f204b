// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The near-wall statistics of the fluid velocity seen (NearWallTurbulence)
// and the random walk they drive (SeenVelocity):
// - the fits' limits at the wall (u', w' ~ y, v' ~ y^2: their leading
//   coefficients) and the wall-normal rms against the DNS of Moser, Kim &
//   Mansour (1999) at Re_tau 395 within 10 % at y+ 1, 5, 10, 30, 100
//   (R_vv of their channel, as tabulated in openearth/tudflow3d's
//   turbulence_models.f, subroutine Chol_tensor_from_DNS_Ret395; rms read
//   off by linear interpolation);
// - the slopes against central differences of the fits;
// - the blend continuous in the rms, the drift and the time at both of its
//   ends; the RANS time at y+ = 100 from the DNS's k+ and epsilon+
//   (Re_tau 180: 1.42 and 0.0136, brent10holladay/DNSValidation,
//   chan180.reystress and chan180.kbal) within 5 % of Kallio & Reeks';
// - crossing trajectories: the time along and across a slip;
// - well mixed: tracers started uniform in slabs of a channel (y+ 0-10 and
//   10-100, reflected at their ends) stay uniform in every wall-distance
//   bin from y+ 0-1 to 80-100; with the drift taken off they do not (the
//   test's power, checked here too).

#include "NearWallTurbulence.H"
#include "inputErrorAssertions.H"
#include "channelSlab.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace brachDunn;
using brachDunn::testCases::channelFlow;
using brachDunn::testCases::throwsInputError;


TEST(NearWallTurbulence, FitsHaveTheWallsLimits)
{
    const double y = 1e-6;
    const Vector3 r = wallRmsPlus(y);
    EXPECT_NEAR(r.x/y, 0.40, 1e-6);
    EXPECT_NEAR(r.y/(y*y), 0.0116, 1e-8);
    EXPECT_NEAR(r.z/y, 0.19, 1e-6);
}


TEST(NearWallTurbulence, WallNormalRmsIsTheDNSs)
{
    // v'+ of Moser, Kim & Mansour (1999), Re_tau 392.24: sqrt of R_vv
    // interpolated linearly in y/h at y+/392.24 (the fits are 10-32 %
    // above their Re_tau 178 values: doc/turbulentDispersion.md)
    const double yPlus[] = {1, 5, 10, 30, 100};
    const double dns[] = {0.01003, 0.1448, 0.3492, 0.8357, 0.9738};
    for (int i = 0; i < 5; ++i)
    {
        EXPECT_NEAR(wallRmsPlus(yPlus[i]).y/dns[i], 1, 0.10) << yPlus[i];
    }
}


TEST(NearWallTurbulence, SlopesAreTheFitsDerivatives)
{
    for (const double y : {0.3, 1.0, 4.0, 12.0, 35.0, 80.0, 99.0})
    {
        const double h = 1e-5*y;
        const Vector3 fd =
            (0.5/h)*(wallRmsPlus(y + h) - wallRmsPlus(y - h));
        const Vector3 slope = wallRmsPlusSlope(y);
        EXPECT_NEAR(slope.x, fd.x, 1e-7*(1 + std::abs(fd.x))) << y;
        EXPECT_NEAR(slope.y, fd.y, 1e-7*(1 + std::abs(fd.y))) << y;
        EXPECT_NEAR(slope.z, fd.z, 1e-7*(1 + std::abs(fd.z))) << y;
    }
}


TEST(NearWallTurbulence, BlendIsContinuousAtBothEnds)
{
    const NearWallSettings settings;
    for (const double y : {settings.blendFrom, settings.blendTo})
    {
        const SeenStatistics below = seenStatistics(channelFlow(y - 1e-7), settings);
        const SeenStatistics above = seenStatistics(channelFlow(y + 1e-7), settings);
        EXPECT_NEAR(mag(below.sigma - above.sigma), 0, 1e-6) << y;
        EXPECT_NEAR(mag(below.drift - above.drift), 0, 1e-6) << y;
        EXPECT_NEAR(below.TL, above.TL, 1e-5*below.TL) << y;
    }
    // Inside the blend the drift is the derivative of the blended rms
    const double y = 90, h = 1e-4;
    const double fd =
        (seenStatistics(channelFlow(y + h), settings).sigma.y
       - seenStatistics(channelFlow(y - h), settings).sigma.y)/(2*h);
    EXPECT_NEAR(seenStatistics(channelFlow(y), settings).drift.y, fd, 1e-7);
}


TEST(NearWallTurbulence, RANSTimeMeetsKallioAndReeksAtTheFitsEnd)
{
    // DNS at y+ = 100 (Re_tau 180): k+ 1.42, epsilon+ 0.0136
    NearWallSettings settings;
    const SeenStatistics rans = seenStatistics
    (
        {100, 1, 1, 1.42, 0.0136, {0, 0, 0}, {0, 0, 0}}, settings
    );
    EXPECT_NEAR(rans.TL/wallTimePlus(100), 1, 0.05);
    EXPECT_NEAR(wallTimePlus(100), 7.122 + 57.31 - 12.9, 1e-12);
    EXPECT_DOUBLE_EQ(wallTimePlus(3), 10);
}


TEST(NearWallTurbulence, CrossingTrajectoriesShortenTheTimeSeen)
{
    // A slip of 2 sigma along s: T_s = T_L/sqrt(1 + 0.64*4),
    // T_n = T_z = T_L/sqrt(1 + 4*0.64*4); along a diagonal of s and n,
    // cos^2 = 1/2: T = T_L/sqrt(1 + 2.5*0.64*4)
    const NearWallSettings settings;
    FlowAtParticle flow{150, 1, 1, 1.5, 0.01, {0, 0, 0}, {0, 0, 0}};
    const double sigma = std::sqrt(2*1.5/3);
    flow.slip = {2*sigma, 0, 0};
    const SeenStatistics s = seenStatistics(flow, settings);
    EXPECT_NEAR(s.T.x, s.TL/std::sqrt(1 + 0.64*4), 1e-14);
    EXPECT_NEAR(s.T.y, s.TL/std::sqrt(1 + 4*0.64*4), 1e-14);
    EXPECT_NEAR(s.T.z, s.T.y, 1e-14);
    flow.slip = {std::sqrt(2.0)*sigma, std::sqrt(2.0)*sigma, 0};
    const SeenStatistics d = seenStatistics(flow, settings);
    EXPECT_NEAR(d.T.x, d.TL/std::sqrt(1 + 2.5*0.64*4), 1e-14);
    flow.slip = {0, 0, 0};
    const SeenStatistics t = seenStatistics(flow, settings);
    EXPECT_EQ(t.T.x, t.TL);
}


TEST(NearWallTurbulence, CrossingTimesKeepTheWallsVelocityScale)
{
    // At y+ 0.01 the mean rms is about 0.003 u*: a slip of 0.02 u* would
    // shorten the times some tenfold with it; with u* as the rms's floor,
    // xi = 0.02 and T_n = T_L/sqrt(1 + 4 0.64 0.0004) (0.05 % shorter).
    // Nearer still (y+ 1e-170: the rms's square underflows) the times
    // stay those of the floor, finite and positive
    const NearWallSettings settings;
    for (const double yPlus : {0.01, 1e-170})
    {
        FlowAtParticle flow{yPlus, 1, 1, 1e-6, 1e-6, {0, 0, 0}, {0.02, 0, 0}};
        const SeenStatistics s = seenStatistics(flow, settings);
        EXPECT_NEAR(s.T.y, s.TL/std::sqrt(1 + 4*0.64*0.0004), 1e-12*s.TL);
        EXPECT_NEAR(s.T.x, s.TL/std::sqrt(1 + 0.64*0.0004), 1e-12*s.TL);
    }
}


TEST(NearWallTurbulence, BadInputNamesItsKeyword)
{
    const NearWallSettings settings;
    EXPECT_TRUE(throwsInputError
    (
        [&] { seenStatistics({-1, 1, 1, 1, 1, {}, {}}, settings); }, "yPlus", "-1"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [&] { seenStatistics({150, 1, 1, 0, 1, {}, {}}, settings); }, "k", "0"
    ));
    NearWallSettings bad;
    bad.blendTo = 60;
    EXPECT_TRUE(throwsInputError([&] { bad.check(); }, "blendTo", "60"));
}


namespace
{

//- Tracers of a slab moved by the wall-normal walk alone (it alone moves
//  them across the flow), with the statistics held over each step dt and w
//  held for the displacement; driftFactor 0 takes the drift off
std::vector<std::pair<double, double>> heldStepConcentration
(
    double lo,
    double hi,
    const std::vector<double>& edges,
    int n,
    double time,
    double dt,
    double driftFactor
)
{
    const NearWallSettings settings;
    std::mt19937_64 gen(7);
    std::normal_distribution<double> normal;
    const auto move = [&](double& y, Vector3& w, int, int)
    {
        SeenStatistics s = seenStatistics(channelFlow(y), settings);
        s.drift = driftFactor*s.drift;
        w.y = seenVelocityStep({0, w.y, 0}, s, 0, dt, {0, normal(gen), 0}).y;
        y += s.sigma.y*w.y*dt;
        if (y < lo)
        {
            y = 2*lo - y;
            w.y = -w.y;
        }
        else if (y > hi)
        {
            y = 2*hi - y;
            w.y = -w.y;
        }
    };
    return testCases::slabConcentration
    (
        lo, hi, edges, n, int(time/dt + 0.5), move
    );
}

} // End namespace


TEST(NearWallTurbulence, TracersStayWellMixedInAChannel)
{
    // The sublayer and buffer (y+ 0-10: 30000 tracers, 150 time units at
    // dt+ 0.25; T_L+ is 10 there) and the rest to the blend's end (y+
    // 10-100: 20000 tracers, 300 time units at dt+ 0.5): every bin within
    // max(5 %, 3 SE) of the mean concentration (SE 1.7 % in y+ 0-1). The
    // walk without the drift gathers tracers where the rms is small: some
    // bin is off by more than 30 % within 100 time units
    const std::vector<double> inner{0, 1, 3, 10}, outer{10, 30, 60, 80, 100};
    const auto near = heldStepConcentration(0, 10, inner, 30000, 150, 0.25, 1);
    const auto far = heldStepConcentration(10, 100, outer, 20000, 300, 0.5, 1);
    EXPECT_TRUE(testCases::wellMixed(inner, near));
    EXPECT_TRUE(testCases::wellMixed(outer, far));

    const auto noDrift =
        heldStepConcentration(0, 10, inner, 10000, 100, 0.25, 0);
    EXPECT_GT(testCases::worstBin(noDrift), 0.3);
}


// ************************************************************************* //
