// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// impactFit's fit: the alternating passes and the public functions
#include "FitParts.H"

#include <sstream>

namespace brachDunn
{
namespace fitParts
{

namespace
{

//- gamma of each slow rebound as if the impact were elastic (R = 1): the
//  most adhesion each rebound allows (Eqs. 18 and 22)
std::vector<double> elasticGamma
(
    const FitProblem& problem,
    const std::vector<Measurement>& slow
)
{
    const ImpactModel elastic
    (
        problem.s.particle, problem.s.wall, RestitutionLaw::constant(1),
        AdhesionLaw::none(), FrictionLaw::sticking(), -1, 0
    );
    std::vector<double> gamma;
    for (const Measurement& m : slow)
    {
        gamma.push_back
        (
            elastic.measuredAdhesion
            (
                Particle{m.d, problem.s.rho}, m.speedIn, m.speedOut
            ).gamma
        );
    }
    return gamma;
}

} // End anonymous namespace


// (FitParts.H)
FitState alternatingFit
(
    const FitProblem& problem,
    const std::vector<Measurement>& fast,
    const std::vector<Measurement>& slow,
    ImpactFitResult& result,
    int passes,
    bool adhesionFirst
)
{
    FitState f;
    f.restitutionTheta = problem.restitution.initial
    (
        speeds(fast), values(measuredRatios(fast))
    );
    if (adhesionFirst)
    {
        f.adhesionTheta =
            problem.adhesion.initial(speeds(slow), elasticGamma(problem, slow));
    }
    VectorXd previous;
    for (int pass = 0; pass < passes; ++pass)
    {
        fitRestitution(problem, fast, f, result);
        fitAdhesion(problem, slow, f, result);

        VectorXd all(f.restitutionTheta.size() + f.adhesionTheta.size());
        all << f.restitutionTheta, f.adhesionTheta;
        if
        (
            previous.size() == all.size()
         && (all - previous).norm() <= 1e-10*(all.norm() + 1e-10)
        )
        {
            break;
        }
        previous = all;
    }
    return f;
}

} // End namespace fitParts


using namespace fitParts;


std::string LawFit::dictionary() const
{
    std::ostringstream os;
    os.precision(4);
    os << "{ type " << type << ";";
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        os << " " << names[i] << " " << values[i] << ";";
    }
    os << " }";
    return os.str();
}


ImpactFitResult fitImpacts
(
    const std::vector<Measurement>& data,
    const ImpactFitSettings& s
)
{
    s.particle.check();
    s.wall.check();
    requirePositive("rho", s.rho);
    if (s.minSpeed) requirePositive("minSpeed", *s.minSpeed);
    const FitProblem problem
    {
        s,
        FittedLaw<RestitutionLaw>(s.restitutionType, "restitution"),
        FittedLaw<AdhesionLaw>(s.adhesionType, "adhesion")
    };

    ImpactFitResult result;
    const std::vector<Measurement> all = rebounds(data, result.captured);
    std::vector<Measurement> fast, slow;
    result.split = splitImpacts(all, problem, fast, slow);
    result.rebounds = all.size();
    result.restitution.points = fast.size();
    result.adhesion.points = slow.size();

    const FitState f =
        s.refine
      ? jointFit(problem, fast, slow, result)
      : alternatingFit(problem, fast, slow, result, 1, false);
    problem.restitution.report
    (
        result.restitution, f.restitutionTheta,
        f.restitutionFit.standardErrors, f.restitutionFit.degreesOfFreedom
    );
    problem.adhesion.report
    (
        result.adhesion, f.adhesionTheta, f.adhesionFit.standardErrors,
        f.adhesionFit.degreesOfFreedom
    );
    return result;
}


ImpactModel fittedModel
(
    const ImpactFitResult& fit,
    const ImpactFitSettings& s
)
{
    return ImpactModel
    (
        s.particle, s.wall,
        RestitutionLaw::fitting(fit.restitution.type).law
        (
            fit.restitution.values.data()
        ),
        AdhesionLaw::fitting(fit.adhesion.type).law(fit.adhesion.values.data()),
        FrictionLaw::sticking(), -1, 0
    );
}

} // End namespace brachDunn
