// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Each restitution, adhesion and friction law on its own, and their
// selection by name as the dictionaries use it.

#include "testCases.H"
#include "ContactForces.H"

#include <gtest/gtest.h>

#include <cmath>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{
constexpr double noRho = 1000, noModulus = 1e9;
}


TEST(RestitutionLaws, PowerLawEq23)
{
    const RestitutionLaw law = RestitutionLaw::powerLaw(45.3, 0.718);
    // 45.3/(45.3 + 10^0.718), 10^0.718 = 5.2240
    EXPECT_NEAR(law(10, noRho, noModulus), 0.89660, 1e-5);
    EXPECT_NEAR(law(0, noRho, noModulus), 1, 1e-15);
}


TEST(RestitutionLaws, ViscousDamping)
{
    EXPECT_EQ(RestitutionLaw::viscousDamping(0)(5, noRho, noModulus), 1);
    // Logarithmic decrement of a damped oscillator: R = exp(-pi zeta/sqrt(1-zeta^2))
    EXPECT_NEAR
    (
        RestitutionLaw::viscousDamping(0.1)(5, noRho, noModulus),
        0.72925, 1e-5
    );
}


TEST(RestitutionLaws, ThorntonElasticPlastic)
{
    const RestitutionLaw law = RestitutionLaw::elasticPlasticYieldVelocity(0.2);
    EXPECT_EQ(law(0.1, noRho, noModulus), 1);
    EXPECT_EQ(law(0.2, noRho, noModulus), 1);
    EXPECT_NEAR(law(0.2*(1 + 1e-9), noRho, noModulus), 1, 1e-6);

    double previous = 1;
    for (double v = 0.3; v < 1e4; v *= 1.5)
    {
        const double R = law(v, noRho, noModulus);
        EXPECT_LT(R, previous);
        EXPECT_GT(R, 0);
        previous = R;
    }
    // Far above yield R falls as (vy/v)^(1/4)
    const double far = law(2e5, noRho, noModulus);
    EXPECT_NEAR(law(16*2e5, noRho, noModulus)/far, 0.5, 1e-4);
}


TEST(RestitutionLaws, ThorntonYieldVelocityFromYieldStress)
{
    // Thornton (1997): vy = 1.56 sqrt(py^5/(E*^4 rho))
    const double py = 5e7, Estar = 1.3e9, rho = 1350;
    const double vy = 1.56*std::sqrt(std::pow(py, 5)/(std::pow(Estar, 4)*rho));
    const RestitutionLaw law = RestitutionLaw::elasticPlasticYieldStress(py);
    EXPECT_EQ(law(0.999*vy, rho, Estar), 1);
    EXPECT_LT(law(1.002*vy, rho, Estar), 1);
}


TEST(RestitutionLaws, TableInterpolatesAndHolds)
{
    const RestitutionLaw law =
        RestitutionLaw::table({{1, 0.9}, {3, 0.7}, {10, 0.5}});
    EXPECT_EQ(law(0.1, noRho, noModulus), 0.9);
    EXPECT_NEAR(law(2, noRho, noModulus), 0.8, 1e-15);
    EXPECT_NEAR(law(6.5, noRho, noModulus), 0.6, 1e-15);
    EXPECT_EQ(law(100, noRho, noModulus), 0.5);
}


TEST(AdhesionLaws, JKRWorkIsMinusPiGammaASquared)
{
    const double a2 = 2e-13, r = 2e-6;
    EXPECT_EQ(AdhesionLaw::none()(3, a2, r).WA, 0);
    const AdhesionLaw::Work w = AdhesionLaw::constant(0.5)(3, a2, r);
    EXPECT_NEAR(w.WA, -3.14159265358979*0.5*a2, 1e-25);
    // Eq. 24: gamma = 0.34 sqrt(4) at 4 m/s
    EXPECT_NEAR(AdhesionLaw::powerLaw(0.34, 0.5)(4, a2, r).gamma, 0.68, 1e-15);
}


TEST(AdhesionLaws, HamakerAndLifshitzConstantsAgree)
{
    // h = 4 pi A/3
    const double A = 1e-19;
    const AdhesionLaw fromA = AdhesionLaw::select
    (
        "vanDerWaals", MapParameters{{"A", A}, {"f", 0.3}}
    );
    const AdhesionLaw fromH = AdhesionLaw::vanDerWaals(4*pi*A/3, 4e-10, 0.3);
    EXPECT_DOUBLE_EQ(fromA(1, 1e-13, 1e-6).WA, fromH(1, 1e-13, 1e-6).WA);
}


TEST(Selection, ByNameWithKeywords)
{
    const RestitutionLaw r = RestitutionLaw::select
    (
        "powerLaw", MapParameters{{"k", 45.3}, {"p", 0.718}}
    );
    ASSERT_TRUE(r.as<restitution::PowerLaw>());
    EXPECT_EQ(r.as<restitution::PowerLaw>()->k, 45.3);
    EXPECT_EQ(r.as<restitution::PowerLaw>()->p, 0.718);
    EXPECT_EQ(r.typeName(), "powerLaw");
    EXPECT_EQ(r.describe(), "type powerLaw; k 45.3; p 0.718;");

    MapParameters table;
    table.setTable("values", {{0, 1}, {10, 0.8}});
    EXPECT_EQ(RestitutionLaw::select("table", table).typeName(), "table");
    EXPECT_EQ
    (
        RestitutionLaw::select("elasticPlastic", MapParameters{{"yieldStress", 1e8}})
            .typeName(),
        "elasticPlastic"
    );

    EXPECT_EQ
    (
        AdhesionLaw::select("constant", MapParameters{{"gamma", 0.1}}).typeName(),
        "constant"
    );
    EXPECT_EQ(AdhesionLaw::select("none", MapParameters{}).typeName(), "none");
    const FrictionLaw coulomb =
        FrictionLaw::select("coulomb", MapParameters{{"mu", 0.3}});
    ASSERT_TRUE(coulomb.as<friction::Coulomb>());
    EXPECT_EQ(coulomb.as<friction::Coulomb>()->mu, 0.3);
    EXPECT_TRUE
    (
        FrictionLaw::select("sticking", MapParameters{})
            .as<friction::Sticking>()
    );

    const std::vector<std::string> restitutionNames
    {
        "constant", "powerLaw", "viscousDamping", "elasticPlastic", "table"
    };
    EXPECT_EQ(RestitutionLaw::typeNames(), restitutionNames);
    const std::vector<std::string> adhesionNames
    {
        "none", "constant", "powerLaw", "vanDerWaals"
    };
    EXPECT_EQ(AdhesionLaw::typeNames(), adhesionNames);
}
