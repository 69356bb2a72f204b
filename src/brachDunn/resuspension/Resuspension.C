// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "Resuspension.H"
#include "InputError.H"
#include "Materials.H"

#include <cmath>

namespace brachDunn
{

namespace
{

constexpr double sqrt2 = 1.41421356237309504880;
constexpr double sqrtPi = 1.77245385090551602730;
constexpr double sqrt2Pi = 2.50662827463100050242;


//- exp(-y^2)/erfc(y) for y >= 20 (where both underflow long before their
//  ratio does), by Laplace's continued fraction
//  erfc(y) = exp(-y^2)/sqrt(pi) / (y + (1/2)/(y + (2/2)/(y + (3/2)/...))):
//  the ratio is sqrt(pi) times the denominator. Its error after 40 levels
//  is far below rounding for y >= 20.
double gaussianOverErfc(double y)
{
    double denominator = y;
    for (int k = 40; k >= 1; --k)
    {
        denominator = y + 0.5*k/denominator;
    }
    return sqrtPi*denominator;
}


//- The integral of f over [a, b] to the absolute tolerance, by adaptive
//  Simpson (Richardson-corrected); fa, fm, fb the values at a, (a+b)/2, b
//  and whole the Simpson sum over [a, b]
template<class Function>
double adaptiveSimpson
(
    const Function& f,
    double a,
    double b,
    double fa,
    double fm,
    double fb,
    double whole,
    double tolerance,
    int depth
)
{
    const double m = 0.5*(a + b);
    const double lm = 0.5*(a + m), rm = 0.5*(m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a)/6*(fa + 4*flm + fm);
    const double right = (b - m)/6*(fm + 4*frm + fb);
    const double difference = left + right - whole;
    // Stop also on a difference that is not a number: refining would not
    // make it one, and would cost 2^depth evaluations
    if (depth <= 0 || !(std::abs(difference) > 15*tolerance))
    {
        return left + right + difference/15;
    }
    return
        adaptiveSimpson(f, a, m, fa, flm, fm, left, tolerance/2, depth - 1)
      + adaptiveSimpson(f, m, b, fm, frm, fb, right, tolerance/2, depth - 1);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * JKR adhesion * * * * * * * * * * * * * * * //

double jkrPullOffForce(double w, double r)
{
    requirePositive("w", w);
    requirePositive("r", r);
    return 1.5*pi*w*r;
}


double jkrContactRadius(double w, double r, double contactModulus)
{
    requirePositive("w", w);
    requirePositive("r", r);
    requirePositive("contactModulus", contactModulus);
    const double K = 4.0/3*contactModulus;
    return std::cbrt(6*pi*w*r*r/K);
}


// * * * * * * * * * * * * * *  Shear-flow load  * * * * * * * * * * * * * //

double wallShearDrag(double tauW, double r)
{
    requireNonNegative("tauW", tauW);
    requirePositive("r", r);
    return oneillDragFactor*6*pi*tauW*r*r;
}


double wallShearTorque(double tauW, double r)
{
    requireNonNegative("tauW", tauW);
    requirePositive("r", r);
    return goldmanTorqueFactor*4*pi*tauW*r*r*r;
}


// * * * * * * * * * * * * * *  Rolling detachment  * * * * * * * * * * * * //

double rollingMomentRatio
(
    double tauW,
    double r,
    double adhesionForce,
    double contactRadius
)
{
    requireNonNegative("tauW", tauW);
    requirePositive("r", r);
    requirePositive("adhesionForce", adhesionForce);
    requirePositive("contactRadius", contactRadius);
    return
        (wallShearTorque(tauW, r) + wallShearDrag(tauW, r)*r)
       /(adhesionForce*contactRadius);
}


double criticalWallShearStress
(
    double r,
    double adhesionForce,
    double contactRadius
)
{
    requirePositive("r", r);
    requirePositive("adhesionForce", adhesionForce);
    requirePositive("contactRadius", contactRadius);
    return adhesionForce*contactRadius/(rollingLoadFactor*pi*r*r*r);
}


double criticalFrictionVelocity
(
    double r,
    double adhesionForce,
    double contactRadius,
    double rho
)
{
    requirePositive("rho", rho);
    return
        std::sqrt(criticalWallShearStress(r, adhesionForce, contactRadius)/rho);
}


double criticalFrictionVelocityJkr
(
    double r,
    double w,
    double contactModulus,
    double rho,
    double reducedAdhesion
)
{
    requirePositive("reducedAdhesion", reducedAdhesion);
    return criticalFrictionVelocity
    (
        r,
        reducedAdhesion*jkrPullOffForce(w, r),
        jkrContactRadius(w, r, contactModulus),
        rho
    );
}


// * * * * * * * * * * * *  Distribution of adhesion  * * * * * * * * * * * //

double standardNormalCdf(double z)
{
    return 0.5*std::erfc(-z/sqrt2);
}


double standardNormalQuantile(double u)
{
    if (!(std::isfinite(u) && u > 0 && u < 1))
    {
        failCheck("u", u, [] { return std::string("must be in (0, 1)"); });
    }

    // The lower half, q <= 1/2, and the upper one by symmetry: 1 - u is
    // exact for u >= 1/2
    const bool upper = u > 0.5;
    const double q = upper ? 1 - u : u;
    if (q == 0.5)
    {
        return 0;
    }

    // Start: Abramowitz & Stegun 26.2.23 (error below 4.5e-4)
    const double t = std::sqrt(-2*std::log(q));
    double z =
        -(
            t
          - (2.515517 + t*(0.802853 + t*0.010328))
           /(1 + t*(1.432788 + t*(0.189269 + t*0.001308)))
        );

    // Halley's iteration on Phi(z) = q (z <= 0: Phi by erfc of a positive
    // argument, no cancellation), cubic: three steps reach rounding
    for (int i = 0; i < 4; ++i)
    {
        const double density = std::exp(-0.5*z*z)/sqrt2Pi;
        const double step = (standardNormalCdf(z) - q)/density;
        z -= step/(1 + 0.5*z*step);
    }
    return upper ? -z : z;
}


void LogNormalAdhesion::check() const
{
    requirePositive("geometricMean", geometricMean);
    requireFinite("geometricSpread", geometricSpread);
    if (!(geometricSpread > 1))
    {
        failCheck("geometricSpread", geometricSpread, []
        {
            return std::string("must be > 1");
        });
    }
}


double LogNormalAdhesion::pdf(double f) const
{
    check();
    if (!(f > 0))
    {
        return 0;
    }
    const double s = std::log(geometricSpread);
    const double z = std::log(f/geometricMean)/s;
    return std::exp(-0.5*z*z)/(sqrt2Pi*f*s);
}


double LogNormalAdhesion::cdf(double f) const
{
    check();
    if (!(f > 0))
    {
        return 0;
    }
    return standardNormalCdf
    (
        std::log(f/geometricMean)/std::log(geometricSpread)
    );
}


double LogNormalAdhesion::quantile(double u) const
{
    check();
    return
        geometricMean
       *std::exp(std::log(geometricSpread)*standardNormalQuantile(u));
}


double LogNormalAdhesion::mean() const
{
    check();
    const double s = std::log(geometricSpread);
    return geometricMean*std::exp(0.5*s*s);
}


LogNormalAdhesion biasiAdhesion(double r)
{
    requirePositive("r", r);
    const double rMicron = 1e6*r;
    const LogNormalAdhesion fit
    {
        0.016 - 0.0023*std::pow(rMicron, 0.545),
        1.8 + 0.136*std::pow(rMicron, 1.4)
    };
    if (!(fit.geometricMean > 0))
    {
        throw InputError
        (
            "r", toText(r),
            "must be below 3.513e-5 m (a diameter of 70.26 um), where Biasi's"
            " fitted geometric mean reaches zero"
        );
    }
    return fit;
}


// * * * * * * * * * * * * * *  Rock'n'roll rate  * * * * * * * * * * * * * //

double rockNRollRate
(
    double fa,
    double meanForce,
    double rmsForce,
    double omega
)
{
    requireNonNegative("adhesionForce", fa);
    requireNonNegative("meanForce", meanForce);
    requirePositive("rmsForce", rmsForce);
    requirePositive("omega", omega);

    const double x = (fa - meanForce)/(sqrt2*rmsForce);
    if (x >= -20)
    {
        // Rice's up-crossing rate over the probability of being held,
        // (1 + erf x)/2 = erfc(-x)/2 (no cancellation for x < 0); for
        // large x the numerator underflows to a rate of 0, as it should
        return omega/(2*pi)*std::exp(-x*x)/(0.5*std::erfc(-x));
    }
    // Deep below the mean force: both underflow; their ratio does not
    return omega/(2*pi)*2*gaussianOverErfc(-x);
}


double reeksHallFrequency(double ustar, double nu, double frequencyPlus)
{
    requireNonNegative("ustar", ustar);
    requirePositive("nu", nu);
    requirePositive("frequencyPlus", frequencyPlus);
    return 2*pi*frequencyPlus*ustar*ustar/nu;
}


double biasiMeanAerodynamicForce
(
    double r,
    double ustar,
    double rho,
    double nu
)
{
    requirePositive("r", r);
    requirePositive("ustar", ustar);
    requirePositive("rho", rho);
    requirePositive("nu", nu);
    const double rPlus = r*ustar/nu;
    // 10.45 (1 + 300 r+^-0.31) r+^2.31 with the bracket multiplied out
    return 10.45*(std::pow(rPlus, 2.31) + 300*rPlus*rPlus)*rho*nu*nu;
}


double momentBalanceForce(double tauW, double r, double contactRadius)
{
    requireNonNegative("tauW", tauW);
    requirePositive("r", r);
    requirePositive("contactRadius", contactRadius);
    return rollingLoadFactor*pi*tauW*r*r*r/contactRadius;
}


// * * * * * * * * * * * * * *  Fraction remaining  * * * * * * * * * * * * //

double fractionRemaining(double rate, double t)
{
    requireNonNegative("rate", rate);
    requireNonNegative("t", t);
    return std::exp(-rate*t);
}


double populationFractionRemaining
(
    const LogNormalAdhesion& adhesion,
    double jkrForce,
    const RockNRollForcing& forcing,
    double t,
    double tolerance
)
{
    adhesion.check();
    requirePositive("jkrForce", jkrForce);
    requireNonNegative("meanForce", forcing.meanForce);
    requirePositive("rmsForce", forcing.rmsForce);
    requirePositive("omega", forcing.omega);
    requireNonNegative("t", t);
    requirePositive("tolerance", tolerance);

    const double logSpread = std::log(adhesion.geometricSpread);
    const auto integrand = [&](double z)
    {
        const double fa =
            jkrForce*adhesion.geometricMean*std::exp(logSpread*z);
        const double p = rockNRollRate
        (
            fa, forcing.meanForce, forcing.rmsForce, forcing.omega
        );
        return std::exp(-0.5*z*z)/sqrt2Pi*std::exp(-p*t);
    };

    // Panels first, so that no step of exp(-p t) hides between the first
    // samples of the adaptive rule
    constexpr double zMax = 8.3;
    constexpr int panels = 32;
    const double width = 2*zMax/panels;
    double sum = 0;
    for (int i = 0; i < panels; ++i)
    {
        const double a = -zMax + i*width, b = a + width;
        const double fa = integrand(a), fm = integrand(0.5*(a + b));
        const double fb = integrand(b);
        sum += adaptiveSimpson
        (
            integrand, a, b, fa, fm, fb, width/6*(fa + 4*fm + fb),
            tolerance/panels, 30
        );
    }
    return sum;
}

} // End namespace brachDunn
