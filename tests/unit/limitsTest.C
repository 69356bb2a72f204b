// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Limits the model must reach: elastic conservation, the continuous approach
// to capture, the classical rebound of OpenFOAM's standardWallInteraction,
// the friction regimes and the rebound floor.

#include "testCases.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

ImpactModel model
(
    const RestitutionLaw& restitution,
    const AdhesionLaw& adhesion,
    const FrictionLaw& friction,
    double minReboundSpeed = 0
)
{
    return ImpactModel
    (
        fluorescein, molybdenum, restitution, adhesion, friction,
        -1, minReboundSpeed
    );
}

const Particle sphere{4.9e-6, 1350};

} // End anonymous namespace


TEST(Limits, ElasticWithoutAdhesionConservesNormalEnergy)
{
    const ImpactModel m = model
    (
        RestitutionLaw::constant(1), AdhesionLaw::none(), FrictionLaw::coulomb(0)
    );
    for (double un : {1e-3, 0.1, 1.0, 37.0, 1e4})
    {
        const ImpactResult r = m.impact(sphere, un, 0.5*un);
        EXPECT_EQ(r.outcome, Fate::rebound);
        EXPECT_NEAR(r.unOut, un, 1e-15*un);
        EXPECT_EQ(r.utOut, 0.5*un);
        EXPECT_NEAR(r.energyLoss, 0, 1e-15*sphere.mass()*un*un);
    }
}


TEST(Limits, ReboundVanishesContinuouslyAtCaptureThreshold)
{
    // For constant gamma, capture starts where pi gamma a_m^2 = R^2 m un^2/2
    const double un = 2.0, R = 0.9;
    const double m = sphere.mass();
    const double a = model
    (
        RestitutionLaw::constant(R), AdhesionLaw::none(), FrictionLaw::sticking()
    ).hertz(sphere, un).contactRadius;
    const double gammaCapture = R*R*0.5*m*un*un/(3.14159265358979323846*a*a);

    double previous = R*un;
    for (double eps : {1e-1, 1e-2, 1e-4, 1e-6, 1e-8})
    {
        const ImpactResult r = model
        (
            RestitutionLaw::constant(R),
            AdhesionLaw::constant(gammaCapture*(1 - eps)),
            FrictionLaw::sticking()
        ).impact(sphere, un, 0);
        ASSERT_EQ(r.outcome, Fate::rebound) << "eps " << eps;
        // Un' = R un sqrt(eps) exactly for this gamma
        EXPECT_NEAR(r.unOut, R*un*std::sqrt(eps), 1e-6*R*un*std::sqrt(eps));
        EXPECT_LT(r.unOut, previous);
        previous = r.unOut;
    }

    const ImpactResult captured = model
    (
        RestitutionLaw::constant(R),
        AdhesionLaw::constant(gammaCapture*(1 + 1e-8)),
        FrictionLaw::sticking()
    ).impact(sphere, un, 0);
    EXPECT_TRUE(captured.captured());
    EXPECT_EQ(captured.cause, CaptureCause::adhesion);
    EXPECT_EQ(captured.unOut, 0);
}


TEST(Limits, ClassicalReboundEqualsStandardWallInteraction)
{
    // OpenFOAM's standardWallInteraction rebound with e and mu = 0, with nw
    // the outward wall normal: if (Un > 0) U -= (1 + e) Un nw, Un = U & nw
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10, 10);

    for (double e : {0.0, 0.3, 0.9, 1.0})
    {
        const ImpactModel m = model
        (
            RestitutionLaw::constant(e),
            AdhesionLaw::none(),
            FrictionLaw::coulomb(0)
        );
        for (int i = 0; i < 1000; ++i)
        {
            Vector3 nw{u(rng), u(rng), u(rng)};
            nw = (1/mag(nw))*nw;
            Vector3 U{u(rng), u(rng), u(rng)};

            const double Un = dot(U, nw);
            Vector3 expected = U;
            if (Un > 0) expected = U - ((1 + e)*Un)*nw;

            const Impact3D r = m.impact(sphere, U, -1*nw);
            if (e == 0 && Un > 0)
            {
                // R = 0 is a capture in this model; the tangential part of
                // the classical rebound remains there
                EXPECT_TRUE(r.result.captured());
                continue;
            }
            EXPECT_NEAR(r.U.x, expected.x, 1e-12*mag(U));
            EXPECT_NEAR(r.U.y, expected.y, 1e-12*mag(U));
            EXPECT_NEAR(r.U.z, expected.z, 1e-12*mag(U));
        }
    }
}


TEST(Limits, StickingStopsTangentialMotion)
{
    const ImpactModel m = model
    (
        RestitutionLaw::constant(0.9), AdhesionLaw::none(), FrictionLaw::sticking()
    );
    const ImpactResult r = m.impact(sphere, 3.0, 4.0);
    EXPECT_EQ(r.utOut, 0);
    EXPECT_NEAR(r.impulseRatio, (4.0/3.0)/(1 + 0.9), 1e-15);   // mu0, Eq. 16
    EXPECT_NEAR(r.frictionLoss, 0.5*sphere.mass()*16, 1e-15*sphere.mass()*16);
}


TEST(Limits, CoulombSlidesThroughoutOrStops)
{
    const double R = 0.9, un = 3.0, ut = 4.0;
    const double mu0 = (ut/un)/(1 + R);

    // mu_f < mu0: sliding throughout, Eq. 13 with mu = mu_f
    const double muSmall = 0.5*mu0;
    const ImpactResult sliding = model
    (
        RestitutionLaw::constant(R), AdhesionLaw::none(),
        FrictionLaw::coulomb(muSmall)
    ).impact(sphere, un, ut);
    EXPECT_NEAR(sliding.utOut, ut - muSmall*un*(1 + R), 1e-14);
    EXPECT_NEAR(sliding.impulseRatio, muSmall, 1e-15);

    // mu_f > mu0: the motion stops and mu = mu0
    const ImpactResult stopping = model
    (
        RestitutionLaw::constant(R), AdhesionLaw::none(),
        FrictionLaw::coulomb(2*mu0)
    ).impact(sphere, un, ut);
    EXPECT_EQ(stopping.utOut, 0);
    EXPECT_NEAR(stopping.impulseRatio, mu0, 1e-15);
}


TEST(Limits, ReboundFloorEndsRepeatedRebounds)
{
    // A particle bouncing on and on with R = 0.9 and no adhesion is captured
    // by the floor after log(floor/u0)/log(R) bounces, never loops forever
    const double floor = 1e-6;
    const ImpactModel m = model
    (
        RestitutionLaw::constant(0.9), AdhesionLaw::none(),
        FrictionLaw::sticking(), floor
    );
    double un = 1.0;
    int bounces = 0;
    ImpactResult r;
    do
    {
        r = m.impact(sphere, un, 0);
        un = r.unOut;
        ++bounces;
    } while (!r.captured() && bounces < 1000);

    EXPECT_TRUE(r.captured());
    EXPECT_EQ(r.cause, CaptureCause::reboundFloor);
    EXPECT_EQ(bounces, static_cast<int>(std::ceil(std::log(floor)/std::log(0.9))));
}


TEST(Limits, ExtremeSpeedsStayFinite)
{
    const TrapFloatingPointErrors trap;
    for (const AdhesionLaw& adhesion
         : {AdhesionLaw::none(), AdhesionLaw::powerLaw(0.34, 0.5)})
    {
        for (double floor : {0.0, 1e-6})
        {
            const ImpactModel m = model
            (
                RestitutionLaw::powerLaw(45.3, 0.718), adhesion,
                FrictionLaw::coulomb(0.2), floor
            );
            for (double un : {1e-300, 1e-12, 1e-6, 1e4})
            {
                for (double ut : {0.0, 1e-12, 1.0, 1e4})
                {
                    const ImpactResult r = m.impact(sphere, un, ut, 1e3);
                    for (double v : {r.unOut, r.utOut, r.spinOut, r.R, r.gamma,
                                     r.WA, r.impulseRatio, r.normalImpulse,
                                     r.tangentialImpulse, r.energyLoss})
                    {
                        EXPECT_TRUE(std::isfinite(v))
                            << "un " << un << " ut " << ut;
                    }
                    EXPECT_LE(std::hypot(r.unOut, r.utOut), std::hypot(un, ut));
                }
            }
        }
    }
}


TEST(Limits, CaptureReportsTheIncidentImpulseRatio)
{
    // A captured particle loses all its momentum to the wall: P_n = m un,
    // P_t = m ut, so the impulse ratio is ut/un whatever the laws
    const ImpactModel model = paperModel();
    const Particle sphere = fluoresceinSphere(4.9e-6);
    const double un = 0.2, ut = 0.15;
    const ImpactResult r = model.impact(sphere, un, ut);
    ASSERT_TRUE(r.captured());
    const double m = sphere.mass();
    EXPECT_NEAR(r.normalImpulse, m*un, 1e-15*m*un);
    EXPECT_NEAR(r.tangentialImpulse, m*ut, 1e-15*m*ut);
    EXPECT_NEAR(r.impulseRatio, ut/un, 1e-15);
}
