// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The exact Brownian step (BrownianStep): the moments of the
// Ornstein-Uhlenbeck transition against the closed forms evaluated here in
// long double (as Taylor remainders for small h, directly otherwise: not
// the code's arrangement), their limits (diffusive, ballistic), the
// composition of two steps into one (Chapman-Kolmogorov: an independent
// check of the functional form), the thermal distribution kept stationary,
// and Monte Carlo: the correlated draw reproduces the covariance, and steps
// iterated reproduce the mean squared displacement of both closed forms.

#include "BrownianStep.H"
#include "inputErrorAssertions.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace brachDunn;
using brachDunn::testCases::throwsInputError;

namespace
{

//- A particle: tau [s], kB T/m [m^2/s^2] (arbitrary, not round numbers)
constexpr double tau = 2.5e-7, sigmaSqr = 3.7;

//- The step ratios h = dt/tau checked, on both sides of the code's
//  switches (h = 2) and across the range
const double ratios[] =
{
    1e-10, 1e-7, 1e-4, 1e-2, 0.1, 0.5, 0.9, 1.0, 1.5, 1.999, 2.0, 2.001,
    3.0, 7.0, 20.0, 50.0, 1e3, 1e6, 1e12
};


//- e^y less its Taylor terms below y^from: sum over k >= from of y^k/k!
//  (for |y| <= 1, in long double)
long double expRemainder(long double y, int from)
{
    long double term = 1, sum = 0;
    for (int k = 1; k < 60; ++k)
    {
        term *= y/k;
        if (k >= from)
        {
            sum += term;
        }
    }
    return sum;
}


//- 1 - e^-h, 1 - e^-2h, h - 1 + e^-h and 2h - 3 + 4e^-h - e^-2h: as
//  Taylor remainders below h = 1/2, directly above
struct Reference
{
    long double a, oneMinusE2, g, f;
};

Reference reference(long double h)
{
    if (h < 0.5L)
    {
        return
        {
            -expRemainder(-h, 1),
            -expRemainder(-2*h, 1),
            expRemainder(-h, 2),
            4*expRemainder(-h, 3) - expRemainder(-2*h, 3)
        };
    }
    const long double E = std::exp(-h);
    return {1 - E, 1 - E*E, h - 1 + E, 2*h - 3 + 4*E - E*E};
}


::testing::AssertionResult relativelyNear
(
    long double actual,
    long double expected,
    long double tol
)
{
    const long double error =
        expected == 0
      ? std::abs(actual)
      : std::abs(actual - expected)/std::abs(expected);
    if (error <= tol)
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
        << double(actual) << " differs from " << double(expected)
        << " by " << double(error) << " (relative) > " << double(tol);
}


//- The moments of a transition as long double
struct Moments
{
    long double E, T, xx, xv, vv;
};

Moments moments(const BrownianTransition& s)
{
    return
    {
        s.velocityDecay, s.displacementPerVelocity,
        s.displacementVariance, s.covariance, s.velocityVariance
    };
}


//- Step 1, then step 2: (x, v) -> (x + T2 v + xi, E2 v + eta)
Moments compose(const Moments& s1, const Moments& s2)
{
    return
    {
        s1.E*s2.E,
        s1.T + s2.T*s1.E,
        s1.xx + 2*s2.T*s1.xv + s2.T*s2.T*s1.vv + s2.xx,
        s2.E*s1.xv + s2.T*s2.E*s1.vv + s2.xv,
        s2.E*s2.E*s1.vv + s2.vv
    };
}


} // End anonymous namespace


TEST(BrownianStep, MomentsAgainstClosedForms)
{
    // To a few roundings at every h (2.3 at worst seen): nothing cancels in
    // the code's forms
    const long double tol = 1e-15L;
    for (const double h : ratios)
    {
        SCOPED_TRACE(h);
        const BrownianTransition s = brownianTransition(h*tau, tau, sigmaSqr);
        const Reference r = reference(h);
        const long double tauL = tau;
        // (e^-h rounded to double first: below 1e-308 it is 0 there)
        EXPECT_TRUE(relativelyNear
        (
            s.velocityDecay, double(std::exp(-(long double)h)), tol
        ));
        EXPECT_TRUE(relativelyNear(s.displacementPerVelocity, tauL*r.a, tol));
        EXPECT_TRUE(relativelyNear(s.velocityVariance, sigmaSqr*r.oneMinusE2, tol));
        EXPECT_TRUE(relativelyNear(s.covariance, sigmaSqr*tauL*r.a*r.a, tol));
        EXPECT_TRUE(relativelyNear
        (
            s.displacementVariance, sigmaSqr*tauL*tauL*r.f, tol
        ));
    }
}


TEST(BrownianStep, CholeskyFactor)
{
    // velocityScale^2 = Var v, the product = Cov, and the conditional
    // variance is the Schur complement Var x - Cov^2/Var v (here from the
    // long-double references; it cancels by a factor 4 at small h)
    for (const double h : ratios)
    {
        SCOPED_TRACE(h);
        const BrownianTransition s = brownianTransition(h*tau, tau, sigmaSqr);
        const Reference r = reference(h);
        const long double tauL = tau;
        const long double vv = sigmaSqr*r.oneMinusE2;
        const long double xv = sigmaSqr*tauL*r.a*r.a;
        const long double xx = sigmaSqr*tauL*tauL*r.f;
        const long double sv = s.velocityScale, sc = s.correlatedScale;
        const long double sx = s.independentScale;
        EXPECT_TRUE(relativelyNear(sv*sv, vv, 4e-15L));
        EXPECT_TRUE(relativelyNear(sc*sv, xv, 4e-15L));
        EXPECT_TRUE(relativelyNear(sx*sx, xx - xv*xv/vv, 4e-15L));
    }

    // No step: no motion, no 0/0
    const BrownianTransition none = brownianTransition(0, tau, sigmaSqr);
    EXPECT_EQ(none.velocityDecay, 1.0);
    EXPECT_EQ(none.velocityScale, 0.0);
    EXPECT_EQ(none.correlatedScale, 0.0);
    EXPECT_EQ(none.independentScale, 0.0);
    EXPECT_EQ(none.displacementVariance, 0.0);
}


TEST(BrownianStep, DiffusiveLimit)
{
    // h -> infinity: Var v -> kT/m and Var dx = 2 D dt - 3 D tau + ...,
    // D = (kT/m) tau; finite up to h = 1e12
    const double D = sigmaSqr*tau;
    for (const double h : {50.0, 1e3, 1e6, 1e12})
    {
        SCOPED_TRACE(h);
        const double dt = h*tau;
        const BrownianTransition s = brownianTransition(dt, tau, sigmaSqr);
        EXPECT_NEAR(s.velocityVariance/sigmaSqr, 1, 1e-15);
        EXPECT_NEAR(s.covariance/(sigmaSqr*tau), 1, 1e-15);
        EXPECT_NEAR(s.displacementVariance/(2*D*dt), 1 - 1.5/h, 1e-15);
        EXPECT_NEAR(brownianMsdThermalStart(dt, tau, D)/(2*D*dt), 1 - 1/h, 1e-15);
        EXPECT_NEAR(brownianMsdFromRest(dt, tau, D)/(2*D*dt), 1 - 1.5/h, 1e-15);
        EXPECT_TRUE(std::isfinite(s.independentScale));
    }
}


TEST(BrownianStep, BallisticLimit)
{
    // h -> 0: Var v ~ 2 (kT/m) h, Cov ~ (kT/m) tau h^2 and the noise's own
    // displacement Var dx ~ (2/3)(kT/m) dt^3/tau; the ballistic
    // (kT/m) dt^2 is the MSD from a thermal start (v0 random), and from rest
    // the MSD is Var dx. The next terms are relative O(h).
    const double D = sigmaSqr*tau;
    for (const double h : {1e-4, 1e-7, 1e-10})
    {
        SCOPED_TRACE(h);
        const double dt = h*tau;
        const BrownianTransition s = brownianTransition(dt, tau, sigmaSqr);
        EXPECT_NEAR(s.velocityVariance/(2*sigmaSqr*h), 1, 2*h);
        EXPECT_NEAR(s.covariance/(sigmaSqr*tau*h*h), 1, 2*h);
        EXPECT_NEAR
        (
            s.displacementVariance/(2.0/3*sigmaSqr*dt*dt*dt/tau), 1, 2*h
        );
        EXPECT_NEAR(brownianMsdThermalStart(dt, tau, D)/(sigmaSqr*dt*dt), 1, 2*h);
        EXPECT_NEAR
        (
            brownianMsdFromRest(dt, tau, D)/(2.0/3*sigmaSqr*dt*dt*dt/tau), 1, 2*h
        );
    }
}


TEST(BrownianStep, CovariancePositiveSemiDefinite)
{
    // Cov^2 <= Var x Var v; the squared correlation falls from 3/4 (h -> 0)
    // to 0 (h -> infinity): never near 1
    double previous = 0.75;
    for (double h = 1e-10; h <= 1e12; h *= 1.5)
    {
        SCOPED_TRACE(h);
        const BrownianTransition s = brownianTransition(h*tau, tau, sigmaSqr);
        const long double xx = s.displacementVariance, vv = s.velocityVariance;
        const long double xv = s.covariance;
        ASSERT_GT(xx, 0);
        ASSERT_GT(vv, 0);
        const double rhoSqr = xv*xv/(xx*vv);
        EXPECT_LE(rhoSqr, 0.75*(1 + 1e-14));
        EXPECT_LE(rhoSqr, previous*(1 + 1e-14));
        previous = rhoSqr;
    }
    const BrownianTransition small = brownianTransition(1e-9*tau, tau, 1);
    EXPECT_NEAR
    (
        small.covariance*small.covariance
       /(small.displacementVariance*small.velocityVariance),
        0.75, 1e-8
    );
}


TEST(BrownianStep, TwoStepsMakeOneStep)
{
    // Chapman-Kolmogorov: steps of 0.3 dt then 0.7 dt, and two of dt/2,
    // compose to the step dt (means and covariance; positive terms only)
    for (const double h : ratios)
    {
        if (h > 1e6)
        {
            continue;   // e^-0.3h underflows: nothing left to compose
        }
        SCOPED_TRACE(h);
        const Moments one = moments(brownianTransition(h*tau, tau, sigmaSqr));
        for (const double first : {0.3, 0.5})
        {
            const Moments composed = compose
            (
                moments(brownianTransition(first*h*tau, tau, sigmaSqr)),
                moments(brownianTransition((1 - first)*h*tau, tau, sigmaSqr))
            );
            EXPECT_TRUE(relativelyNear(composed.E, one.E, 1e-14L));
            EXPECT_TRUE(relativelyNear(composed.T, one.T, 1e-14L));
            EXPECT_TRUE(relativelyNear(composed.xx, one.xx, 1e-14L));
            EXPECT_TRUE(relativelyNear(composed.xv, one.xv, 1e-14L));
            EXPECT_TRUE(relativelyNear(composed.vv, one.vv, 1e-14L));
        }
    }
}


TEST(BrownianStep, ThermalDistributionIsStationary)
{
    // v0 drawn from N(0, kT/m): after any step Var v = e^-2h kT/m + Var v
    // = kT/m
    for (const double h : ratios)
    {
        const BrownianTransition s = brownianTransition(h*tau, tau, sigmaSqr);
        const long double E = s.velocityDecay;
        EXPECT_TRUE(relativelyNear
        (
            E*E*sigmaSqr + s.velocityVariance, sigmaSqr, 1e-15L
        )) << h;
    }
}


TEST(BrownianStep, MsdClosedForms)
{
    // Against the long-double references, and tied to the transition:
    // from rest, the MSD is Var dx; from a thermal start, Var dx plus the
    // variance of the mean v0 tau a, (kT/m) (tau a)^2
    const double D = sigmaSqr*tau;
    for (const double h : ratios)
    {
        SCOPED_TRACE(h);
        const double t = h*tau;
        const Reference r = reference(h);
        EXPECT_TRUE(relativelyNear
        (
            brownianMsdThermalStart(t, tau, D), 2*D*(long double)tau*r.g, 1e-15L
        ));
        EXPECT_TRUE(relativelyNear
        (
            brownianMsdFromRest(t, tau, D), D*(long double)tau*r.f, 1e-15L
        ));

        const BrownianTransition s = brownianTransition(t, tau, sigmaSqr);
        const long double T = s.displacementPerVelocity;
        EXPECT_TRUE(relativelyNear
        (
            brownianMsdFromRest(t, tau, D), s.displacementVariance, 1e-15L
        ));
        EXPECT_TRUE(relativelyNear
        (
            brownianMsdThermalStart(t, tau, D),
            s.displacementVariance + sigmaSqr*T*T,
            1e-15L
        ));
    }
}


TEST(BrownianStep, SamplesReproduceTheCovariance)
{
    // Monte Carlo with independent normals (not the project's generator):
    // means, variances and covariance within 5 standard errors
    std::mt19937_64 engine(20240607);
    std::normal_distribution<double> normal;
    const int n = 400000;
    for (const double h : {1e-3, 1.0, 20.0})
    {
        SCOPED_TRACE(h);
        const BrownianTransition s = brownianTransition(h*tau, tau, sigmaSqr);
        const double v0 = 0.7*std::sqrt(sigmaSqr);
        const double meanX = s.displacementPerVelocity*v0;
        const double meanV = s.velocityDecay*v0;
        long double sx = 0, sv = 0, sxx = 0, sxv = 0, svv = 0;
        for (int i = 0; i < n; ++i)
        {
            const double z1 = normal(engine), z2 = normal(engine);
            const BrownianSample b = sampleBrownian(s, v0, z1, z2);
            const long double x = b.displacement - meanX;
            const long double v = b.velocity - meanV;
            sx += x; sv += v; sxx += x*x; sxv += x*v; svv += v*v;
        }
        const double xx = s.displacementVariance, vv = s.velocityVariance;
        const double xv = s.covariance;
        EXPECT_NEAR(double(sx/n), 0, 5*std::sqrt(xx/n));
        EXPECT_NEAR(double(sv/n), 0, 5*std::sqrt(vv/n));
        EXPECT_NEAR(double(sxx/n), xx, 5*xx*std::sqrt(2.0/n));
        EXPECT_NEAR(double(svv/n), vv, 5*vv*std::sqrt(2.0/n));
        EXPECT_NEAR(double(sxv/n), xv, 5*std::sqrt((xx*vv + xv*xv)/n));
    }
}


TEST(BrownianStep, IteratedStepsReproduceTheMsd)
{
    // Parcels stepped 50 times by h = 0.2 (to t = 10 tau) from a thermal
    // start and from rest: <x^2> after 1, 5 and 50 steps against the two
    // closed forms, within 5 standard errors (x is normal: the error of the
    // mean of x^2 is <x^2> sqrt(2/n))
    std::mt19937_64 engine(7);
    std::normal_distribution<double> normal;
    const int n = 100000, steps = 50;
    const double h = 0.2, dt = h*tau, D = sigmaSqr*tau;
    const BrownianTransition s = brownianTransition(dt, tau, sigmaSqr);
    const int checked[] = {1, 5, 50};

    for (const bool thermal : {true, false})
    {
        SCOPED_TRACE(thermal ? "thermal start" : "from rest");
        std::vector<long double> sumSqr(steps + 1, 0);
        for (int i = 0; i < n; ++i)
        {
            double x = 0;
            double v = thermal ? std::sqrt(sigmaSqr)*normal(engine) : 0;
            for (int k = 1; k <= steps; ++k)
            {
                const double z1 = normal(engine), z2 = normal(engine);
                const BrownianSample b = sampleBrownian(s, v, z1, z2);
                x += b.displacement;
                v = b.velocity;
                sumSqr[k] += x*x;
            }
        }
        for (const int k : checked)
        {
            const double expected =
                thermal
              ? brownianMsdThermalStart(k*dt, tau, D)
              : brownianMsdFromRest(k*dt, tau, D);
            EXPECT_NEAR(double(sumSqr[k]/n), expected,
                        5*expected*std::sqrt(2.0/n)) << k << " steps";
        }
    }
}


TEST(BrownianStep, BadInput)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(throwsInputError
        ([] { brownianTransition(-1e-9, tau, 1); }, "dt", "-1e-09"));
    EXPECT_TRUE(throwsInputError
        ([&] { brownianTransition(nan, tau, 1); }, "dt", "nan"));
    EXPECT_TRUE(throwsInputError
        ([] { brownianTransition(1e-9, 0, 1); }, "tau", "0"));
    EXPECT_TRUE(throwsInputError
        ([&] { brownianTransition(1e-9, inf, 1); }, "tau", "inf"));
    EXPECT_TRUE(throwsInputError
        ([] { brownianTransition(1e-9, tau, -1); }, "thermalVariance", "-1"));
    EXPECT_TRUE(throwsInputError
        ([&] { brownianTransition(1e-9, tau, nan); }, "thermalVariance", "nan"));

    for (const auto msd : {&brownianMsdThermalStart, &brownianMsdFromRest})
    {
        EXPECT_TRUE(throwsInputError([&] { msd(-1, tau, 1); }, "t", "-1"));
        EXPECT_TRUE(throwsInputError([&] { msd(1, -tau, 1); }, "tau", "-2.5e-07"));
        EXPECT_TRUE(throwsInputError([&] { msd(1, tau, -2); }, "D", "-2"));
        EXPECT_TRUE(throwsInputError([&] { msd(inf, tau, 1); }, "t", "inf"));
    }
}
