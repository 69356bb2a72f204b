// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// What the flow does to one deposit in one step (DepositResuspension): the
// rolling threshold against the moment balance written out here, the
// rock'n'roll probability at the mean force (p = omega/pi, an identity of
// the rate) and far above it, the spreads' medians against their own
// formulas, and bad input.

#include "DepositResuspension.H"
#include "inputErrorAssertions.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace brachDunn;
using brachDunn::testCases::throwsInputError;

namespace
{

constexpr double pi = 3.14159265358979323846;

//- Alumina on stainless steel, E* from the handbook values (370 GPa,
//  0.22; 193 GPa, 0.30), written out: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
const double contactModulus =
    1/((1 - 0.22*0.22)/3.7e11 + (1 - 0.30*0.30)/1.93e11);

//- The wall shear stress at which the rolling moment of the shear flow
//  about the contact edge equals the adhesion's (O'Neill's drag 1.7009,
//  Goldman, Cox & Brenner's torque 0.944, JKR's pull-off force and
//  zero-load contact radius), from the formulas, not the library
double rollingThreshold(double w, double r, double fPrime)
{
    const double K = 4.0/3.0*contactModulus;
    const double a0 = std::cbrt(6*pi*w*r*r/K);
    const double adhesionMoment = fPrime*1.5*pi*w*r*a0;
    const double loadPerTau = 1.7009*6*pi*r*r*r + 0.944*4*pi*r*r*r;
    return adhesionMoment/loadPerTau;
}

DepositResuspension rolling(double w)
{
    DepositResuspension model;
    model.kind = DepositResuspension::Kind::rollingBalance;
    model.w = w;
    model.spread = DepositResuspension::Spread::none;
    model.contactModulus = contactModulus;
    return model;
}

} // End anonymous namespace


TEST(DepositResuspension, RollingBalanceLeavesAtTheThreshold)
{
    for (const double r : {0.5e-6, 5e-6, 10e-6})
    {
        for (const double fPrime : {1.0, 0.01})
        {
            DepositResuspension model = rolling(0.56);
            model.spread = DepositResuspension::Spread::logNormal;
            model.logNormal = {fPrime, 1.0000001};
            const double f = model.reducedAdhesion(r, 0.5);
            EXPECT_NEAR(f, fPrime, 1e-12*fPrime);
            const double tauC = rollingThreshold(0.56, r, f);
            EXPECT_EQ(model.leavingProbability(r, f, 0.999*tauC, 1.2, 1.5e-5, 0.1), 0);
            EXPECT_EQ(model.leavingProbability(r, f, 1.001*tauC, 1.2, 1.5e-5, 0.1), 1);
        }
    }
}


TEST(DepositResuspension, RockNRollAtTheMeanForce)
{
    // With the adhesion equal to the mean aerodynamic force, x = 0 and
    // p = omega/pi = 2 0.00658 u*^2/nu: the chance over dt is 1 - e^-p dt
    const double r = 5e-6, rho = 1.2, nu = 1.5e-5;
    for (const double ustar : {0.3, 1.0, 2.5})
    {
        const double rPlus = r*ustar/nu;
        const double meanForce =
            10.45*(1 + 300*std::pow(rPlus, -0.31))*std::pow(rPlus, 2.31)
           *rho*nu*nu;
        DepositResuspension model;
        model.w = meanForce/(1.5*pi*r);
        model.spread = DepositResuspension::Spread::none;
        const double p = 2*0.00658*ustar*ustar/nu;
        for (const double dt : {1e-4, 1e-2, 1.0})
        {
            const double expected = 1 - std::exp(-p*dt);
            EXPECT_NEAR
            (
                model.leavingProbability(r, 1, rho*ustar*ustar, rho, nu, dt),
                expected, 1e-12*expected
            ) << "u* " << ustar << " dt " << dt;
        }
        // Far above the mean, the Gaussian tail: p (omega/2 pi)^-1 = e^-x^2
        // to erfc(x)/(1 + erf x)
        const double x = 4;
        DepositResuspension strong = model;
        strong.w = meanForce*(1 + x*std::sqrt(2.0)*0.2)/(1.5*pi*r);
        const double tail = p/2*std::exp(-x*x);
        const double dt = 1e-3;
        EXPECT_NEAR
        (
            strong.leavingProbability(r, 1, rho*ustar*ustar, rho, nu, dt),
            -std::expm1(-tail*dt), 1e-7*tail*dt
        );
    }
}


TEST(DepositResuspension, NoFlowNoResuspension)
{
    DepositResuspension model;
    model.w = 0.56;
    EXPECT_EQ(model.leavingProbability(5e-6, 0.01, 0, 1.2, 1.5e-5, 1), 0);
    EXPECT_EQ(rolling(0.56).leavingProbability(5e-6, 0.01, 0, 1.2, 1.5e-5, 1), 0);
}


TEST(DepositResuspension, SpreadMedians)
{
    DepositResuspension model;
    model.w = 0.56;
    model.spread = DepositResuspension::Spread::none;
    EXPECT_EQ(model.reducedAdhesion(5e-6, 0.01), 1);
    model.spread = DepositResuspension::Spread::logNormal;
    model.logNormal = {0.02, 3};
    EXPECT_NEAR(model.reducedAdhesion(5e-6, 0.5), 0.02, 1e-15);
    // One geometric spread above the median at Phi(1) = 0.841344746068543
    EXPECT_NEAR(model.reducedAdhesion(5e-6, 0.841344746068543), 0.06, 1e-10);
    // Biasi et al.'s fit at r = 5 um: fbar = 0.016 - 0.0023 5^0.545
    model.spread = DepositResuspension::Spread::biasi;
    EXPECT_NEAR
    (
        model.reducedAdhesion(5e-6, 0.5), 0.016 - 0.0023*std::pow(5.0, 0.545),
        1e-14
    );
}


TEST(DepositResuspension, BadInput)
{
    DepositResuspension model;
    EXPECT_TRUE(throwsInputError([&] { model.check(); }, "w", "0"));
    model.w = 0.56;
    model.check();
    model.rmsRatio = -1;
    EXPECT_TRUE(throwsInputError([&] { model.check(); }, "rmsRatio", "-1"));
    model.rmsRatio = 0.2;
    model.kind = DepositResuspension::Kind::rollingBalance;
    EXPECT_TRUE(throwsInputError([&] { model.check(); }, "contactModulus", "0"));
    model.kind = DepositResuspension::Kind::rockNRoll;
    model.spread = DepositResuspension::Spread::logNormal;
    model.logNormal = {0.01, 1};
    EXPECT_TRUE(throwsInputError([&] { model.check(); }, "geometricSpread", "1"));
    model.spread = DepositResuspension::Spread::none;
    EXPECT_TRUE(throwsInputError
    (
        [&] { model.leavingProbability(5e-6, 1, -1, 1.2, 1.5e-5, 1); },
        "tauW", "-1"
    ));
    EXPECT_TRUE(throwsInputError
    (
        [&] { model.leavingProbability(5e-6, 1, 1, 1.2, 1.5e-5, -0.5); },
        "dt", "-0.5"
    ));
}


TEST(DepositResuspension, DescribedWithUnits)
{
    // The log's line of an entry's resuspension names the units
    DepositResuspension rolling;
    rolling.kind = DepositResuspension::Kind::rollingBalance;
    rolling.w = 0.5;
    rolling.contactModulus = 2e10;
    rolling.spread = DepositResuspension::Spread::none;
    EXPECT_EQ(rolling.describe(),
              "rollingBalance w 0.5 J/m^2 adhesionSpread none contactModulus 2e+10 Pa");
}
