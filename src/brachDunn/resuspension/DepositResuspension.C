// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "DepositResuspension.H"
#include "InputError.H"

#include <cmath>
#include <sstream>

namespace brachDunn
{

void DepositResuspension::check() const
{
    requirePositive("w", w);
    if (kind == Kind::rollingBalance)
    {
        requirePositive("contactModulus", contactModulus);
    }
    requirePositive("rmsRatio", rmsRatio);
    requirePositive("frequencyPlus", frequencyPlus);
    if (spread == Spread::logNormal)
    {
        logNormal.check();
    }
}


double DepositResuspension::reducedAdhesion(double r, double u) const
{
    switch (spread)
    {
        case Spread::none: return 1;
        case Spread::logNormal: return logNormal.quantile(u);
        default: return biasiAdhesion(r).quantile(u);
    }
}


double DepositResuspension::leavingProbability
(
    double r,
    double reducedAdhesion,
    double tauW,
    double rho,
    double nu,
    double dt
) const
{
    requirePositive("r", r);
    requirePositive("reducedAdhesion", reducedAdhesion);
    requirePositive("rho", rho);
    requirePositive("nu", nu);
    requireNonNegative("tauW", tauW);
    requireNonNegative("dt", dt);
    if (tauW == 0)
    {
        return 0;
    }
    const double adhesionForce = reducedAdhesion*jkrPullOffForce(w, r);
    if (kind == Kind::rollingBalance)
    {
        const double a0 = jkrContactRadius(w, r, contactModulus);
        return rollingMomentRatio(tauW, r, adhesionForce, a0) >= 1 ? 1 : 0;
    }
    const double ustar = std::sqrt(tauW/rho);
    const double meanForce = biasiMeanAerodynamicForce(r, ustar, rho, nu);
    const double rate = rockNRollRate
    (
        adhesionForce, meanForce, rmsRatio*meanForce,
        reeksHallFrequency(ustar, nu, frequencyPlus)
    );
    return -std::expm1(-rate*dt);
}


std::string DepositResuspension::describe() const
{
    std::ostringstream os;
    os  << (kind == Kind::rollingBalance ? "rollingBalance" : "rockNRoll")
        << " w " << w << " J/m^2";
    switch (spread)
    {
        case Spread::none: os << " adhesionSpread none"; break;
        case Spread::logNormal:
            os  << " adhesionSpread logNormal (geometricMean "
                << logNormal.geometricMean << " geometricSpread "
                << logNormal.geometricSpread << ")";
            break;
        default: os << " adhesionSpread biasi";
    }
    if (kind == Kind::rollingBalance)
    {
        os << " contactModulus " << contactModulus << " Pa";
    }
    else
    {
        os << " rmsRatio " << rmsRatio << " frequencyPlus " << frequencyPlus;
    }
    return os.str();
}

} // End namespace brachDunn
