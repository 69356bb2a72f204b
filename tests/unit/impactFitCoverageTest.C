// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Whether impactFit's 95 % intervals cover the true coefficients about as
// often as they claim, on small synthetic data sets made by the core from
// known coefficients with measurement-like scatter, fitted with impactFit's
// defaults (split chosen from the data, joint fit).
//
// Each set (fixed seed): 8 to 20 normal impacts, speeds spread over
// 0.5-50 m/s (one in each of as many equal steps of log speed, at random
// within it), each of a Figure 5 diameter at random, the rebound speed
// multiplied by (1 + 0.02 N(0, 1)); a capture is a 0.
//
// Measured on 2026-11-24 (200 sets each, seeds 1000-1199):
//   Eqs. 23, 24 (k 45.3, p 0.718, c 0.34, n 0.5): 194 sets fitted, 6 refused
//   for too few rebounds (5 or fewer, where two power laws need 6);
//   coverage k 185/194 = 0.954, p 0.954, c 0.959, n 0.943
//   constant R 0.85, gamma 0.6: 200 fitted; coverage R 0.940, gamma 0.930
// and over 1000 sets (seeds 1000-1999): k 0.941, p 0.946, c 0.950,
// n 0.958 (974 fitted; 25 refused for too few rebounds, 1 of 6 rebounds as
// undetermined by the joint fit); R 0.951, gamma 0.952.
// Two choices of the fit make these honest (measured while making them):
// the joint fit's residuals are relative, as the scatter is (unweighted, R
// was covered in 0.930 and gamma in 0.967 of 300 sets: the fast rebounds,
// which fix R, scatter more than the pooled s^2 says, the slow ones less);
// and the joint fit is started from several points and kept within the
// coefficients' ranges step by step (from the paper's alternating passes
// alone, 17 of 200 sets ended where p = 0 with the adhesion gone, far from
// the least residual, and k was covered in 0.874).

#include "ImpactFit.H"
#include "testCases.H"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

using namespace brachDunn;
using namespace brachDunn::testCases;

namespace
{

std::vector<Measurement> smallSet(const ImpactModel& model, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal(0, 1);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::uniform_int_distribution<int> diameter(0, 3);
    const double diameters[] = {2.58e-6, 3.44e-6, 4.90e-6, 6.89e-6};
    const int n = std::uniform_int_distribution<int>(8, 20)(rng);
    std::vector<Measurement> data;
    for (int i = 0; i < n; ++i)
    {
        const double v = 0.5*std::pow(100.0, (i + uniform(rng))/n);
        const double d = diameters[diameter(rng)];
        const ImpactResult r = model.impact(Particle{d, 1350}, v, 0);
        const double out = r.captured() ? 0 : r.unOut*(1 + 0.02*normal(rng));
        data.push_back({d, v, std::min(out, v), i + 2});
    }
    return data;
}


struct Coverage
{
    int sets = 0;
    int fitted = 0;
    std::map<std::string, int> refused;     //!< by the error's keyword
    std::vector<int> covered;
};


//- Fit each set with the defaults and count how often each coefficient's
//  95 % interval holds the truth
Coverage coverage
(
    const ImpactModel& model,
    const std::vector<double>& truth,
    const std::string& restitutionType,
    const std::string& adhesionType,
    int sets
)
{
    ImpactFitSettings s;
    s.particle = fluorescein;
    s.wall = molybdenum;
    s.rho = 1350;
    s.restitutionType = restitutionType;
    s.adhesionType = adhesionType;
    Coverage c;
    c.sets = sets;
    c.covered.assign(truth.size(), 0);
    for (int k = 0; k < sets; ++k)
    {
        try
        {
            const ImpactFitResult fit = fitImpacts(smallSet(model, 1000 + k), s);
            ++c.fitted;
            std::size_t i = 0;
            for (const LawFit* law : {&fit.restitution, &fit.adhesion})
            {
                for (std::size_t j = 0; j < law->values.size(); ++j, ++i)
                {
                    c.covered[i] +=
                        law->lower[j] <= truth[i] && truth[i] <= law->upper[j];
                }
            }
        }
        catch (const InputError& err)
        {
            ++c.refused[err.keyword()];
        }
    }
    return c;
}


void expectHonest(const Coverage& c, const std::vector<std::string>& names)
{
    EXPECT_GE(c.fitted, 100);
    // Refused: too few rebounds for the laws (the sets of 8 impacts with
    // 3 captures), or, in at most 1 % of the sets (at 6 or 7 rebounds for 4
    // coefficients), a joint fit that ends at a coefficient's bound from
    // every start
    std::cout << "    " << c.fitted << " of " << c.sets << " sets fitted\n";
    for (const auto& [keyword, count] : c.refused)
    {
        std::cout << "    " << count << " refused under " << keyword << '\n';
        EXPECT_TRUE(keyword == "rebounds" || keyword == "restitution")
            << keyword;
        EXPECT_LE(count, (keyword == "rebounds" ? 0.05 : 0.01)*c.sets)
            << keyword;
    }
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        const double fraction = double(c.covered[i])/c.fitted;
        std::cout << "    " << names[i] << ": 95 % interval covers the truth"
            << " in " << c.covered[i] << " of " << c.fitted << " sets ("
            << fraction << ")\n";
        EXPECT_GE(fraction, 0.90) << names[i];
        EXPECT_LE(fraction, 0.99) << names[i];
    }
}

} // End anonymous namespace


TEST(ImpactFitCoverage, PowerLawsOfThePaper)
{
    const Coverage c =
        coverage(paperModel(), {45.3, 0.718, 0.34, 0.5}, "powerLaw", "powerLaw", 200);
    expectHonest(c, {"k", "p", "c", "n"});
}


TEST(ImpactFitCoverage, ConstantLaws)
{
    const ImpactModel model = paperModel
    (
        RestitutionLaw::constant(0.85), AdhesionLaw::constant(0.6)
    );
    const Coverage c = coverage(model, {0.85, 0.6}, "constant", "constant", 200);
    expectHonest(c, {"R", "gamma"});
}
