// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "CounterRandom.H"
#include "Materials.H"

#include <cmath>

namespace brachDunn
{

namespace
{

// Philox4x64's multipliers and key increments (Salmon et al. 2011; the
// increments are the first bits of the golden ratio and of sqrt(3) - 1)
constexpr std::uint64_t multiplier0 = 0xD2E7470EE14C6C93;
constexpr std::uint64_t multiplier1 = 0xCA5A826395121157;
constexpr std::uint64_t keyIncrement0 = 0x9E3779B97F4A7C15;
constexpr std::uint64_t keyIncrement1 = 0xBB67AE8584CAA73B;


//- The high and low 64 bits of the 128-bit product a b, from 32-bit halves
//  (no compiler extension)
void multiplyWide
(
    std::uint64_t a,
    std::uint64_t b,
    std::uint64_t& high,
    std::uint64_t& low
)
{
    constexpr std::uint64_t lower32 = 0xFFFFFFFF;
    const std::uint64_t aLow = a & lower32, aHigh = a >> 32;
    const std::uint64_t bLow = b & lower32, bHigh = b >> 32;
    const std::uint64_t lowLow = aLow*bLow, lowHigh = aLow*bHigh;
    const std::uint64_t highLow = aHigh*bLow, highHigh = aHigh*bHigh;
    const std::uint64_t middle =
        (lowLow >> 32) + (lowHigh & lower32) + (highLow & lower32);
    high = highHigh + (lowHigh >> 32) + (highLow >> 32) + (middle >> 32);
    low = a*b;
}

} // End anonymous namespace


RandomBlock philox4x64(RandomBlock c, RandomKey key)
{
    for (int round = 0; round < 10; ++round)
    {
        if (round > 0)
        {
            key[0] += keyIncrement0;
            key[1] += keyIncrement1;
        }
        std::uint64_t high0, low0, high1, low1;
        multiplyWide(multiplier0, c[0], high0, low0);
        multiplyWide(multiplier1, c[2], high1, low1);
        c = {high1 ^ c[1] ^ key[0], low1, high0 ^ c[3] ^ key[1], low0};
    }
    return c;
}


std::uint64_t randomBits
(
    std::uint64_t seed,
    std::uint64_t key1,
    std::uint64_t key2,
    std::uint64_t counter
)
{
    return philox4x64({counter, key1, key2, 0}, {seed, 0})[0];
}


std::uint64_t textCounter(const std::string& text)
{
    // FNV-1a, 64 bits: offset basis and prime of the published parameters
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const unsigned char c : text)
    {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    return hash;
}


double uniformFromBits(std::uint64_t bits)
{
    // k + 1/2 < 2^52 needs 53 bits: exact, so never 0 nor 1
    return (double(bits >> 12) + 0.5)*0x1p-52;
}


std::pair<double, double> boxMuller(double u1, double u2)
{
    const double radius = std::sqrt(-2*std::log(u1));
    return {radius*std::cos(2*pi*u2), radius*std::sin(2*pi*u2)};
}


CounterRandom::CounterRandom
(
    std::uint64_t seed,
    std::uint64_t key1,
    std::uint64_t key2,
    std::uint64_t counter
)
:
    key_{seed, 0},
    counter_{counter, key1, key2, 0},
    block_{},
    next_(4),
    spareNormal_(0),
    hasSpare_(false)
{}


std::uint64_t CounterRandom::bits()
{
    if (next_ == 4)
    {
        block_ = philox4x64(counter_, key_);
        ++counter_[3];
        next_ = 0;
    }
    return block_[next_++];
}


double CounterRandom::uniform()
{
    return uniformFromBits(bits());
}


double CounterRandom::normal()
{
    if (hasSpare_)
    {
        hasSpare_ = false;
        return spareNormal_;
    }
    const double u1 = uniform();
    const auto [first, second] = boxMuller(u1, uniform());
    spareNormal_ = second;
    hasSpare_ = true;
    return first;
}

} // End namespace brachDunn
