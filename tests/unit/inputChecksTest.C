// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Every bad input raises an InputError that names the keyword and the value.

#include "testCases.H"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

void expectInputError
(
    const std::function<void()>& call,
    const std::string& keyword,
    const std::string& value
)
{
    try
    {
        call();
        ADD_FAILURE() << "no error for " << keyword << " = " << value;
    }
    catch (const InputError& err)
    {
        EXPECT_EQ(err.keyword(), keyword);
        EXPECT_EQ(err.value(), value);
        EXPECT_NE(std::string(err.what()).find(keyword + " = " + value),
                  std::string::npos) << err.what();
    }
}

ImpactModel modelWith
(
    const ElasticMaterial& particle,
    const ElasticMaterial& wall,
    double momentCoeff = -1
)
{
    return ImpactModel
    (
        particle, wall, paperRestitution(), paperAdhesion(),
        FrictionLaw::sticking(), momentCoeff
    );
}

const double notANumber = std::numeric_limits<double>::quiet_NaN();
const double infinity = std::numeric_limits<double>::infinity();

} // End anonymous namespace


TEST(InputChecks, Materials)
{
    expectInputError([]{ modelWith({0, 0.3}, molybdenum); }, "E", "0");
    expectInputError([]{ modelWith(fluorescein, {-1e9, 0.3}); }, "E", "-1e+09");
    expectInputError([]{ modelWith({1e9, -1}, molybdenum); }, "nu", "-1");
    expectInputError([]{ modelWith({1e9, 0.6}, molybdenum); }, "nu", "0.6");
    expectInputError([]{ modelWith({1e9, notANumber}, molybdenum); }, "nu", "nan");
    expectInputError
    (
        []{ modelWith(fluorescein, molybdenum, 1.5); }, "momentCoeff", "1.5"
    );
    expectInputError
    (
        []{ modelWith(fluorescein, molybdenum, -1.01); }, "momentCoeff", "-1.01"
    );
}


TEST(InputChecks, Laws)
{
    expectInputError([]{ RestitutionLaw::constant(1.1); }, "R", "1.1");
    expectInputError([]{ RestitutionLaw::constant(-0.1); }, "R", "-0.1");
    expectInputError([]{ RestitutionLaw::powerLaw(0, 1); }, "k", "0");
    expectInputError([]{ RestitutionLaw::viscousDamping(1); }, "zeta", "1");
    expectInputError
    (
        []{ RestitutionLaw::elasticPlasticYieldVelocity(-2); }, "yieldVelocity", "-2"
    );
    expectInputError
    (
        []{ RestitutionLaw::table({{1, 0.9}, {1, 0.8}}); }, "values (speed)", "1"
    );
    expectInputError
    (
        []{ RestitutionLaw::table({{1, 0.9}, {2, 1.5}}); }, "values (R)", "1.5"
    );
    expectInputError([]{ AdhesionLaw::constant(-1); }, "gamma", "-1");
    expectInputError([]{ AdhesionLaw::powerLaw(0.34, infinity); }, "n", "inf");
    expectInputError([]{ AdhesionLaw::vanDerWaals(1e-19, 0, 0.5); }, "z", "0");
    expectInputError([]{ AdhesionLaw::vanDerWaals(1e-19, 4e-10, 2); }, "f", "2");
    expectInputError([]{ FrictionLaw::coulomb(-0.1); }, "mu", "-0.1");
}


TEST(InputChecks, SelectionNamesUnknownTypesAndMissingKeywords)
{
    expectInputError
    (
        []{ RestitutionLaw::select("bouncy", MapParameters{}); }, "type", "bouncy"
    );
    expectInputError
    (
        []{ AdhesionLaw::select("glue", MapParameters{}); }, "type", "glue"
    );
    expectInputError
    (
        []{ FrictionLaw::select("grip", MapParameters{}); }, "type", "grip"
    );
    expectInputError
    (
        []{ RestitutionLaw::select("powerLaw", MapParameters{{"k", 45.3}}); },
        "p", "missing"
    );
    expectInputError
    (
        []{ AdhesionLaw::select("vanDerWaals", MapParameters{{"f", 0.1}}); },
        "h", "missing"
    );
    expectInputError
    (
        []
        {
            RestitutionLaw::select
            (
                "elasticPlastic",
                MapParameters{{"yieldVelocity", 1}, {"yieldStress", 1e8}}
            );
        },
        "yieldStress", "1e+08"
    );

    try
    {
        RestitutionLaw::select("bouncy", MapParameters{});
    }
    catch (const InputError& err)
    {
        // The message lists what is valid
        EXPECT_NE(std::string(err.what()).find("powerLaw"), std::string::npos);
    }
}


TEST(InputChecks, SelectionRejectsKeywordsTheLawDoesNotTake)
{
    // A misspelt optional keyword: vanDerWaals would take z = 4e-10 in silence
    expectInputError
    (
        []
        {
            AdhesionLaw::select
            (
                "vanDerWaals", MapParameters{{"h", 7.3e-19}, {"Z", 3e-10}, {"f", 0.1}}
            );
        },
        "Z", "3e-10"
    );
    // Another law's coefficient left behind
    expectInputError
    (
        []
        {
            RestitutionLaw::select("constant", MapParameters{{"R", 0.9}, {"k", 45.3}});
        },
        "k", "45.3"
    );
    expectInputError
    (
        []{ FrictionLaw::select("sticking", MapParameters{{"mu", 0.3}}); },
        "mu", "0.3"
    );
    expectInputError
    (
        []
        {
            RestitutionLaw::select
            (
                "table",
                MapParameters{}.setTable("values", {{0, 1}}).setTable("value", {{0, 1}})
            );
        },
        "value", "(table)"
    );

    // The message names the law and what it takes
    try
    {
        FrictionLaw::select("coulomb", MapParameters{{"mu", 0.3}, {"e", 0.5}});
        ADD_FAILURE() << "no error for e";
    }
    catch (const InputError& err)
    {
        const std::string what = err.what();
        EXPECT_NE(what.find("friction law coulomb"), std::string::npos) << what;
        EXPECT_NE(what.find("it takes: mu"), std::string::npos) << what;
    }

    // Every keyword a law reads, optional ones included, is accepted
    EXPECT_NO_THROW
    (
        AdhesionLaw::select
        (
            "vanDerWaals", MapParameters{{"A", 1e-19}, {"z", 3e-10}, {"f", 0.1}}
        )
    );
    EXPECT_NO_THROW
    (
        RestitutionLaw::select("elasticPlastic", MapParameters{{"yieldStress", 1e8}})
    );
    EXPECT_NO_THROW(FrictionLaw::select("sticking", MapParameters{}));
}


TEST(InputChecks, Impacts)
{
    const ImpactModel m = paperModel();
    expectInputError([&]{ m.impact(Particle{0, 1350}, 1, 0); }, "d", "0");
    expectInputError([&]{ m.impact(Particle{1e-6, -5}, 1, 0); }, "rho", "-5");
    expectInputError([&]{ m.impact(Particle{1e-6, 1350}, notANumber, 0); }, "un", "nan");
    expectInputError([&]{ m.impact(Particle{1e-6, 1350}, 1, infinity); }, "ut", "inf");
    expectInputError([&]{ m.impact(Particle{1e-6, 1350}, 1, -1); }, "ut", "-1");
    expectInputError
    (
        [&]{ m.impact(Particle{1e-6, 1350}, Vector3{1, notANumber, 0}, Vector3{0, 0, 1}); },
        "U", "nan"
    );
    expectInputError
    (
        [&]{ m.impact(Particle{1e-6, 1350}, Vector3{1, 0, 0}, Vector3{}); },
        "|n|", "0"
    );
}


// The rule each check states: a value that is not finite is said to be so
// whatever the check, and a range names its bounds with their open or
// closed ends
TEST(InputChecks, RequirementTexts)
{
    const auto requirementOf = [](const std::function<void()>& call)
    {
        try
        {
            call();
        }
        catch (const InputError& err)
        {
            return err.requirement();
        }
        return std::string("no error");
    };
    EXPECT_EQ(requirementOf([]{ requirePositive("k", infinity); }), "must be a finite number");
    EXPECT_EQ(requirementOf([]{ requireInRange("p", notANumber, 0, 10); }), "must be a finite number");
    EXPECT_EQ(requirementOf([]{ requireFinite("zeta", -infinity); }), "must be a finite number");
    EXPECT_EQ(requirementOf([]{ requirePositive("k", 0); }), "must be > 0");
    EXPECT_EQ(requirementOf([]{ requireNonNegative("mu", -1); }), "must be >= 0");
    EXPECT_EQ(requirementOf([]{ requireInRange("f", 2, 0, 1); }), "must be in [0, 1]");
    EXPECT_EQ(requirementOf([]{ requireAboveAtMost("h", 0, 0, 1e-14); }), "must be in (0, 1e-14]");
    EXPECT_EQ(requirementOf([]{ requireInRange("f", 1, 0, 1); }), "no error");
    EXPECT_EQ(requirementOf([]{ requireAboveAtMost("h", 1e-14, 0, 1e-14); }), "no error");
}
