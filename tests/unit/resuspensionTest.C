// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Resuspension of a sphere resting on a wall (Resuspension): the JKR
// pull-off force and zero-load contact radius against JKR's load-radius
// relation solved here (bisection, a scan for its minimum), the shear-flow
// load against the published forms, the rolling threshold against the
// moment balance solved by bisection, the normal and log-normal quantiles
// against tabulated values and the integrated density, the rock'n'roll
// rate against its limits (the Gaussian tail above the mean force, the
// asymptote far below it, p = omega/pi at the mean), the population's
// fraction remaining against exact cases, a trapezoid sum and Monte Carlo
// over the quantile, and bad input.

#include "Resuspension.H"
#include "Materials.H"
#include "inputErrorAssertions.H"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace brachDunn;
using brachDunn::testCases::throwsInputError;

namespace
{

constexpr long double piL = 3.141592653589793238462643383279503L;

//- Alumina on stainless steel (handbook values, for the tests only):
//  E [Pa], nu [-]
const ElasticMaterial alumina{3.7e11, 0.22}, steel{1.93e11, 0.30};

//- Work of adhesion [J/m^2] and radii [m] checked
constexpr double w = 0.56;
const double radii[] = {0.3e-6, 2.5e-6, 5e-6, 10e-6, 27e-6};


//- JKR's load P [N] at contact radius a [m]: P = K a^3/r - sqrt(6 pi w
//  K a^3) (the load-radius relation solved for the load)
long double jkrLoad(long double a, long double r, long double K)
{
    return K*a*a*a/r - std::sqrt(6*piL*w*K*a*a*a);
}


//- The root of a continuous g between lo and hi (g(lo), g(hi) of
//  opposite signs), by bisection to the last bit
template<class Function>
long double bisect(const Function& g, long double lo, long double hi)
{
    const bool rising = g(hi) > 0;
    for (int i = 0; i < 200; ++i)
    {
        const long double mid = 0.5L*(lo + hi);
        if ((g(mid) > 0) == rising) hi = mid; else lo = mid;
    }
    return 0.5L*(lo + hi);
}


//- The rate as printed: (omega/2 pi) exp(-x^2)/((1 + erf x)/2), in long
//  double with erf (not erfc) as in the paper
long double printedRate
(
    long double fa,
    long double mean,
    long double rms,
    long double omega
)
{
    const long double x = (fa - mean)/std::sqrt(2*rms*rms);
    return omega/(2*piL)*std::exp(-x*x)/(0.5L*(1 + std::erf(x)));
}

} // End anonymous namespace


TEST(Resuspension, ContactModulusOfTwoMaterials)
{
    const double expected =
        1/((1 - 0.22*0.22)/3.7e11 + (1 - 0.30*0.30)/1.93e11);
    EXPECT_NEAR(contactModulus(alumina, steel), expected, 1e-14*expected);
    EXPECT_DOUBLE_EQ
    (
        contactModulus(alumina, steel), contactModulus(steel, alumina)
    );
}


TEST(Resuspension, JkrAgainstTheLoadRadiusRelation)
{
    const double Estar = contactModulus(alumina, steel);
    const long double K = 4.0L/3*Estar;
    for (const double r : radii)
    {
        // Zero load: the positive root of P(a) = 0 (P < 0 below it)
        const long double aScale = std::cbrt(w*r*r/K);
        const long double a0 = bisect
        (
            [&](long double a) { return jkrLoad(a, r, K); },
            0.1L*aScale, 100*aScale
        );
        EXPECT_NEAR(jkrContactRadius(w, r, Estar), a0, 1e-13*a0) << r;

        // Pull-off under load control: the least load of the relation,
        // found by a golden-section search, is -(3/2) pi w r
        long double lo = 0.01L*a0, hi = a0;
        const long double g = (std::sqrt(5.0L) - 1)/2;
        for (int i = 0; i < 200; ++i)
        {
            const long double m1 = hi - g*(hi - lo), m2 = lo + g*(hi - lo);
            if (jkrLoad(m1, r, K) < jkrLoad(m2, r, K)) hi = m2; else lo = m1;
        }
        const long double least = jkrLoad(0.5L*(lo + hi), r, K);
        EXPECT_NEAR(jkrPullOffForce(w, r), -least, 1e-12*std::abs(least));
    }
}


TEST(Resuspension, ShearLoadAgainstThePublishedForms)
{
    // F = 1.7009 6 pi mu r U with U = gamma r, M = 0.944 4 pi mu r^3 gamma:
    // written with a viscosity and a shear rate, which drop out
    for (const double mu : {1.8e-5, 3.9e-5, 1e-3})
    {
        for (const double r : radii)
        {
            const double gamma = 2.3e4, tauW = mu*gamma;
            const long double F = 1.7009L*6*piL*mu*r*(gamma*r);
            const long double M = 0.944L*4*piL*mu*r*r*r*gamma;
            EXPECT_NEAR(wallShearDrag(tauW, r), F, 1e-14*F);
            EXPECT_NEAR(wallShearTorque(tauW, r), M, 1e-14*M);
        }
    }
    EXPECT_NEAR(rollingLoadFactor, 13.9814, 1e-12);
    EXPECT_EQ(wallShearDrag(0, 1e-6), 0);
    EXPECT_EQ(wallShearTorque(0, 1e-6), 0);
}


TEST(Resuspension, RollingThresholdAgainstTheMomentBalance)
{
    const double Estar = contactModulus(alumina, steel);
    for (const double r : radii)
    {
        for (const double reduced : {1.0, 0.05, 0.003})
        {
            const double Fadh = reduced*jkrPullOffForce(w, r);
            const double a0 = jkrContactRadius(w, r, Estar);

            // The net moment about the downstream contact edge, written
            // out: torque + drag at the centre's height - adhesion at the
            // contact's centre
            const auto net = [&](long double tau)
            {
                const long double drag = 1.7009L*6*piL*tau*r*r;
                const long double torque = 0.944L*4*piL*tau*r*r*r;
                return torque + drag*r - Fadh*(long double)(a0);
            };
            const long double tauC = bisect(net, 0, 1e12L);
            const double tauCode = criticalWallShearStress(r, Fadh, a0);
            EXPECT_NEAR(tauCode, tauC, 1e-13*tauC) << r << ' ' << reduced;

            // It stays below the threshold, leaves at and above it
            EXPECT_LT(rollingMomentRatio(0.999999*tauCode, r, Fadh, a0), 1);
            EXPECT_GE(rollingMomentRatio(1.000001*tauCode, r, Fadh, a0), 1);
            EXPECT_NEAR(rollingMomentRatio(tauCode, r, Fadh, a0), 1, 1e-14);

            // u* from tau_w = rho u*^2, and the JKR shorthand
            const double rho = 1.19;
            const double ustar = criticalFrictionVelocity(r, Fadh, a0, rho);
            EXPECT_NEAR(rho*ustar*ustar, tauC, 1e-13*tauC);
            EXPECT_NEAR
            (
                criticalFrictionVelocityJkr(r, w, Estar, rho, reduced),
                ustar, 1e-14*ustar
            );

            // The moment force over the adhesion is the moment ratio
            EXPECT_NEAR
            (
                momentBalanceForce(3.7, r, a0)/Fadh,
                rollingMomentRatio(3.7, r, Fadh, a0), 1e-13
            );
        }
    }
}


TEST(Resuspension, CriticalShearStressScaling)
{
    // Smooth JKR contact: tau_c = (3/2) w a0/(C r^2) ~ w^(4/3) r^(-4/3)
    // E*^(-1/3): halving r raises tau_c by 2^(4/3), independently of E*
    const double Estar = contactModulus(alumina, steel);
    const double rho = 1;
    const double u1 = criticalFrictionVelocityJkr(10e-6, w, Estar, rho);
    const double u2 = criticalFrictionVelocityJkr(5e-6, w, Estar, rho);
    EXPECT_NEAR(u2*u2/(u1*u1), std::pow(2.0, 4.0/3), 1e-12);
    const double u3 = criticalFrictionVelocityJkr(10e-6, w, 8*Estar, rho);
    EXPECT_NEAR(u3*u3/(u1*u1), 0.5, 1e-12);
}


TEST(Resuspension, NormalQuantileAgainstTables)
{
    // Phi^-1 at tabulated points (Abramowitz & Stegun Table 26.5 and the
    // exact Phi(1) = 0.8413447460685429...)
    EXPECT_EQ(standardNormalQuantile(0.5), 0);
    EXPECT_NEAR(standardNormalQuantile(0.975), 1.959963984540054, 1e-14);
    EXPECT_NEAR(standardNormalQuantile(0.025), -1.959963984540054, 1e-14);
    EXPECT_NEAR(standardNormalQuantile(0.8413447460685429), 1, 2e-15);
    EXPECT_NEAR(standardNormalQuantile(1e-10), -6.361340902404056, 1e-13);

    // Phi(Phi^-1(u)) = u, relative to u, over the whole range (also the
    // far tail, and the upper half through 1 - u)
    for (const double u :
        {1e-300, 1e-200, 1e-50, 1e-16, 1e-6, 0.01, 0.3, 0.49, 0.5})
    {
        const double z = standardNormalQuantile(u);
        EXPECT_NEAR(standardNormalCdf(z), u, 1e-13*u) << u;
    }
    // Symmetric: Phi^-1(v) = -Phi^-1(1 - v), 1 - v exact for v >= 1/2
    for (const double v : {0.5, 0.51, 0.7, 0.975, 1 - 1e-6, 1 - 1e-12})
    {
        EXPECT_EQ(standardNormalQuantile(v), -standardNormalQuantile(1 - v))
            << v;
    }

    // Increasing
    double previous = -std::numeric_limits<double>::infinity();
    for (int i = 1; i < 1000; ++i)
    {
        const double z = standardNormalQuantile(i/1000.0);
        EXPECT_GT(z, previous);
        previous = z;
    }
}


TEST(Resuspension, LogNormalQuantileAgainstTheIntegratedDensity)
{
    for (const LogNormalAdhesion& d :
        {LogNormalAdhesion{0.0105, 3.1}, LogNormalAdhesion{0.0079, 5.2},
         LogNormalAdhesion{0.3, 1.05}})
    {
        // The pdf integrated (Simpson in ln f, fine) from far below up to
        // the quantile gives back the share u
        for (const double u : {0.001, 0.05, 0.3, 0.5, 0.77, 0.99})
        {
            const double upper = d.quantile(u);
            const double lo = std::log(d.geometricMean) - 12*std::log(d.geometricSpread);
            const double hi = std::log(upper);
            const int n = 20000;
            const double h = (hi - lo)/n;
            long double sum = 0;
            for (int i = 0; i <= n; ++i)
            {
                const double s = lo + i*h;
                const double f = std::exp(s);
                const int weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
                sum += weight*d.pdf(f)*f;
            }
            EXPECT_NEAR(double(sum*h/3), u, 1e-9) << u;
            EXPECT_NEAR(d.cdf(upper), u, 1e-14) << u;
        }

        // The median is the geometric mean; the mean against the density
        EXPECT_NEAR(d.quantile(0.5), d.geometricMean, 1e-15*d.geometricMean);
        const double s = std::log(d.geometricSpread);
        const double lo = std::log(d.geometricMean) - 12*s;
        const double hi = std::log(d.geometricMean) + 12*s;
        const int n = 20000;
        const double h = (hi - lo)/n;
        long double total = 0, first = 0;
        for (int i = 0; i <= n; ++i)
        {
            const double f = std::exp(lo + i*h);
            const int weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
            total += weight*d.pdf(f)*f;
            first += weight*d.pdf(f)*f*f;
        }
        EXPECT_NEAR(double(total*h/3), 1, 1e-10);
        EXPECT_NEAR(double(first*h/3), d.mean(), 1e-9*d.mean());
    }
    EXPECT_EQ(LogNormalAdhesion({0.01, 3}).pdf(0), 0);
    EXPECT_EQ(LogNormalAdhesion({0.01, 3}).cdf(-1), 0);
}


TEST(Resuspension, BiasiFit)
{
    // The fit as Biasi et al. (2001) give it, r in micrometres
    for (const double rMicron : {0.5, 2.5, 5.0, 10.0, 20.0, 34.0})
    {
        const LogNormalAdhesion d = biasiAdhesion(rMicron*1e-6);
        EXPECT_NEAR
        (
            d.geometricMean, 0.016 - 0.0023*std::pow(rMicron, 0.545), 1e-15
        );
        EXPECT_NEAR
        (
            d.geometricSpread, 1.8 + 0.136*std::pow(rMicron, 1.4), 1e-13
        );
    }
    // 10 and 20 um diameters (Reeks & Hall's alumina): worked values
    EXPECT_NEAR(biasiAdhesion(5e-6).geometricMean, 0.0104707, 1e-7);
    EXPECT_NEAR(biasiAdhesion(5e-6).geometricSpread, 3.0945, 1e-4);
    EXPECT_NEAR(biasiAdhesion(10e-6).geometricMean, 0.0079327, 1e-7);
    EXPECT_NEAR(biasiAdhesion(10e-6).geometricSpread, 5.2162, 1e-4);
    EXPECT_TRUE(throwsInputError([] { biasiAdhesion(36e-6); }, "r", "3.6e-05"));
    // The fit ends where its geometric mean reaches zero:
    // r = (0.016/0.0023)^(1/0.545) um = 35.1296 um (worked by hand), the
    // radius the README and the message give
    EXPECT_GT(biasiAdhesion(35.12e-6).geometricMean, 0);
    EXPECT_TRUE
    (
        throwsInputError([] { biasiAdhesion(35.14e-6); }, "r", "3.514e-05")
    );
}


TEST(Resuspension, RateAgainstThePrintedForm)
{
    const double omega = 2*pi*0.00658*1.0/1.5e-5;
    for (const double mean : {1e-9, 3e-7})
    {
        for (const double x : {-3.0, -1.0, -0.2, 0.0, 0.7, 2.0, 6.0, 25.0})
        {
            const double rms = 0.2*mean;
            const double fa = mean + x*std::sqrt(2.0)*rms;
            if (fa < 0) continue;
            const long double expected = printedRate(fa, mean, rms, omega);
            EXPECT_NEAR
            (
                rockNRollRate(fa, mean, rms, omega), expected,
                1e-12*expected
            ) << x;
        }
    }
}


TEST(Resuspension, RateLimits)
{
    const double omega = 2.7e3, mean = 1, rms = 0.2;
    const auto xOf = [&](double fa) { return (fa - mean)/(std::sqrt(2.0)*rms); };

    // At the mean force: half the particles would be free, p = omega/pi
    EXPECT_NEAR(rockNRollRate(mean, mean, rms, omega), omega/pi, 1e-13*omega);

    // Far above the mean (strong adhesion): the Gaussian tail,
    // p -> (omega/2 pi) exp(-x^2) with relative difference erfc(x)/2
    for (const double fa : {2.0, 3.0, 5.0})
    {
        const double x = xOf(fa);
        const double tail = omega/(2*pi)*std::exp(-x*x);
        const double p = rockNRollRate(fa, mean, rms, omega);
        EXPECT_NEAR(p/tail - 1, std::erfc(x)/(1 + std::erf(x)), 1e-12) << fa;
        EXPECT_LT(std::abs(p/tail - 1), 1e-6) << fa;
    }
    EXPECT_EQ(rockNRollRate(1e3, mean, rms, omega), 0);

    // Far below (weak adhesion): not omega/2 pi but the conditional rate
    // of a particle almost surely free, p ~ (omega/sqrt(pi)) y (1 + 1/(2
    // y^2) - 1/y^4 ...), y = -x
    for (const double y : {30.0, 100.0, 1e3, 1e6})
    {
        const double fa = 1, meanHere = fa + y*std::sqrt(2.0)*rms;
        const double asymptote =
            omega/std::sqrt(pi)*y*(1 + 0.5/(y*y) - 0.5/std::pow(y, 4));
        const double p = rockNRollRate(fa, meanHere, rms, omega);
        EXPECT_NEAR(p/asymptote, 1, 5/std::pow(y, 6) + 1e-13) << y;
    }

    // Continuous across the switch to the continued fraction (x = -20)
    const double faSwitch = mean - 20*std::sqrt(2.0)*0.01;
    const double below = rockNRollRate(faSwitch*(1 - 1e-12), mean, 0.01, omega);
    const double above = rockNRollRate(faSwitch*(1 + 1e-12), mean, 0.01, omega);
    EXPECT_NEAR(below/above, 1, 1e-11);

    // Decreasing in the adhesion; independent of the unit of force
    double previous = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 400; ++i)
    {
        const double fa = 0.01*i;
        const double p = rockNRollRate(fa, mean, rms, omega);
        EXPECT_LE(p, previous) << fa;
        previous = p;
        EXPECT_NEAR
        (
            rockNRollRate(7.3e-9*fa, 7.3e-9*mean, 7.3e-9*rms, omega), p,
            1e-12*p
        );
    }
}


TEST(Resuspension, ReeksHallFlowModel)
{
    const double nu = 1.5e-5;
    for (const double ustar : {0.1, 0.7, 2.0})
    {
        EXPECT_NEAR
        (
            reeksHallFrequency(ustar, nu)*nu/(2*pi*ustar*ustar), 0.00658,
            1e-15
        );
        for (const double r : {5e-6, 10e-6})
        {
            const double rho = 1.2, rPlus = r*ustar/nu;
            const double printed =
                10.45*(1 + 300*std::pow(rPlus, -0.31))*std::pow(rPlus, 2.31)
               *rho*nu*nu;
            EXPECT_NEAR
            (
                biasiMeanAerodynamicForce(r, ustar, rho, nu), printed,
                1e-13*printed
            );
        }
    }
    EXPECT_EQ(reeksHallFrequency(0, nu), 0);
    EXPECT_DOUBLE_EQ(reeksHallRmsRatio, 0.2);
}


TEST(Resuspension, FractionRemaining)
{
    EXPECT_EQ(fractionRemaining(0, 5), 1);
    EXPECT_EQ(fractionRemaining(3, 0), 1);
    EXPECT_NEAR(fractionRemaining(2, 0.5), std::exp(-1.0), 1e-16);

    const LogNormalAdhesion d{0.0105, 3.1};
    const double jkr = 1.3e-5;
    const RockNRollForcing forcing{2e-7, 0.4e-7, 2*pi*300};

    // Nothing leaves at t = 0: the quadrature's total mass is 1
    EXPECT_NEAR(populationFractionRemaining(d, jkr, forcing, 0), 1, 1e-9);
    EXPECT_NEAR
    (
        populationFractionRemaining(d, jkr, forcing, 0, 1e-13), 1, 1e-13
    );

    // A narrow distribution: a single particle's exp(-p t)
    const LogNormalAdhesion narrow{0.0105, 1 + 1e-9};
    const double p =
        rockNRollRate(0.0105*jkr, forcing.meanForce, forcing.rmsForce,
            forcing.omega);
    EXPECT_NEAR
    (
        populationFractionRemaining(narrow, jkr, forcing, 0.003),
        std::exp(-p*0.003), 1e-8
    );

    // Against a trapezoid sum over z (spectrally accurate for this smooth
    // integrand on a fine grid) and against Monte Carlo over the quantile
    for (const double t : {1e-3, 1.0, 1e3})
    {
        const double zMax = 9;
        const int n = 400000;
        const double h = 2*zMax/n;
        long double sum = 0;
        for (int i = 0; i <= n; ++i)
        {
            const double z = -zMax + i*h;
            const double fa = jkr*d.geometricMean*std::pow(d.geometricSpread, z);
            const double rate = rockNRollRate
            (
                fa, forcing.meanForce, forcing.rmsForce, forcing.omega
            );
            sum += (i == 0 || i == n ? 0.5L : 1.0L)
                *std::exp(-0.5*z*z)/std::sqrt(2*pi)*std::exp(-rate*t);
        }
        const double reference = double(sum*h);
        const double code = populationFractionRemaining(d, jkr, forcing, t);
        EXPECT_NEAR(code, reference, 2e-9) << t;

        std::mt19937_64 engine(20011175 + int(t*1e3));
        std::uniform_real_distribution<double> uniform(0, 1);
        const int draws = 200000;
        double stay = 0;
        for (int i = 0; i < draws; ++i)
        {
            double u = uniform(engine);
            while (u == 0) u = uniform(engine);
            const double rate = rockNRollRate
            (
                jkr*d.quantile(u), forcing.meanForce, forcing.rmsForce,
                forcing.omega
            );
            stay += std::exp(-rate*t);
        }
        stay /= draws;
        // exp(-p t) is in [0, 1]: its standard deviation is at most 1/2
        EXPECT_NEAR(stay, code, 4*0.5/std::sqrt(double(draws))) << t;
    }

    // Decreasing in time
    double previous = 1;
    for (const double t : {1e-4, 1e-2, 1.0, 1e2, 1e4})
    {
        const double f = populationFractionRemaining(d, jkr, forcing, t);
        EXPECT_LT(f, previous) << t;
        previous = f;
    }
}


TEST(Resuspension, BadInput)
{
    EXPECT_TRUE(throwsInputError([] { jkrPullOffForce(0, 1e-6); }, "w", "0"));
    EXPECT_TRUE(throwsInputError([] { jkrPullOffForce(0.5, -1); }, "r", "-1"));
    EXPECT_TRUE(throwsInputError
    (
        [] { jkrContactRadius(0.5, 1e-6, 0); }, "contactModulus", "0"
    ));
    EXPECT_TRUE(throwsInputError([] { wallShearDrag(-1, 1e-6); }, "tauW", "-1"));
    EXPECT_TRUE(throwsInputError
    (
        [] { wallShearTorque(std::nan(""), 1e-6); }, "tauW", "nan"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { rollingMomentRatio(1, 1e-6, 0, 1e-7); }, "adhesionForce", "0"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { criticalWallShearStress(1e-6, 1e-6, 0); }, "contactRadius", "0"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { criticalFrictionVelocity(1e-6, 1e-6, 1e-7, 0); }, "rho", "0"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { criticalFrictionVelocityJkr(1e-6, 0.5, 1e11, 1, 0); },
        "reducedAdhesion", "0"
    ));
    EXPECT_TRUE(throwsInputError([] { standardNormalQuantile(0); }, "u", "0"));
    EXPECT_TRUE(throwsInputError([] { standardNormalQuantile(1); }, "u", "1"));
    EXPECT_TRUE(throwsInputError
    (
        [] { LogNormalAdhesion{0.01, 1}.quantile(0.5); }, "geometricSpread", "1"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { LogNormalAdhesion{-0.01, 3}.pdf(0.5); }, "geometricMean", "-0.01"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [] { rockNRollRate(-1, 1, 0.2, 1); }, "adhesionForce", "-1"
    ));
    EXPECT_TRUE(throwsInputError([] { rockNRollRate(1, 1, 0, 1); }, "rmsForce", "0"));
    EXPECT_TRUE(throwsInputError([] { rockNRollRate(1, 1, 0.2, 0); }, "omega", "0"));
    EXPECT_TRUE(throwsInputError([] { reeksHallFrequency(1, 0); }, "nu", "0"));
    EXPECT_TRUE(throwsInputError
    (
        [] { biasiMeanAerodynamicForce(5e-6, 0, 1, 1e-5); }, "ustar", "0"
    ));
    EXPECT_TRUE(throwsInputError([] { fractionRemaining(-1, 1); }, "rate", "-1"));
    EXPECT_TRUE(throwsInputError
    (
        []
        {
            populationFractionRemaining
            (
                {0.01, 3}, 1e-5, {1e-7, 2e-8, 100}, 1, 0
            );
        },
        "tolerance", "0"
    ));
    EXPECT_TRUE(throwsInputError
    (
        []
        {
            populationFractionRemaining({0.01, 3}, 0, {1e-7, 2e-8, 100}, 1);
        },
        "jkrForce", "0"
    ));
}
