// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// impactFit's restitution fit
#include "FitParts.H"

namespace brachDunn
{
namespace fitParts
{

//- The restitution law fitted to the rebound ratio of the fast impacts,
//  with the adhesion found so far (none at first)
void fitRestitution
(
    const FitProblem& problem,
    const std::vector<Measurement>& fast,
    FitState& f,
    ImpactFitResult& result
)
{
    const VectorXd ratios = measuredRatios(fast);
    f.restitutionFit = fitLaw
    (
        problem, problem.restitution,
        [&](const VectorXd& t)
        {
            return problem.evaluate
            (
                fast, t, f.adhesionTheta, FitProblem::reboundRatio
            );
        },
        ratios, f.restitutionTheta,
        "rebounds faster than minSpeed over a wider range of speeds (a lower"
        " -minSpeed takes in more)"
    );
    f.restitutionTheta = f.restitutionFit.theta;
    result.restitution.correlation =
        correlation(ratios, f.restitutionFit.fitted);
}

} // End namespace fitParts
} // End namespace brachDunn
