// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Critical (capture) speeds of the paper's Figure 5 (NH4-fluorescein on
// molybdenum, normal impact, Eq. 23 for R, Eq. 24 for gamma), against the
// values recomputed in doc/model-notes.md and the paper's text
// (3.14-0.70 m/s, R(v_c) from 0.952 to 0.983, log-log slope about -1.53).

#include "testCases.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

const double diameters[] = {2.58e-6, 3.44e-6, 4.90e-6, 6.89e-6};

//- Eq. 26 in closed form for a fixed R: v_c = [H (1 + eta^2)/(r R^2)]^(10/7),
//  H = 0.51 [5 pi^2 (k1 + k2)/(4 rho^(3/2))]^(2/5), written out here from the
//  paper independently of the core
double eq26(double d, double R, double eta)
{
    const double pi = 3.14159265358979323846;
    const double k1 = (1 - 0.33*0.33)/(pi*1.2e9);
    const double k2 = (1 - 0.30*0.30)/(pi*3.2e11);
    const double H =
        0.51*std::pow(5*pi*pi*(k1 + k2)/(4*std::pow(1350.0, 1.5)), 0.4);
    return std::pow(H*(1 + eta*eta)/(0.5*d*R*R), 10.0/7);
}

} // End anonymous namespace


TEST(Figure5, IteratedRestitutionBothMethods)
{
    const TrapFloatingPointErrors trap;
    const double expected[] = {3.141, 2.005, 1.171, 0.705};
    const ImpactModel model = paperModel();

    for (int i = 0; i < 4; ++i)
    {
        const Particle p = fluoresceinSphere(diameters[i]);
        for (CriticalMethod method
             : {CriticalMethod::consistent, CriticalMethod::paper})
        {
            const CriticalSpeed c = model.criticalSpeed(p, 0, method);
            ASSERT_EQ(c.status, CriticalSpeed::Status::found);
            EXPECT_NEAR(c.speed/expected[i], 1, 1e-3) << "d = " << diameters[i];
            EXPECT_DOUBLE_EQ(c.normalSpeed, c.speed);
        }
    }
}


TEST(Figure5, RestitutionAtCriticalSpeed)
{
    const ImpactModel model = paperModel();
    const double Rsmall =
        model.criticalSpeed(fluoresceinSphere(diameters[0])).R;
    const double Rlarge =
        model.criticalSpeed(fluoresceinSphere(diameters[3])).R;
    EXPECT_NEAR(Rsmall, 0.952, 5e-4);
    EXPECT_NEAR(Rlarge, 0.983, 5e-4);
}


TEST(Figure5, LogLogSlope)
{
    const ImpactModel model = paperModel();
    const double v0 = model.criticalSpeed(fluoresceinSphere(diameters[0])).speed;
    const double v3 = model.criticalSpeed(fluoresceinSphere(diameters[3])).speed;
    const double slope =
        std::log(v3/v0)/std::log(diameters[3]/diameters[0]);
    EXPECT_NEAR(slope, -1.52, 0.01);
}


TEST(Figure5, FixedRestitutionBounds)
{
    const double expectedR1[] = {2.730, 1.810, 1.092, 0.671};
    const double expectedR09[] = {3.690, 2.446, 1.476, 0.907};

    for (int i = 0; i < 4; ++i)
    {
        const Particle p = fluoresceinSphere(diameters[i]);
        const double vR1 = paperModel(RestitutionLaw::constant(1))
            .criticalSpeed(p).speed;
        const double vR09 = paperModel(RestitutionLaw::constant(0.9))
            .criticalSpeed(p).speed;
        EXPECT_NEAR(vR1/expectedR1[i], 1, 1e-3);
        EXPECT_NEAR(vR09/expectedR09[i], 1, 1e-3);
        EXPECT_NEAR(vR1/eq26(diameters[i], 1, 0), 1, 2e-3);
        EXPECT_NEAR(vR09/eq26(diameters[i], 0.9, 0), 1, 2e-3);

        // The iterated-R solution lies between the bounds
        const double v = paperModel().criticalSpeed(p).speed;
        EXPECT_GT(v, vR1);
        EXPECT_LT(v, vR09);
    }
}


TEST(Figure5, ObliqueMethodsDiffer)
{
    // With fixed R the paper's form is Eq. 26 itself and exceeds the
    // consistent critical speed by (1 + eta^2)^(13/14)
    const ImpactModel model = paperModel(RestitutionLaw::constant(0.95));
    for (double eta : {0.5, 1.0, 3.0})
    {
        for (double d : diameters)
        {
            const Particle p = fluoresceinSphere(d);
            const CriticalSpeed consistent = model.criticalSpeed(p, eta);
            const CriticalSpeed paper =
                model.criticalSpeed(p, eta, CriticalMethod::paper);
            EXPECT_NEAR(paper.speed/eq26(d, 0.95, eta), 1, 2e-3);
            EXPECT_NEAR
            (
                paper.speed/consistent.speed,
                std::pow(1 + eta*eta, 13.0/14),
                1e-9*paper.speed/consistent.speed
            );
            // Consistent: the normal part of the critical speed is the
            // normal critical speed
            EXPECT_NEAR
            (
                consistent.normalSpeed,
                model.criticalSpeed(p).normalSpeed,
                1e-12*consistent.normalSpeed
            );
        }
    }
}


TEST(Figure5, CaptureBelowReboundAbove)
{
    const ImpactModel model = paperModel();
    for (double d : diameters)
    {
        const Particle p = fluoresceinSphere(d);
        const double vc = model.criticalSpeed(p).normalSpeed;
        EXPECT_TRUE(model.impact(p, 0.999*vc, 0).captured());
        EXPECT_FALSE(model.impact(p, 1.001*vc, 0).captured());
    }
}


TEST(Figure5, NoAdhesionNeverCaptures)
{
    const CriticalSpeed c = paperModel(paperRestitution(), AdhesionLaw::none())
        .criticalSpeed(fluoresceinSphere(1e-6));
    EXPECT_EQ(c.status, CriticalSpeed::Status::neverCaptured);
    EXPECT_EQ(c.speed, 0);
}


TEST(Figure5, NoRestitutionAlwaysCaptures)
{
    const CriticalSpeed c = paperModel(RestitutionLaw::constant(0))
        .criticalSpeed(fluoresceinSphere(1e-6));
    EXPECT_EQ(c.status, CriticalSpeed::Status::alwaysCaptured);
    EXPECT_TRUE(std::isfinite(c.speed));
}
