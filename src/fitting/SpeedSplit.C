// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SpeedSplit.H"
#include "InputError.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace brachDunn
{

namespace
{

std::string speedText(double v)
{
    std::ostringstream os;
    os.precision(4);
    os << v << " m/s";
    return os.str();
}


std::string coefficients(const SplitSide& side)
{
    return side.law + " (" + std::to_string(side.coefficients)
      + (side.coefficients == 1 ? " coefficient)" : " coefficients)");
}


//- "12 rebounds faster for restitution powerLaw (2 coefficients), 8 at or
//  below for adhesion powerLaw (2 coefficients)"
std::string sides
(
    int fast, int slow, const SplitSide& fastSide, const SplitSide& slowSide
)
{
    return
        std::to_string(fast) + " rebounds faster for "
      + coefficients(fastSide) + ", " + std::to_string(slow)
      + " at or below for " + coefficients(slowSide);
}


//- The hint of a side with too few rebounds: a law of one coefficient
std::string fewerCoefficients(const SplitSide& side)
{
    return
        side.coefficients > 1
      ? side.option + " constant (one coefficient), or " : std::string();
}


//- "1 rebound", "3 rebounds"
std::string count(int n, const std::string& what)
{
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}


//- "one speed only", "3 different speeds"
std::string speedCount(int n)
{
    return n == 1 ? "one speed only" : count(n, "different speed");
}


//- The rebounds of sorted speeds on each side of a split
struct Sides
{
    const std::vector<double>& sorted;

    //- Different speeds among the first i rebounds
    std::vector<int> distinctBefore;

    explicit Sides(const std::vector<double>& sorted)
    :
        sorted(sorted),
        distinctBefore(sorted.size() + 1, 0)
    {
        for (std::size_t i = 0; i < sorted.size(); ++i)
        {
            distinctBefore[i + 1] =
                distinctBefore[i] + (i == 0 || sorted[i] != sorted[i - 1]);
        }
    }

    //- Rebounds at or below a speed
    int slowCount(double minSpeed) const
    {
        return std::upper_bound(sorted.begin(), sorted.end(), minSpeed)
          - sorted.begin();
    }

    //- Different speeds among sorted[begin, end)
    int speeds(int begin, int end) const
    {
        if (end <= begin) return 0;
        return
            distinctBefore[end] - distinctBefore[begin]
          + (begin > 0 && sorted[begin] == sorted[begin - 1]);
    }

    //- Whether a law can be fitted to sorted[begin, end): more rebounds
    //  than coefficients, at as many different speeds as coefficients
    bool enough(int begin, int end, const SplitSide& side) const
    {
        return
            end - begin > side.coefficients
         && speeds(begin, end) >= side.coefficients;
    }

    //- Whether the split after the first m rebounds leaves both laws
    //  enough (between different speeds)
    bool admissible(int m, const SplitSide& fast, const SplitSide& slow) const
    {
        const int n = sorted.size();
        return
            m > 0 && m < n && sorted[m - 1] < sorted[m]
         && enough(0, m, slow) && enough(m, n, fast);
    }
};


//- The InputError of a minSpeed given that leaves a law too few rebounds
//  or speeds
void requireEnough
(
    const Sides& s, int begin, int end, const SplitSide& side,
    double minSpeed, const char* where, const char* change
)
{
    if (s.enough(begin, end, side)) return;
    const int n = end - begin;
    const std::string need =
        n <= side.coefficients
      ? ", the fit needs at least " + std::to_string(side.coefficients + 1)
      : " at " + speedCount(s.speeds(begin, end)) + ", its coefficients need "
      + std::to_string(side.coefficients) + " speeds at least";
    throw InputError
    (
        "minSpeed", toText(minSpeed),
        side.law + ", impacts " + where + " minSpeed: "
      + count(n, "rebounding impact") + need + "; give a " + change
      + " -minSpeed, or leave -minSpeed out to have it chosen from the data,"
        " or " + fewerCoefficients(side) + "rebounds at more speeds"
    );
}


//- A minSpeed given: used as it is, each side with enough rebounds
SpeedSplit givenSplit
(
    const Sides& s,
    const SplitSide& fast,
    const SplitSide& slow,
    double minSpeed
)
{
    requirePositive("minSpeed", minSpeed);
    const int n = s.sorted.size();
    const int nSlow = s.slowCount(minSpeed);
    requireEnough(s, nSlow, n, fast, minSpeed, "faster than", "lower");
    requireEnough(s, 0, nSlow, slow, minSpeed, "at or below", "higher");
    return
    {
        minSpeed, n - nSlow, nSlow, false,
        "minSpeed " + speedText(minSpeed) + " as given: "
      + sides(n - nSlow, nSlow, fast, slow)
    };
}


//- A round speed in [low, high): the paper's when it is there, else the
//  geometric mean to the fewest significant figures that stay inside
double roundSpeed(double low, double high)
{
    if (paperMinSpeed >= low && paperMinSpeed < high) return paperMinSpeed;
    const double mean = std::sqrt(low*high);
    for (int figures = 1; figures <= 15; ++figures)
    {
        const double unit =
            std::pow(10.0, std::floor(std::log10(mean)) - figures + 1);
        const double v = std::round(mean/unit)*unit;
        if (v >= low && v < high) return v;
    }
    return low;
}


//- No split leaves both laws enough rebounds
[[noreturn]] void tooFewRebounds
(
    const Sides& s, const SplitSide& fast, const SplitSide& slow
)
{
    const int n = s.sorted.size();
    throw InputError
    (
        "rebounds", std::to_string(n),
        "no split of these rebounds (at " + std::to_string(s.speeds(0, n))
      + " different speeds) leaves each law enough: the fit needs at least "
      + std::to_string(fast.coefficients + 1) + " faster rebounds for "
      + coefficients(fast) + " and "
      + std::to_string(slow.coefficients + 1) + " slower ones for "
      + coefficients(slow) + ", each side at as many different speeds as"
        " its coefficients; give more rebounds, or "
      + fewerCoefficients(fast) + fewerCoefficients(slow)
      + "rebounds at more speeds"
    );
}


//- Of the admissible splits, the one that leaves the smaller side the most
//  rebounds beyond its coefficients, the nearest the paper's among equals;
//  the number of slow rebounds (0: none admissible)
int balancedSplit
(
    const Sides& s, const SplitSide& fast, const SplitSide& slow
)
{
    const int n = s.sorted.size();
    int best = -1, bestSlow = 0;
    double bestDistance = HUGE_VAL;
    for (int m = 1; m < n; ++m)
    {
        if (!s.admissible(m, fast, slow)) continue;
        const int surplus =
            std::min(m - slow.coefficients, n - m - fast.coefficients);
        const double distance = std::abs
        (
            std::log(roundSpeed(s.sorted[m - 1], s.sorted[m])/paperMinSpeed)
        );
        if (surplus > best || (surplus == best && distance < bestDistance))
        {
            best = surplus;
            bestSlow = m;
            bestDistance = distance;
        }
    }
    return bestSlow;
}


//- Why the paper's split does not do for a side (empty: it does)
std::string shortfall
(
    const Sides& s, int begin, int end, const SplitSide& side,
    const char* where
)
{
    const int n = end - begin;
    const std::string rebounds =
        count(n, "rebound") + " " + where + " it";
    if (n <= side.coefficients)
    {
        return "only " + rebounds + ", too few for " + coefficients(side);
    }
    if (s.speeds(begin, end) < side.coefficients)
    {
        return rebounds + " at " + speedCount(s.speeds(begin, end))
          + ", too few speeds for " + coefficients(side);
    }
    if (n < side.coefficients + preferredSurplus)
    {
        return "only " + rebounds + ", not "
          + std::to_string(preferredSurplus) + " more than the coefficients"
            " of " + coefficients(side);
    }
    return "";
}


//- No minSpeed given: the paper's when the data allow it, else the
//  balanced split
SpeedSplit chosenSplit
(
    const Sides& s,
    const SplitSide& fast,
    const SplitSide& slow
)
{
    const int n = s.sorted.size();
    const int paperSlow = s.slowCount(paperMinSpeed);
    const std::string paper = sides(n - paperSlow, paperSlow, fast, slow);
    const std::string given = "minSpeed " + speedText(paperMinSpeed)
      + ", the paper's (no -minSpeed given; ";
    const std::string fastShort =
        shortfall(s, paperSlow, n, fast, "faster than");
    const std::string slowShort =
        shortfall(s, 0, paperSlow, slow, "at or below");
    if (fastShort.empty() && slowShort.empty())
    {
        return {paperMinSpeed, n - paperSlow, paperSlow, true,
            given + "kept as the data allow it): " + paper};
    }
    const int m = balancedSplit(s, fast, slow);
    if (m == 0) tooFewRebounds(s, fast, slow);
    const double v = roundSpeed(s.sorted[m - 1], s.sorted[m]);
    if (v == paperMinSpeed)
    {
        return {v, n - m, m, true,
            given + "no other split leaves the smaller side more): " + paper};
    }
    return
    {
        v, n - m, m, true,
        "minSpeed " + speedText(v) + ", chosen from the data (no -minSpeed"
        " given): the paper's " + speedText(paperMinSpeed) + " would leave "
      + fastShort + (fastShort.empty() || slowShort.empty() ? "" : ", and ")
      + slowShort + "; " + speedText(v) + " leaves " + std::to_string(n - m)
      + " faster and " + std::to_string(m)
      + " at or below, the most the data allow on the smaller side"
    };
}

} // End anonymous namespace


SpeedSplit splitRebounds
(
    std::vector<double> speeds,
    const SplitSide& fast,
    const SplitSide& slow,
    const std::optional<double>& minSpeed
)
{
    std::sort(speeds.begin(), speeds.end());
    const Sides s(speeds);
    return
        minSpeed
      ? givenSplit(s, fast, slow, *minSpeed)
      : chosenSplit(s, fast, slow);
}


std::vector<double> admissibleSplits
(
    std::vector<double> speeds,
    const SplitSide& fast,
    const SplitSide& slow,
    int most
)
{
    std::sort(speeds.begin(), speeds.end());
    const Sides s(speeds);
    std::vector<double> all;
    for (int m = 1; m < int(speeds.size()); ++m)
    {
        if (s.admissible(m, fast, slow))
        {
            all.push_back(roundSpeed(speeds[m - 1], speeds[m]));
        }
    }
    if (int(all.size()) <= most || most < 2) return all;
    std::vector<double> spread;
    for (int i = 0; i < most; ++i)
    {
        spread.push_back(all[(i*(all.size() - 1))/(most - 1)]);
    }
    return spread;
}

} // End namespace brachDunn
