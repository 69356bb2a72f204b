// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The fluid velocity seen (SeenVelocity): the wall's frame is right-handed
// and orthonormal with s along the mean flow's part parallel to the wall;
// the step's mean and variance equal the textbook solution of the
// Ornstein-Uhlenbeck process with constant drift (the same formula as the
// code's, so this checks the transcription and the components' wiring);
// the independent checks are the composition of two half steps into one
// (Chapman-Kolmogorov) and the stationary law N(a T/(1 + St), 1), kept by
// a step of any length in a Monte Carlo sample (which also checks the
// factor 1/(1 + St) on its own).

#include "SeenVelocity.H"
#include "inputErrorAssertions.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace brachDunn;
using brachDunn::testCases::throwsInputError;

namespace
{

double sqr(double x)
{
    return x*x;
}

void expectOrthonormal(const WallFrame& f)
{
    EXPECT_NEAR(mag(f.s), 1, 1e-15);
    EXPECT_NEAR(mag(f.n), 1, 1e-15);
    EXPECT_NEAR(mag(f.z), 1, 1e-15);
    EXPECT_NEAR(dot(f.s, f.n), 0, 1e-15);
    EXPECT_NEAR(dot(f.s, f.z), 0, 1e-15);
    EXPECT_NEAR(dot(f.n, f.z), 0, 1e-15);
    // right-handed: s x n = z
    const Vector3 c = cross(f.s, f.n);
    EXPECT_NEAR(mag(c - f.z), 0, 1e-15);
}

} // End namespace


TEST(WallFrame, StreamwiseAlongTheMeanFlowsPartParallelToTheWall)
{
    // A tilted wall (normal (1, 2, 2)/3) and a flow with a part into it
    const Vector3 n{1, 2, 2};
    const Vector3 U{3, -1, 0.5};
    const WallFrame f = WallFrame::of(n, U);
    expectOrthonormal(f);
    EXPECT_NEAR(mag(f.n - (1.0/3)*n), 0, 1e-15);
    const Vector3 along = U - dot(U, f.n)*f.n;
    EXPECT_NEAR(mag(f.s - (1/mag(along))*along), 0, 1e-15);
    // a vector's components and back
    const Vector3 v{0.3, -7, 2};
    EXPECT_NEAR(mag(f.global(f.local(v)) - v), 0, 1e-14);
}


TEST(WallFrame, NoFlowAlongTheWallTakesAnAxis)
{
    for (const Vector3& U : {Vector3{0, 0, 0}, Vector3{0, 0, -4}})
    {
        const WallFrame f = WallFrame::of({0, 0, 1}, U);
        expectOrthonormal(f);
        EXPECT_NEAR(std::abs(dot(f.n, {0, 0, 1})), 1, 1e-15);
    }
    EXPECT_TRUE(throwsInputError
    (
        [] { WallFrame::of({0, 0, 0}, {1, 0, 0}); }, "wall normal length", "0"
    ));
}


TEST(SeenVelocityStep, MeanAndVarianceAreTheOrnsteinUhlenbecksWithDrift)
{
    // dw_i = (-w_i/T_i + a_i/(1 + St)) dt + sqrt(2/T_i) dW_i from w0 over
    // dt, St = tauP/TL: mean m_i + (w0_i - m_i) e^-dt/T_i,
    // m_i = a_i T_i/(1 + St); variance 1 - e^-2dt/T_i. With xi = 0 the
    // step gives the mean; xi = e_i adds the standard deviation to
    // component i alone
    const SeenStatistics stats
    {
        {1.1, 0.4, 0.7}, {-30, 250, 12}, 2.5e-3, {2.5e-3, 1e-3, 4e-3}
    };
    const Vector3 w0{0.8, -1.3, 2.1};
    const double a[3] = {-30, 250, 12}, T[3] = {2.5e-3, 1e-3, 4e-3},
        w[3] = {0.8, -1.3, 2.1};
    for (const double tauP : {0.0, 1e-3, 0.05})
    {
        const double scale = 1/(1 + tauP/stats.TL);
        for (const double dt : {1e-9, 1e-5, 1e-3, 2.5e-3, 0.1})
        {
            double mean[3], sd[3];
            for (int i = 0; i < 3; ++i)
            {
                const double m = a[i]*T[i]*scale, e = std::exp(-dt/T[i]);
                mean[i] = m + (w[i] - m)*e;
                // (in long double: 1 - e^2 cancels at small dt/T)
                sd[i] = double(std::sqrt(-std::expm1(-2.0L*dt/T[i])));
            }
            const Vector3 got = seenVelocityStep(w0, stats, tauP, dt, {0, 0, 0});
            EXPECT_NEAR(got.x, mean[0], 1e-13*std::abs(mean[0]) + 1e-15);
            EXPECT_NEAR(got.y, mean[1], 1e-13*std::abs(mean[1]) + 1e-15);
            EXPECT_NEAR(got.z, mean[2], 1e-13*std::abs(mean[2]) + 1e-15);
            const Vector3 up = seenVelocityStep(w0, stats, tauP, dt, {0, 1, 0});
            // (the difference of two values near w0 carries its rounding)
            EXPECT_NEAR(up.y - got.y, sd[1], 1e-12*sd[1] + 1e-15) << dt;
            EXPECT_DOUBLE_EQ(up.x, got.x);
            EXPECT_DOUBLE_EQ(up.z, got.z);
        }
    }
}


TEST(SeenVelocityStep, TwoHalfStepsComposeIntoOne)
{
    // Chapman-Kolmogorov: the mean after two half steps is the mean after
    // one; the variance e^-h (1 - e^-h) + (1 - e^-h) = 1 - e^-2h, with the
    // first half's spread decayed over the second
    const SeenStatistics stats{{1, 1, 1}, {40, -15, 3}, 1e-3, {1e-3, 1e-3, 1e-3}};
    const Vector3 w0{1.5, 0.2, -0.7};
    const double dt = 7e-4, tauP = 2e-4;
    const Vector3 half = seenVelocityStep(w0, stats, tauP, dt/2, {0, 0, 0});
    const Vector3 two = seenVelocityStep(half, stats, tauP, dt/2, {0, 0, 0});
    const Vector3 one = seenVelocityStep(w0, stats, tauP, dt, {0, 0, 0});
    EXPECT_NEAR(mag(two - one), 0, 1e-14);

    const double sHalf =
        seenVelocityStep(w0, stats, tauP, dt/2, {1, 0, 0}).x - half.x;
    const double sOne = seenVelocityStep(w0, stats, tauP, dt, {1, 0, 0}).x - one.x;
    const double eHalf = std::exp(-dt/2/stats.T.x);
    EXPECT_NEAR(sqr(sHalf*eHalf) + sqr(sHalf), sqr(sOne), 1e-14);
}


TEST(SeenVelocityStep, StationaryLawIsKeptAndSampled)
{
    // From w0 ~ N(m, 1), one step of any length keeps N(m, 1): a Monte
    // Carlo sample of 200000 within 5 standard errors
    const SeenStatistics stats{{1, 1, 1}, {0, 80, 0}, 5e-3, {5e-3, 5e-3, 5e-3}};
    const double tauP = 5e-3, m = 80*5e-3/2;
    std::mt19937_64 gen(20261207);
    std::normal_distribution<double> normal;
    const int n = 200000;
    for (const double dt : {1e-4, 5e-3, 1.0})
    {
        double sum = 0, sumSqr = 0;
        for (int i = 0; i < n; ++i)
        {
            const Vector3 w0{0, m + normal(gen), 0};
            const Vector3 xi{normal(gen), normal(gen), normal(gen)};
            const double w = seenVelocityStep(w0, stats, tauP, dt, xi).y;
            sum += w;
            sumSqr += sqr(w - m);
        }
        const double mean = sum/n, var = sumSqr/n - sqr(mean - m);
        EXPECT_NEAR(mean, m, 5/std::sqrt(double(n))) << dt;
        EXPECT_NEAR(var, 1, 5*std::sqrt(2.0/n)) << dt;
    }
}


TEST(SeenVelocityStep, BadInputNamesItsKeyword)
{
    const SeenStatistics stats{{1, 1, 1}, {0, 0, 0}, 1e-3, {1e-3, 1e-3, 1e-3}};
    EXPECT_TRUE(throwsInputError
    (
        [&] { seenVelocityStep({0, 0, 0}, stats, 0, -1e-3, {0, 0, 0}); },
        "dt", "-0.001"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [&]
        {
            seenVelocityStep
            (
                {0, 0, 0}, {{1, 1, 1}, {0, 0, 0}, 1e-3, {1e-3, 0, 1e-3}}, 0,
                1e-3, {0, 0, 0}
            );
        },
        "T", "0"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [&] { seenVelocityStep({0, 0, 0}, stats, -1, 1e-3, {0, 0, 0}); },
        "tauP", "-1"
    ));
}
