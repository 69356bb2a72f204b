// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The law families' one table (LawSet.H): every law reads back what it
// describes, each law's type name is the name at its place in the table,
// only the laws that declare their coefficients can be fitted, and each
// family's evaluation is its law's.

#include "lawCombinations.H"

#include <gtest/gtest.h>

#include <regex>
#include <set>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

//- The keywords and numbers of a describe() text, "type X; k 1; p 2;", and
//  of a table's "values ((0 1) (5 0.9));"
MapParameters parse(const std::string& text, std::string& type)
{
    MapParameters parameters;
    const std::regex entry(R"((\w+) ([^;]*);)");
    for
    (
        auto it = std::sregex_iterator(text.begin(), text.end(), entry);
        it != std::sregex_iterator();
        ++it
    )
    {
        const std::string keyword = (*it)[1], value = (*it)[2];
        if (keyword == "type")
        {
            type = value;
        }
        else if (value[0] == '(')
        {
            Table table;
            const std::regex pair(R"(\(([-\d.e+]+) ([-\d.e+]+)\))");
            for
            (
                auto p = std::sregex_iterator(value.begin(), value.end(), pair);
                p != std::sregex_iterator();
                ++p
            )
            {
                table.push_back({std::stod((*p)[1]), std::stod((*p)[2])});
            }
            parameters.setTable(keyword, table);
        }
        else
        {
            parameters.set(keyword, std::stod(value));
        }
    }
    return parameters;
}


template<class Family>
void expectReadsBack(const Family& law)
{
    std::string type;
    const MapParameters parameters = parse(law.describe(), type);
    const Family again = Family::select(type, parameters);
    EXPECT_EQ(again.describe(), law.describe());
    EXPECT_EQ(again.law().index(), law.law().index()) << law.describe();
}


//- The type name of a law is the table's name at the law's place
template<class Family>
void expectNameInPlace(const Family& law)
{
    EXPECT_EQ(Family::typeNames()[law.law().index()], law.typeName());
}

} // End anonymous namespace


TEST(LawSet, EveryLawReadsBackWhatItDescribes)
{
    std::set<std::string> seen;
    for (const LawCombination& c : allLawCombinations())
    {
        seen.insert(c.restitution.describe());
        seen.insert(c.adhesion.describe());
        seen.insert(c.friction.describe());
        expectReadsBack(c.restitution);
        expectReadsBack(c.adhesion);
        expectReadsBack(c.friction);
        expectNameInPlace(c.restitution);
        expectNameInPlace(c.adhesion);
        expectNameInPlace(c.friction);
    }
    // Every law type of each family appears among the combinations
    EXPECT_EQ(seen.size(), RestitutionLaw::typeNames().size() + 1    // both elasticPlastic forms
        + AdhesionLaw::typeNames().size() + FrictionLaw::typeNames().size());
}


TEST(LawSet, TheTableIsTheDocumentedList)
{
    EXPECT_EQ
    (
        RestitutionLaw::typeNames(),
        (std::vector<std::string>
        {"constant", "powerLaw", "viscousDamping", "elasticPlastic", "table"})
    );
    EXPECT_EQ
    (
        AdhesionLaw::typeNames(),
        (std::vector<std::string>{"none", "constant", "powerLaw", "vanDerWaals"})
    );
    EXPECT_EQ
    (
        FrictionLaw::typeNames(),
        (std::vector<std::string>{"sticking", "coulomb"})
    );
}


TEST(LawSet, OnlyLawsWithCoefficientsCanBeFitted)
{
    const LawFitting<RestitutionLaw> power = RestitutionLaw::fitting("powerLaw");
    ASSERT_EQ(power.coefficients.size(), 2u);
    EXPECT_STREQ(power.coefficients[0].name, "k");
    EXPECT_TRUE(power.coefficients[0].logarithmic);
    const double values[] = {45.3, 0.718};
    const RestitutionLaw law = power.law(values);
    EXPECT_EQ(law.describe(), RestitutionLaw::powerLaw(45.3, 0.718).describe());
    EXPECT_EQ(power.values(law), (std::vector<double>{45.3, 0.718}));

    try
    {
        RestitutionLaw::fitting("viscousDamping", "restitution");
        ADD_FAILURE() << "viscousDamping fitted";
    }
    catch (const InputError& err)
    {
        EXPECT_EQ(err.keyword(), "restitution");
        EXPECT_EQ(err.value(), "viscousDamping");
        EXPECT_NE(std::string(err.what()).find(": constant powerLaw"),
                  std::string::npos) << err.what();
    }
    EXPECT_THROW(AdhesionLaw::fitting("vanDerWaals"), InputError);
    EXPECT_NO_THROW(AdhesionLaw::fitting("constant"));
}


TEST(LawSet, FrictionLawsGiveTheirImpulse)
{
    // m = 2 kg at ut = 3 m/s under P_n = 10 N s: sticking stops it (6 N s);
    // Coulomb 0.3 slides (3 N s), Coulomb 0.9 stops it (min(9, 6))
    EXPECT_EQ(FrictionLaw::sticking().tangentialImpulse(2, 3, 10), 6);
    EXPECT_EQ(FrictionLaw::coulomb(0.3).tangentialImpulse(2, 3, 10), 3);
    EXPECT_EQ(FrictionLaw::coulomb(0.9).tangentialImpulse(2, 3, 10), 6);
}


TEST(LawSet, AMissingKeywordNamesTheStrangerGiven)
{
    // pp typed for p: the error is about p, and names pp
    try
    {
        RestitutionLaw::select("powerLaw", MapParameters{{"k", 45.3}, {"pp", 0.7}});
        ADD_FAILURE() << "no error";
    }
    catch (const InputError& err)
    {
        EXPECT_EQ(err.keyword(), "p");
        EXPECT_NE(std::string(err.what()).find("given instead: pp"),
                  std::string::npos) << err.what();
    }
    // Nothing else given: just required
    try
    {
        AdhesionLaw::select("powerLaw", MapParameters{{"c", 0.34}});
        ADD_FAILURE() << "no error";
    }
    catch (const InputError& err)
    {
        EXPECT_EQ(err.keyword(), "n");
        EXPECT_EQ(err.requirement(), "keyword is required");
    }
}
