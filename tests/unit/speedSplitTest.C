// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The split of impactFit's rebounds between the restitution fit (fast) and
// the adhesion fit (slow): the paper's 10 m/s when the data allow it, else
// chosen so that both laws have enough rebounds, and a message saying what
// to change when no split does.

#include "SpeedSplit.H"
#include "InputError.H"

#include <gtest/gtest.h>

using namespace brachDunn;

namespace
{

const SplitSide restitutionPower{"restitution powerLaw", 2, "-restitution"};
const SplitSide adhesionPower{"adhesion powerLaw", 2, "-adhesion"};
const SplitSide restitutionConstant{"restitution constant", 1, "-restitution"};
const SplitSide adhesionConstant{"adhesion constant", 1, "-adhesion"};

//- The split chosen from the data
SpeedSplit chosen
(
    const std::vector<double>& speeds,
    const SplitSide& fast = restitutionPower,
    const SplitSide& slow = adhesionPower
)
{
    return splitRebounds(speeds, fast, slow, std::nullopt);
}


//- The InputError of a split, or an empty one
InputError errorOf
(
    const std::vector<double>& speeds,
    const SplitSide& fast,
    const SplitSide& slow,
    const std::optional<double>& minSpeed = std::nullopt
)
{
    try
    {
        splitRebounds(speeds, fast, slow, minSpeed);
    }
    catch (const InputError& err)
    {
        return err;
    }
    return InputError("", "", "no error");
}

} // End anonymous namespace


TEST(SpeedSplit, ThePapersSplitWhenTheDataAllowIt)
{
    // Four on each side: two more than each law's coefficients
    const SpeedSplit s = chosen({20, 1, 2, 3, 4, 15, 30, 50});
    EXPECT_EQ(s.minSpeed, 10);
    EXPECT_EQ(s.fast, 4);
    EXPECT_TRUE(s.chosen);
    EXPECT_NE(s.reason.find("the paper's"), std::string::npos) << s.reason;

    // Given, it is used as it is
    const SpeedSplit given =
        splitRebounds({1, 2, 3, 4, 15, 30, 50}, restitutionPower, adhesionPower, 3.5);
    EXPECT_EQ(given.minSpeed, 3.5);
    EXPECT_FALSE(given.chosen);
    EXPECT_EQ(given.slow, 3);
}


TEST(SpeedSplit, ChosenFromTheDataWhenThePapersLeavesTooFew)
{
    // At 10 m/s only two rebounds are faster: the split that leaves the
    // smaller side the most is between 6 and 8 m/s (four each), at 7 m/s
    const SpeedSplit s = chosen({0.8, 1.5, 3, 6, 8, 9, 12, 25});
    EXPECT_EQ(s.minSpeed, 7);
    EXPECT_EQ(s.fast, 4);
    EXPECT_EQ(s.slow, 4);
    EXPECT_NE(s.reason.find("chosen from the data"), std::string::npos);
    EXPECT_NE(s.reason.find("only 2 rebounds faster"), std::string::npos)
        << s.reason;

    // Three faster rebounds: too few for a power law to keep the paper's
    // split, enough for a law of one coefficient
    const std::vector<double> nine{0.8, 1.5, 3, 6, 8, 9, 12, 25, 40};
    EXPECT_NE(chosen(nine).minSpeed, 10);
    EXPECT_EQ(chosen(nine, restitutionConstant).minSpeed, 10);
}


TEST(SpeedSplit, AdhesionAtOneSpeedTakesInFasterRebounds)
{
    // Every slow rebound at 2 m/s leaves a power law's exponent
    // undetermined: the split moves up to take in rebounds at more speeds
    const std::vector<double> speeds{2, 2, 2, 2, 15, 20, 30, 40};
    const SpeedSplit s = chosen(speeds);
    EXPECT_GT(s.minSpeed, 15);
    EXPECT_NE(s.reason.find("at one speed only"), std::string::npos)
        << s.reason;

    // Given at 10 m/s it is refused, saying what to change
    const InputError err = errorOf(speeds, restitutionPower, adhesionPower, 10);
    EXPECT_EQ(err.keyword(), "minSpeed");
    for (const char* hint : {"one speed only", "-adhesion constant", "higher -minSpeed", "leave -minSpeed out"})
    {
        EXPECT_NE(err.requirement().find(hint), std::string::npos)
            << hint << " not in: " << err.what();
    }
    // and the hint works
    EXPECT_NO_THROW
    (
        splitRebounds(speeds, restitutionPower, adhesionConstant, 10.0)
    );
}


TEST(SpeedSplit, TooFewReboundsSayWhatToChange)
{
    // Five rebounds cannot give two power laws three each
    const std::vector<double> speeds{1, 2, 5, 20, 40};
    const InputError err = errorOf(speeds, restitutionPower, adhesionPower);
    EXPECT_EQ(err.keyword(), "rebounds");
    EXPECT_EQ(err.value(), "5");
    for (const char* hint : {"the fit needs at least 3", "-restitution constant", "-adhesion constant", "more rebounds"})
    {
        EXPECT_NE(err.requirement().find(hint), std::string::npos)
            << hint << " not in: " << err.what();
    }
    // and the hint works
    const SpeedSplit s = chosen(speeds, restitutionPower, adhesionConstant);
    EXPECT_EQ(s.fast + s.slow, 5);

    // A given split with too few on a side names it
    const InputError given =
        errorOf(speeds, restitutionPower, adhesionPower, 30);
    EXPECT_EQ(given.keyword(), "minSpeed");
    EXPECT_NE(given.requirement().find("lower -minSpeed"), std::string::npos)
        << given.what();
}


TEST(SpeedSplit, StartingSplitsAreAdmissibleAndSpread)
{
    std::vector<double> speeds;
    for (int i = 1; i <= 40; ++i) speeds.push_back(0.5*i);
    const std::vector<double> splits =
        admissibleSplits(speeds, restitutionPower, adhesionPower, 8);
    ASSERT_EQ(splits.size(), 8u);
    EXPECT_TRUE(std::is_sorted(splits.begin(), splits.end()));
    // The lowest leaves three slow rebounds, the highest three fast ones
    EXPECT_GE(splits.front(), 1.5);
    EXPECT_LT(splits.front(), 2);
    EXPECT_GE(splits.back(), 18.5);
    EXPECT_LT(splits.back(), 19);
}
