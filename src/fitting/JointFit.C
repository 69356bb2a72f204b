// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// impactFit's joint refit of both laws
#include "FitParts.H"

namespace brachDunn
{
namespace fitParts
{

namespace
{

//- Joint fit of both laws to the rebound ratio of every rebounding impact
//  from a state's parameters, in relative residuals (fitted/measured - 1:
//  the scatter of a measured rebound speed is taken as proportional to it)
LeastSquares jointLeastSquares
(
    const FitProblem& problem,
    const std::vector<Measurement>& all,
    const FitState& f
)
{
    const int nr = f.restitutionTheta.size(), na = f.adhesionTheta.size();
    VectorXd theta(nr + na);
    theta << f.restitutionTheta, f.adhesionTheta;
    const VectorXd measured = measuredRatios(all);
    return levenbergMarquardt
    (
        [&](const VectorXd& t)
        {
            return VectorXd
            (
                problem.evaluate
                (
                    all, t.head(nr), t.tail(na), FitProblem::reboundRatio
                ).cwiseQuotient(measured)
            );
        },
        VectorXd::Ones(all.size()),
        theta,
        [&](const VectorXd& t)
        {
            VectorXd projected(nr + na);
            projected << problem.restitution.project(t.head(nr)),
                problem.adhesion.project(t.tail(na));
            return projected;
        }
    );
}


//- The joint fit from several starts, the one of least residual (from a
//  poor start it can settle where a coefficient meets a bound, such as
//  p = 0 with the adhesion gone): three alternating passes in each order
//  at the split used and at up to 8 others spread over those the data allow
LeastSquares bestJointFit
(
    const FitProblem& problem,
    const std::vector<Measurement>& all,
    double minSpeed,
    int& starts
)
{
    std::vector<double> splits = admissibleSplits
    (
        speeds(all), problem.restitution.side(), problem.adhesion.side(), 8
    );
    splits.insert(splits.begin(), minSpeed);
    std::optional<LeastSquares> best;
    std::vector<std::size_t> slowCounts;
    starts = 0;
    for (const double split : splits)
    {
        std::vector<Measurement> fast, slow;
        for (const Measurement& m : all)
        {
            (m.speedIn > split ? fast : slow).push_back(m);
        }
        if (std::count(slowCounts.begin(), slowCounts.end(), slow.size()))
        {
            continue;   // the same split as one before
        }
        slowCounts.push_back(slow.size());
        for (const bool adhesionFirst : {false, true})
        {
            ImpactFitResult ignored;
            const LeastSquares joint = jointLeastSquares
            (
                problem, all,
                alternatingFit(problem, fast, slow, ignored, 3, adhesionFirst)
            );
            ++starts;
            if
            (
                !best
             || (joint.determined && (!best->determined || joint.rss < best->rss))
            )
            {
                best = joint;
            }
        }
    }
    return *best;
}

} // End anonymous namespace


//- Both laws from the joint fit, with standard errors from its covariance;
//  the correlations as the paper reports them: the rebound ratio of the
//  fast impacts, and gamma recovered from the slow ones against the law
FitState jointFit
(
    const FitProblem& problem,
    const std::vector<Measurement>& fast,
    const std::vector<Measurement>& slow,
    ImpactFitResult& result
)
{
    std::vector<Measurement> all(fast);
    all.insert(all.end(), slow.begin(), slow.end());
    const LeastSquares joint =
        bestJointFit(problem, all, result.split.minSpeed, result.starts);
    requireDetermined
    (
        joint, "restitution", problem.restitution.fitting.type
      + " with adhesion " + problem.adhesion.fitting.type + " (joint fit)",
        "give -restitution constant or -adhesion constant (one coefficient"
        " each), or rebounds over a wider range of speeds"
    );
    result.scatter = std::sqrt(joint.rss/joint.degreesOfFreedom);
    const int nr = problem.restitution.size(), na = problem.adhesion.size();
    FitState f;
    f.restitutionTheta = joint.theta.head(nr);
    f.adhesionTheta = joint.theta.tail(na);
    f.restitutionFit.standardErrors = joint.standardErrors.head(nr);
    f.adhesionFit.standardErrors = joint.standardErrors.tail(na);
    f.restitutionFit.degreesOfFreedom = joint.degreesOfFreedom;
    f.adhesionFit.degreesOfFreedom = joint.degreesOfFreedom;

    const VectorXd fastRatios = measuredRatios(fast);
    result.restitution.correlation = correlation
    (
        fastRatios,
        joint.fitted.head(fast.size()).cwiseProduct(fastRatios).eval()
    );
    result.adhesion.correlation = correlation
    (
        problem.evaluate
        (
            slow, f.restitutionTheta, VectorXd(), FitProblem::measuredGamma
        ),
        problem.evaluate
        (
            slow, f.restitutionTheta, f.adhesionTheta, FitProblem::lawGamma
        )
    );
    return f;
}

} // End namespace fitParts
} // End namespace brachDunn
