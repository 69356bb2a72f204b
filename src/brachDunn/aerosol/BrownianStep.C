// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "BrownianStep.H"
#include "InputError.H"

#include <cmath>

namespace brachDunn
{

namespace
{

//- The functions of h = dt/tau that the moments are made of: a = 1 - e^-h,
//  t = tanh(h/2) and phi = h - 2 tanh(h/2), each to rounding
struct StepFunctions
{
    double a, t, phi;
};


//- x - tanh(x), x >= 0. Below 1 it is (x cosh x - sinh x)/cosh x, and
//  x cosh x - sinh x = sum over k >= 1 of 2k x^(2k+1)/(2k+1)!: positive
//  terms, where x - tanh(x) itself would cancel (~x^3/3); above 1 the
//  difference loses at most two bits.
double xMinusTanh(double x)
{
    if (x >= 1)
    {
        return x - std::tanh(x);
    }
    const double xSqr = x*x;
    double power = x;   // x^(2k+1)/(2k+1)!
    double sum = 0;
    for (int k = 1; k <= 20; ++k)
    {
        power *= xSqr/((2*k)*(2*k + 1));
        const double term = 2*k*power;
        sum += term;
        if (term <= 1e-17*sum)
        {
            break;
        }
    }
    return sum/std::cosh(x);
}


StepFunctions stepFunctions(double h)
{
    return {-std::expm1(-h), std::tanh(h/2), 2*xMinusTanh(h/2)};
}

} // End anonymous namespace


BrownianTransition brownianTransition
(
    double dt,
    double tau,
    double thermalVariance
)
{
    requireNonNegative("dt", dt);
    requirePositive("tau", tau);
    requireNonNegative("thermalVariance", thermalVariance);

    const double h = dt/tau;
    const auto [a, t, phi] = stepFunctions(h);
    const double sigma = std::sqrt(thermalVariance);

    BrownianTransition step;
    step.velocityDecay = std::exp(-h);
    step.displacementPerVelocity = tau*a;

    step.velocityVariance = thermalVariance*a*(2 - a);
    step.covariance = thermalVariance*tau*a*a;
    step.displacementVariance = thermalVariance*tau*tau*(2*phi + a*a*t);

    // Cov/sqrt(Var v) = sigma tau a sqrt(t), as a^2/sqrt(a (2 - a)) =
    // a sqrt(a/(2 - a)): no 0/0 at dt = 0
    step.velocityScale = sigma*std::sqrt(a*(2 - a));
    step.correlatedScale = sigma*tau*a*std::sqrt(t);
    step.independentScale = sigma*tau*std::sqrt(2*phi);
    return step;
}


BrownianSample sampleBrownian
(
    const BrownianTransition& step,
    double v0,
    double z1,
    double z2
)
{
    return
    {
        step.displacementPerVelocity*v0
      + step.correlatedScale*z1 + step.independentScale*z2,
        step.velocityDecay*v0 + step.velocityScale*z1
    };
}


double brownianMsdThermalStart(double t, double tau, double D)
{
    requireNonNegative("t", t);
    requirePositive("tau", tau);
    requireNonNegative("D", D);

    // t/tau - 1 + e^-h = phi + a tanh(h/2): positive terms
    const StepFunctions f = stepFunctions(t/tau);
    return 2*D*tau*(f.phi + f.a*f.t);
}


double brownianMsdFromRest(double t, double tau, double D)
{
    requireNonNegative("t", t);
    requirePositive("tau", tau);
    requireNonNegative("D", D);

    // 2h - 3 + 4e^-h - e^-2h = 2 phi + a^2 tanh(h/2): positive terms
    const StepFunctions f = stepFunctions(t/tau);
    return D*tau*(2*f.phi + f.a*f.a*f.t);
}

} // End namespace brachDunn
