// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Counter-based random numbers (CounterRandom): Philox4x64-10 against the
// known-answer vectors of Random123 and against an implementation written
// here with 128-bit integers; the streams' bits pinned from a third,
// independent implementation in Python integers; reproducibility; the
// statistics of the uniform and normal numbers (moments, a chi-square, the
// normal distribution function) and the independence of the streams of
// neighbouring seeds, origins and time indices.

#include "CounterRandom.H"

#include <gtest/gtest.h>

#include <bitset>
#include <cmath>
#include <cstdint>
#include <random>
#include <unordered_set>

using namespace brachDunn;

namespace
{

//- Philox4x64-10 as Salmon et al. (2011) describe it, with the compiler's
//  128-bit product (the code under test builds it from 32-bit halves)
RandomBlock referencePhilox(RandomBlock c, RandomKey k)
{
    for (int round = 0; round < 10; ++round)
    {
        const unsigned __int128 p0 =
            (unsigned __int128)0xD2E7470EE14C6C93u*c[0];
        const unsigned __int128 p1 =
            (unsigned __int128)0xCA5A826395121157u*c[2];
        c =
        {
            std::uint64_t(p1 >> 64) ^ c[1] ^ k[0], std::uint64_t(p1),
            std::uint64_t(p0 >> 64) ^ c[3] ^ k[1], std::uint64_t(p0)
        };
        k[0] += 0x9E3779B97F4A7C15u;
        k[1] += 0xBB67AE8584CAA73Bu;
    }
    return c;
}


//- The sample correlation coefficient of n pairs
struct Correlation
{
    long double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    long n = 0;

    void add(double x, double y)
    {
        sx += x; sy += y; sxx += x*x; syy += y*y; sxy += x*y; ++n;
    }

    double value() const
    {
        const long double cxy = sxy/n - sx/n*sy/n;
        const long double cxx = sxx/n - sx/n*sx/n;
        const long double cyy = syy/n - sy/n*sy/n;
        return double(cxy/std::sqrt(cxx*cyy));
    }
};


constexpr std::uint64_t seed = 0x5eed;

} // End anonymous namespace


TEST(CounterRandom, PhiloxKnownAnswers)
{
    // Random123's kat_vectors (philox4x64, 10 rounds): counter, key, output
    struct Case { RandomBlock counter; RandomKey key; RandomBlock output; };
    const std::uint64_t ones = ~std::uint64_t(0);
    const Case cases[] =
    {
        {
            {0, 0, 0, 0}, {0, 0},
            {0x16554d9eca36314c, 0xdb20fe9d672d0fdc,
             0xd7e772cee186176b, 0x7e68b68aec7ba23b}
        },
        {
            {ones, ones, ones, ones}, {ones, ones},
            {0x87b092c3013fe90b, 0x438c3c67be8d0224,
             0x9cc7d7c69cd777b6, 0xa09caebf594f0ba0}
        },
        {
            {0x243f6a8885a308d3, 0x13198a2e03707344,
             0xa4093822299f31d0, 0x082efa98ec4e6c89},
            {0x452821e638d01377, 0xbe5466cf34e90c6c},
            {0xa528f45403e61d95, 0x38c72dbd566e9788,
             0xa5a1610e72fd18b5, 0x57bd43b5e52b7fe6}
        }
    };
    for (const Case& c : cases)
    {
        EXPECT_EQ(philox4x64(c.counter, c.key), c.output);
    }
}


TEST(CounterRandom, PhiloxAgainstAReference)
{
    // Random counters and keys: the carries of the 32-bit product halves
    std::mt19937_64 engine(1);
    for (int i = 0; i < 20000; ++i)
    {
        const RandomBlock c{engine(), engine(), engine(), engine()};
        const RandomKey k{engine(), engine()};
        ASSERT_EQ(philox4x64(c, k), referencePhilox(c, k)) << i;
    }
}


TEST(CounterRandom, TextCounterIsFnv1a)
{
    // The FNV-1a 64-bit test vectors of its authors' reference tables:
    // "" gives the offset basis, "a" 0xaf63dc4c8601ec8c, "foobar"
    // 0x85944171f73967e8
    EXPECT_EQ(textCounter(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(textCounter("a"), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(textCounter("foobar"), 0x85944171f73967e8ULL);
    EXPECT_NE(textCounter("0.0003"), textCounter("0.0004"));
}


TEST(CounterRandom, PinnedBits)
{
    // From an implementation in Python integers (checked there against the
    // known answers): the words of (seed, key1, key2, counter), blocks
    // (counter, key1, key2, block) under the key (seed, 0)
    struct Case { std::uint64_t seed, key1, key2, counter, words[6]; };
    const Case cases[] =
    {
        {0, 0, 0, 0, {0x16554d9eca36314c, 0xdb20fe9d672d0fdc,
                      0xd7e772cee186176b, 0x7e68b68aec7ba23b,
                      0x0bcebd58167d0f31, 0x7834e0e0d3a96d3f}},
        {12345, 3, 987654321, 42, {0xa095e7420be17f22, 0xa5bf8b9812464c27,
                                   0x59b96d2df93b0387, 0x95fd38eb5d03c7ea,
                                   0x0f984bfada04a066, 0x648bf6f967a6269d}},
        {~std::uint64_t(0), 7, (std::uint64_t(1) << 40) + 5, 1000000,
                                  {0xca371d43de8b7087, 0x66d929ec5cc46fa9,
                                   0xeec6d80c7e2370d8, 0x07f0c5bdea8aa372,
                                   0xe10a19dc3464fd08, 0x05689f35a7606f16}}
    };
    for (const Case& c : cases)
    {
        EXPECT_EQ(randomBits(c.seed, c.key1, c.key2, c.counter), c.words[0]);
        CounterRandom stream(c.seed, c.key1, c.key2, c.counter);
        for (const std::uint64_t word : c.words)
        {
            EXPECT_EQ(stream.bits(), word);
        }
    }

    // The uniform and normal numbers of the second stream (Python floats:
    // exact for the uniforms, to the last bits of log, cos, sin for the
    // normals)
    CounterRandom uniforms(12345, 3, 987654321, 42);
    for (const double u : {0.6272873436208836, 0.6474539991634397,
                           0.3504856335868959, 0.5858951162927176})
    {
        EXPECT_EQ(uniforms.uniform(), u);
    }
    CounterRandom normals(12345, 3, 987654321, 42);
    for (const double z : {-0.5800877515033926, -0.7721394437792993,
                           -1.2422387309924814, -0.7441196534139441})
    {
        EXPECT_NEAR(normals.normal(), z, 1e-14);
    }
}


TEST(CounterRandom, SameInputsSameNumbers)
{
    CounterRandom a(seed, 2, 17, 300), b(seed, 2, 17, 300);
    for (int i = 0; i < 100; ++i)
    {
        ASSERT_EQ(a.bits(), b.bits()) << i;
        ASSERT_EQ(a.normal(), b.normal()) << i;
    }
    // Any one input changed: other bits
    const std::uint64_t bits = randomBits(seed, 2, 17, 300);
    EXPECT_NE(randomBits(seed + 1, 2, 17, 300), bits);
    EXPECT_NE(randomBits(seed, 3, 17, 300), bits);
    EXPECT_NE(randomBits(seed, 2, 18, 300), bits);
    EXPECT_NE(randomBits(seed, 2, 17, 301), bits);
    EXPECT_NE(randomBits(seed, 17, 2, 300), bits);

    // 200000 origins and times: no two equal words (a collision among
    // 2e5 random 64-bit words has probability 1e-9)
    std::unordered_set<std::uint64_t> seen;
    for (std::uint64_t id = 0; id < 2000; ++id)
    {
        for (std::uint64_t time = 0; time < 100; ++time)
        {
            ASSERT_TRUE(seen.insert(randomBits(seed, id % 4, id, time)).second);
        }
    }
}


TEST(CounterRandom, UniformRange)
{
    // (k + 1/2)/2^52 of the upper 52 bits k: strictly inside (0, 1)
    EXPECT_EQ(uniformFromBits(0), 0x1p-53);
    EXPECT_EQ(uniformFromBits(~std::uint64_t(0)), 1 - 0x1p-53);
    EXPECT_EQ(uniformFromBits(std::uint64_t(1) << 63), 0.5 + 0x1p-53);
    EXPECT_EQ(uniformFromBits(0xFFF), 0x1p-53);
}


TEST(CounterRandom, UniformMomentsAndChiSquare)
{
    // One number per parcel and time index, as the model draws them: mean
    // 1/2 and variance 1/12 within 5 standard errors; 100 equal bins:
    // chi-square with 99 degrees of freedom within 5 of its standard
    // deviations, sqrt(198), of 99
    const int n = 1000000, bins = 100;
    long double sum = 0, sumSqr = 0;
    long counts[bins] = {};
    for (int id = 0; id < 10000; ++id)
    {
        for (int time = 0; time < 100; ++time)
        {
            const double u = uniformFromBits(randomBits(seed, 1, id, time));
            sum += u;
            sumSqr += (u - 0.5)*(u - 0.5);
            ++counts[int(u*bins)];
        }
    }
    EXPECT_NEAR(double(sum/n), 0.5, 5*std::sqrt(1.0/12/n));
    EXPECT_NEAR(double(sumSqr/n), 1.0/12, 5*std::sqrt(1.0/180/n));

    const double expected = double(n)/bins;
    double chiSquare = 0;
    for (const long count : counts)
    {
        chiSquare += (count - expected)*(count - expected)/expected;
    }
    EXPECT_NEAR(chiSquare, 99, 5*std::sqrt(198.0));
}


TEST(CounterRandom, NormalMoments)
{
    // Mean 0, variance 1, skewness 0, kurtosis 3 within 5 standard errors
    // (the variances of z, z^2, z^3, z^4 are 1, 2, 15, 96), and the
    // distribution function at -2, -1, 0, 1, 2 within 5 standard errors
    const int n = 1000000;
    const double points[] = {-2, -1, 0, 1, 2};
    long below[5] = {};
    long double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
    for (int id = 0; id < n/4; ++id)
    {
        CounterRandom random(seed, 0, id, 12);
        for (int k = 0; k < 4; ++k)
        {
            const long double z = random.normal();
            s1 += z; s2 += z*z; s3 += z*z*z; s4 += z*z*z*z;
            for (int j = 0; j < 5; ++j)
            {
                below[j] += z < points[j];
            }
        }
    }
    EXPECT_NEAR(double(s1/n), 0, 5*std::sqrt(1.0/n));
    EXPECT_NEAR(double(s2/n), 1, 5*std::sqrt(2.0/n));
    EXPECT_NEAR(double(s3/n), 0, 5*std::sqrt(15.0/n));
    EXPECT_NEAR(double(s4/n), 3, 5*std::sqrt(96.0/n));
    for (int j = 0; j < 5; ++j)
    {
        const double P = 0.5*std::erfc(-points[j]/std::sqrt(2.0));
        EXPECT_NEAR(double(below[j])/n, P, 5*std::sqrt(P*(1 - P)/n))
            << points[j];
    }
}


TEST(CounterRandom, BoxMullerByHand)
{
    // u1 = e^-2: radius sqrt(-2 ln u1) = 2; u2 = 1/8: the angle pi/4
    const auto [z1, z2] = boxMuller(std::exp(-2.0), 0.125);
    EXPECT_NEAR(z1, std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(z2, std::sqrt(2.0), 1e-15);
    const auto [z3, z4] = boxMuller(std::exp(-0.5), 0.5);
    EXPECT_NEAR(z3, -1, 1e-15);
    EXPECT_NEAR(z4, 0, 1e-15);
}


TEST(CounterRandom, NeighbouringStreamsUncorrelated)
{
    // The uniform numbers of neighbouring seeds, origins (processor, id),
    // time indices and successive words of one stream: correlation within
    // 5/sqrt(n) of 0
    const int n = 200000;
    Correlation bySeed, byProc, byId, byTime, byWord, byNormal;
    for (int i = 0; i < n; ++i)
    {
        const std::uint64_t proc = i % 8, id = i/8, time = 5;
        const auto u = [](std::uint64_t s, std::uint64_t p, std::uint64_t k,
                          std::uint64_t t)
        {
            return uniformFromBits(randomBits(s, p, k, t));
        };
        const double here = u(seed, proc, id, time);
        bySeed.add(here, u(seed + 1, proc, id, time));
        byProc.add(here, u(seed, proc + 1, id, time));
        byId.add(here, u(seed, proc, id + 1, time));
        byTime.add(here, u(seed, proc, id, time + 1));

        CounterRandom stream(seed, proc, id, time);
        const double first = stream.uniform();
        byWord.add(first, stream.uniform());
        CounterRandom normals(seed, proc, id, time);
        const double z = normals.normal();
        byNormal.add(z, normals.normal());
    }
    const double bound = 5/std::sqrt(double(n));
    EXPECT_NEAR(bySeed.value(), 0, bound);
    EXPECT_NEAR(byProc.value(), 0, bound);
    EXPECT_NEAR(byId.value(), 0, bound);
    EXPECT_NEAR(byTime.value(), 0, bound);
    EXPECT_NEAR(byWord.value(), 0, bound);
    EXPECT_NEAR(byNormal.value(), 0, bound);
}


TEST(CounterRandom, Avalanche)
{
    // One input bit flipped flips each output bit with probability 1/2:
    // the mean fraction of flipped bits within 5 standard errors of 1/2
    std::mt19937_64 engine(3);
    const int n = 20000;
    long flipped = 0;
    for (int i = 0; i < n; ++i)
    {
        std::uint64_t in[4] = {engine(), engine() % 1024, engine(), engine()};
        const std::uint64_t before = randomBits(in[0], in[1], in[2], in[3]);
        in[i % 4] ^= std::uint64_t(1) << (engine() % 64);
        const std::uint64_t after = randomBits(in[0], in[1], in[2], in[3]);
        flipped += std::bitset<64>(before ^ after).count();
    }
    const double bits = 64.0*n;
    EXPECT_NEAR(flipped/bits, 0.5, 5*std::sqrt(0.25/bits));
}
