// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// impactFit's measurements checked and split, and the correlations
#include "FitParts.H"

namespace brachDunn
{
namespace fitParts
{

//- Check the measurements; the rebounds, and the number of captures
std::vector<Measurement> rebounds
(
    const std::vector<Measurement>& data,
    int& captured
)
{
    std::vector<Measurement> result;
    captured = 0;
    for (const Measurement& m : data)
    {
        const std::string where = " (line " + std::to_string(m.line) + ")";
        requireInRange
        (
            ("diameter" + where).c_str(), m.d, Particle::minD, Particle::maxD
        );
        requireAboveAtMost
        (
            ("speedIn" + where).c_str(), m.speedIn, 0, ImpactModel::maxSpeed
        );
        requireNonNegative(("speedOut" + where).c_str(), m.speedOut);
        if (m.speedOut > m.speedIn)
        {
            throw InputError
            (
                "speedOut" + where,
                toText(m.speedOut),
                "a rebound cannot be faster than its impact, speedIn = "
              + toText(m.speedIn)
            );
        }
        if (m.speedOut == 0) ++captured;
        else result.push_back(m);
    }
    if (result.empty())
    {
        throw InputError
        (
            "speedOut",
            "0",
            "all " + std::to_string(data.size()) + " impacts are captures:"
            " there is no rebound to fit"
        );
    }
    return result;
}


//- The rebounds split at minSpeed, given or chosen from the data
SpeedSplit splitImpacts
(
    const std::vector<Measurement>& all,
    const FitProblem& problem,
    std::vector<Measurement>& fast,
    std::vector<Measurement>& slow
)
{
    const SpeedSplit split = splitRebounds
    (
        speeds(all), problem.restitution.side(), problem.adhesion.side(),
        problem.s.minSpeed
    );
    for (const Measurement& m : all)
    {
        (m.speedIn > split.minSpeed ? fast : slow).push_back(m);
    }
    return split;
}


//- Pearson's r of measured and fitted values; none when the fitted values
//  are all the same (a constant law: nothing to correlate)
std::optional<double> correlation
(
    const VectorXd& measured,
    const VectorXd& fitted
)
{
    const double range = fitted.maxCoeff() - fitted.minCoeff();
    if (!(range > 1e-12*fitted.cwiseAbs().maxCoeff()))
    {
        return std::nullopt;
    }
    return pearson(measured, fitted);
}

} // End namespace fitParts
} // End namespace brachDunn
