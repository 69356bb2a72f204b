// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SlipCorrection.H"
#include "InputError.H"
#include "Materials.H"

#include <cmath>

namespace brachDunn
{

SlipCoefficients slipCoefficients(const std::string& name)
{
    if (name == "Davies")
    {
        return daviesSlip;
    }
    if (name == "AllenRaabe")
    {
        return allenRaabeSlip;
    }
    throw InputError
    (
        "slipCoefficients", name, "must be Davies or AllenRaabe"
    );
}


double meanFreePath(double mu, double p, double T, double molarMass)
{
    requirePositive("mu", mu);
    requirePositive("p", p);
    requirePositive("T", T);
    requirePositive("molarMass", molarMass);

    // sqrt(rho p) = p sqrt(M/(R T)): rho p itself would overflow (or
    // underflow) long before lambda does
    return
        std::sqrt(pi/8)/0.4987445*(mu/p)
       *std::sqrt(gasConstant*T/molarMass);
}


double cunningham(double d, double lambda, const SlipCoefficients& c)
{
    requirePositive("d", d);
    requireNonNegative("lambda", lambda);
    const double Kn = 2*lambda/d;

    // exp(-A3/Kn) is below 1e-300 of A1 when A3/Kn > 700: zero then,
    // without dividing by a Kn of 0 (a trapped floating-point exception in
    // OpenFOAM; lambda = 0 is the continuum limit, Cc = 1)
    const double transition = Kn*700 > c.A3 ? std::exp(-c.A3/Kn) : 0;
    return 1 + Kn*(c.A1 + c.A2*transition);
}


double stokesEinstein(double d, double T, double mu, double Cc)
{
    requirePositive("d", d);
    requirePositive("T", T);
    requirePositive("mu", mu);
    requirePositive("Cc", Cc);
    return boltzmann*T*Cc/(3*pi*mu*d);
}


double relaxationTime(double rho, double d, double mu, double Cc)
{
    requirePositive("rho", rho);
    requirePositive("d", d);
    requirePositive("mu", mu);
    requirePositive("Cc", Cc);
    return rho*d*d*Cc/(18*mu);
}

} // End namespace brachDunn
