// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Physical identities that hold for every law combination: the energy
// balance of Eq. 17, impulse-momentum, the sticking condition, and frame
// invariance of the 3D form.

#include "lawCombinations.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

class EveryLawCombination
:
    public ::testing::TestWithParam<LawCombination>
{
protected:

    ImpactModel model(double momentCoeff = -1) const
    {
        const LawCombination& laws = GetParam();
        return ImpactModel
        (
            fluorescein, molybdenum,
            laws.restitution, laws.adhesion, laws.friction,
            momentCoeff, 0
        );
    }
};


//- Random oblique impacts of micrometre spheres at 0.05-50 m/s
struct ImpactSampler
{
    std::mt19937_64 rng{12345};

    double uniform(double a, double b)
    {
        return std::uniform_real_distribution<double>(a, b)(rng);
    }

    double logUniform(double a, double b)
    {
        return std::exp(uniform(std::log(a), std::log(b)));
    }
};

} // End anonymous namespace


TEST_P(EveryLawCombination, EnergyIdentityEq17)
{
    const ImpactModel m = model();
    ImpactSampler s;
    int rebounds = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Particle p{s.logUniform(1e-6, 2e-5), 1350};
        const double v0 = s.logUniform(0.05, 50);
        const double alpha = s.uniform(0, 1.5);
        const double un = v0*std::cos(alpha), ut = v0*std::sin(alpha);
        const ImpactResult r = m.impact(p, un, ut);
        const double mass = p.mass();

        // Loss = initial minus final translational kinetic energy
        const double before = 0.5*mass*(un*un + ut*ut);
        const double after = 0.5*mass*(r.unOut*r.unOut + r.utOut*r.utOut);
        EXPECT_NEAR(r.energyLoss, before - after, 1e-12*before);
        // The parts: deformation (1 - R^2) m un^2/2, friction the tangential
        // energy lost; adhesion the rest, so they must add up to the loss
        EXPECT_NEAR
        (
            r.deformationLoss, 0.5*mass*un*un*(1 - r.R*r.R), 1e-12*before
        );
        EXPECT_NEAR
        (
            r.frictionLoss,
            0.5*mass*(ut*ut - r.utOut*r.utOut),
            1e-12*before
        );
        EXPECT_NEAR
        (
            r.deformationLoss + r.adhesionLoss + r.frictionLoss,
            before - after,
            1e-12*before
        );

        if (r.captured()) continue;
        ++rebounds;

        // Eq. 17: T_L = -W_A + (m un^2/2)[(1 - R^2) + eta^2 x (2 - x)],
        // x = mu/mu0, mu0 = eta/(1 + R S), R S = Un'/un
        const double eta = ut/un;
        const double mu0 = eta/(1 + r.unOut/un);
        const double x = r.impulseRatio/mu0;
        const double eq17 =
            -r.WA + 0.5*mass*un*un*((1 - r.R*r.R) + eta*eta*x*(2 - x));
        EXPECT_NEAR(r.energyLoss, eq17, 1e-10*before);

        // Eq. 12: Un' = R un sqrt(1 + 2 W_A/(R^2 m un^2))
        EXPECT_NEAR
        (
            r.unOut,
            r.R*un*std::sqrt(1 + 2*r.WA/(r.R*r.R*mass*un*un)),
            1e-12*un
        );

        // Impulse-momentum, Eqs. 3-4
        EXPECT_NEAR(r.normalImpulse, mass*(un + r.unOut), 1e-12*mass*v0);
        EXPECT_NEAR(r.tangentialImpulse, mass*(ut - r.utOut), 1e-12*mass*v0);
        EXPECT_LE(r.impulseRatio, mu0*(1 + 1e-12));
    }
    EXPECT_GT(rebounds, 0);
}


TEST_P(EveryLawCombination, FrameInvariance3D)
{
    // The same impact seen in two frames rotated against each other gives
    // the same speeds and the rotated velocities
    const ImpactModel m = model(-0.4);
    const Particle p{5e-6, 1350};
    ImpactSampler s;

    for (int i = 0; i < 200; ++i)
    {
        const Vector3 n{0, 0, 1};
        const Vector3 U{s.uniform(-5, 5), s.uniform(-5, 5), s.uniform(-20, -0.1)};
        const Vector3 w{s.uniform(-1e5, 1e5), s.uniform(-1e5, 1e5), 0};

        // Rotation by 0.7 rad about x then 0.3 rad about z
        const auto rotate = [](const Vector3& v)
        {
            const double c1 = std::cos(0.7), s1 = std::sin(0.7);
            const double c2 = std::cos(0.3), s2 = std::sin(0.3);
            const Vector3 a{v.x, c1*v.y - s1*v.z, s1*v.y + c1*v.z};
            return Vector3{c2*a.x - s2*a.y, s2*a.x + c2*a.y, a.z};
        };

        const Impact3D here = m.impact(p, U, n, w);
        const Impact3D there = m.impact(p, rotate(U), rotate(n), rotate(w));
        const Vector3 expected = rotate(here.U);
        const Vector3 expectedW = rotate(here.omega);
        const double scale = mag(U), scaleW = mag(w) + 1e6;

        EXPECT_NEAR(there.U.x, expected.x, 1e-12*scale);
        EXPECT_NEAR(there.U.y, expected.y, 1e-12*scale);
        EXPECT_NEAR(there.U.z, expected.z, 1e-12*scale);
        EXPECT_NEAR(there.omega.x, expectedW.x, 1e-9*scaleW);
        EXPECT_NEAR(there.omega.y, expectedW.y, 1e-9*scaleW);
        EXPECT_NEAR(there.omega.z, expectedW.z, 1e-9*scaleW);
        EXPECT_EQ(there.result.outcome, here.result.outcome);

        // The 3D result is the planar one in the incident plane
        if (here.result.outcome == Fate::rebound)
        {
            EXPECT_NEAR(here.U.z, here.result.unOut, 1e-12*scale);
            EXPECT_NEAR
            (
                std::hypot(here.U.x, here.U.y), here.result.utOut, 1e-12*scale
            );
        }
    }
}


TEST_P(EveryLawCombination, SpinFollowsMomentCoefficient)
{
    // Omega = -e_m (omega + r P_t/I) about n x t: e_m = 0 stops the spin,
    // e_m = -1 adds the friction spin-up r P_t/I = (5/2)(ut - Ut')/r
    const Particle p{1e-5, 1350};
    const double un = 20, ut = 10, spin = 3e4;

    const ImpactResult free = model(-1).impact(p, un, ut, spin);
    ASSERT_FALSE(free.captured());
    EXPECT_NEAR
    (
        free.spinOut,
        spin + 2.5*(ut - free.utOut)/p.radius(),
        1e-12*std::abs(free.spinOut)
    );
    EXPECT_EQ(model(0).impact(p, un, ut, spin).spinOut, 0);

    const ImpactResult half = model(0.5).impact(p, un, ut, spin);
    EXPECT_NEAR(half.spinOut, -0.5*free.spinOut, 1e-12*std::abs(free.spinOut));
}


TEST_P(EveryLawCombination, MovingAwayIsLeftAlone)
{
    const ImpactModel m = model();
    const Particle p{1e-5, 1350};
    for (double un : {0.0, -1e-12, -3.0})
    {
        const ImpactResult r = m.impact(p, un, 2.0, 5.0);
        EXPECT_EQ(r.outcome, Fate::notApproaching);
        EXPECT_EQ(r.unOut, -un);
        EXPECT_EQ(r.utOut, 2.0);
        EXPECT_EQ(r.spinOut, 5.0);
        EXPECT_EQ(r.energyLoss, 0);
    }
    const Vector3 U{1, 2, 3}, w{4, 5, 6};
    const Impact3D away = m.impact(p, U, Vector3{0, 0, 1}, w);
    EXPECT_EQ(away.U.x, 1);
    EXPECT_EQ(away.U.z, 3);
    EXPECT_EQ(away.omega.y, 5);
}


INSTANTIATE_TEST_SUITE_P
(
    Laws,
    EveryLawCombination,
    ::testing::ValuesIn(allLawCombinations()),
    [](const ::testing::TestParamInfo<LawCombination>& info)
    {
        return info.param.name;
    }
);
