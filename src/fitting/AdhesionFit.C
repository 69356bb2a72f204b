// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// impactFit's adhesion fit
#include "FitParts.H"

namespace brachDunn
{
namespace fitParts
{

//- The adhesion law fitted to gamma of the slow rebounds under the
//  restitution law found (Eqs. 18 and 22)
void fitAdhesion
(
    const FitProblem& problem,
    const std::vector<Measurement>& slow,
    FitState& f,
    ImpactFitResult& result
)
{
    const VectorXd gamma = problem.evaluate
    (
        slow, f.restitutionTheta, VectorXd(), FitProblem::measuredGamma
    );
    if (f.adhesionTheta.size() == 0)
    {
        f.adhesionTheta = problem.adhesion.initial(speeds(slow), values(gamma));
    }
    const VectorXd& restitutionTheta = f.restitutionTheta;
    f.adhesionFit = fitLaw
    (
        problem, problem.adhesion,
        [&](const VectorXd& t)
        {
            return problem.evaluate
            (
                slow, restitutionTheta, t, FitProblem::lawGamma
            );
        },
        gamma, f.adhesionTheta,
        "rebounds at or below minSpeed at more speeds (a higher -minSpeed"
        " takes in more)"
    );
    f.adhesionTheta = f.adhesionFit.theta;
    result.adhesion.correlation = correlation(gamma, f.adhesionFit.fitted);
}

} // End namespace fitParts
} // End namespace brachDunn
