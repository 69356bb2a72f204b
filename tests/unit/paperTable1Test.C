// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The paper's Table 1 impact (4.90 um NH4-fluorescein on molybdenum,
// v_n = 8.23 m/s, measured V_n = 6.50 m/s), against the values recomputed
// independently in doc/model-notes.md, to 3 significant figures.

#include "ContactForces.H"
#include "testCases.H"

#include <gtest/gtest.h>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

constexpr double vn = 8.23;
constexpr double Vn = 6.50;
const Particle sphere = fluoresceinSphere(4.90e-6);

//- |actual/expected - 1| under half a unit of the third significant figure
void expectThreeFigures(double actual, double expected)
{
    EXPECT_NEAR(actual/expected, 1, 5e-3)
        << "actual " << actual << ", expected " << expected;
}

} // End anonymous namespace


TEST(PaperTable1, Mass)
{
    expectThreeFigures(sphere.mass(), 8.316e-14);
}


TEST(PaperTable1, HertzContact)
{
    const HertzContact h = paperModel().hertz(sphere, vn);
    expectThreeFigures(h.contactRadius, 4.728e-7);
    expectThreeFigures(h.approach, 9.124e-8);
    expectThreeFigures(h.maxForce, 7.717e-5);
    expectThreeFigures(h.duration, 3.260e-8);
}


TEST(PaperTable1, RestitutionEq23)
{
    const ImpactResult res = paperModel().impact(sphere, vn, 0);
    expectThreeFigures(res.R, 0.9089);
}


TEST(PaperTable1, AdhesionFromMeasuredRebound)
{
    const ImpactModel model = paperModel();
    const AdhesionLaw::Work work = model.measuredAdhesion(sphere, vn, Vn);
    expectThreeFigures(work.WA, -5.697e-13);
    expectThreeFigures(work.gamma, 0.811);

    const HertzContact h = model.hertz(sphere, vn);
    expectThreeFigures
    (
        adhesionFractureForce(work.WA, sphere.radius(), h.contactRadius),
        9.365e-6
    );
}


TEST(PaperTable1, Energies)
{
    const double m = sphere.mass();
    expectThreeFigures(0.5*m*vn*vn, 2.816e-12);
    expectThreeFigures(0.5*m*Vn*Vn, 1.757e-12);

    // A model with the gamma recovered from this very point must give back
    // the measured rebound and the deformation loss of Table 1
    const ImpactModel fitted = paperModel
    (
        paperRestitution(),
        AdhesionLaw::constant(paperModel().measuredAdhesion(sphere, vn, Vn).gamma)
    );
    const ImpactResult res = fitted.impact(sphere, vn, 0);
    EXPECT_NEAR(res.unOut, Vn, 1e-9);
    expectThreeFigures(res.deformationLoss, 4.899e-13);
    expectThreeFigures(res.adhesionLoss, 5.697e-13);
}


TEST(PaperTable1, VanDerWaalsEnergyEq34)
{
    // h = 4.56 eV, z = 4 A; Eq. 34 gives 6.18e-12 J (the paper's 1.64e-12
    // cannot be reproduced from Eq. 34; see doc/model-notes.md)
    const HertzContact h = paperModel().hertz(sphere, vn);
    ForceReviewInputs in;
    in.h = 4.56*1.602176634e-19;
    in.z = 4e-10;
    const ContactForces f = contactForces(sphere, h.contactRadius, in);
    expectThreeFigures(f.vanDerWaalsEnergy, 6.18e-12);

    // The same energy through the vanDerWaals adhesion law with f = 1
    const ImpactModel vdw = paperModel
    (
        paperRestitution(), AdhesionLaw::vanDerWaals(in.h, in.z, 1)
    );
    expectThreeFigures(-vdw.impact(sphere, vn, 0).WA, 6.18e-12);
}


TEST(PaperTable1, ForceReviewOrdering)
{
    // The paper's conclusion for h = 1 eV, z = 4 A, Phi = 0.5 V: van der
    // Waals dominates, the capillary force is at least an order below, the
    // electrostatic and gravitational forces several orders below
    const HertzContact h = paperModel().hertz(sphere, vn);
    ForceReviewInputs in;
    in.h = 1.602176634e-19;
    const ContactForces f = contactForces(sphere, h.contactRadius, in);
    EXPECT_LT(f.capillary, f.vanDerWaals/10);
    EXPECT_LT(f.contactPotential, f.vanDerWaals/10);
    EXPECT_LT(f.image, f.vanDerWaals/1e3);
    EXPECT_LT(f.gravity, f.vanDerWaals/1e3);
    EXPECT_DOUBLE_EQ
    (
        f.total,
        f.vanDerWaals + f.capillary + f.gravity + f.image + f.contactPotential
    );
    // Boltzmann charge of a 4.9 um sphere: about 5 elementary charges
    EXPECT_NEAR(f.charge/1.602176634e-19, 2.37*std::sqrt(4.9), 0.1);

    // A given charge is used as given, of either sign; the image force,
    // q^2/(16 pi eps_r eps_0 r^2), does not depend on the sign
    in.charge = -10*1.602176634e-19;
    const ContactForces negative = contactForces(sphere, h.contactRadius, in);
    EXPECT_EQ(negative.charge, -10*1.602176634e-19);
    const double r = sphere.radius();
    EXPECT_NEAR
    (
        negative.image,
        std::pow(10*1.602176634e-19, 2)
       /(16*pi*in.relativePermittivity*8.8541878128e-12*r*r),
        1e-12*negative.image
    );
}


TEST(PaperTable1, CapillaryForceEq30)
{
    // Eq. 30 (after Hinds): F_cap = [3.75e-6 + 3.38e-8 %RH] r, r in m
    const HertzContact h = paperModel().hertz(sphere, vn);
    const double r = sphere.radius();
    for (const double humidity : {0.0, 50.0, 100.0})
    {
        ForceReviewInputs in;
        in.relativeHumidity = humidity;
        const ContactForces f = contactForces(sphere, h.contactRadius, in);
        EXPECT_NEAR
        (
            f.capillary, (3.75e-6 + 3.38e-8*humidity)*r, 1e-15*f.capillary
        ) << "RH " << humidity << " %";
    }
}
