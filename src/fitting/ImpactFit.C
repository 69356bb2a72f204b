// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "ImpactFit.H"
#include "LeastSquares.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace brachDunn
{

namespace
{

using Eigen::VectorXd;

//- The law of a family chosen for a fit and its parameters theta: the
//  coefficient values, through their logarithm for those fitted so (to stay
//  positive), as the law type's coefficient table says
template<class Family>
struct FittedLaw
{
    LawFitting<Family> fitting;

    FittedLaw(const std::string& type, const char* keyword)
    :
        fitting(Family::fitting(type, keyword))
    {}

    int size() const { return fitting.coefficients.size(); }

    std::vector<double> values(const VectorXd& theta) const
    {
        std::vector<double> v(size());
        for (int i = 0; i < size(); ++i)
        {
            v[i] =
                fitting.coefficients[i].logarithmic
              ? std::exp(theta(i)) : theta(i);
        }
        return v;
    }

    VectorXd theta(const std::vector<double>& values) const
    {
        VectorXd t(size());
        for (int i = 0; i < size(); ++i)
        {
            t(i) =
                fitting.coefficients[i].logarithmic
              ? std::log(values[i]) : values[i];
        }
        return t;
    }

    //- Whether theta lies in the coefficients' ranges, where the law is
    //  defined (a trial step beyond is rejected)
    bool inRange(const VectorXd& theta) const
    {
        const std::vector<double> v = values(theta);
        for (int i = 0; i < size(); ++i)
        {
            const Coefficient& c = fitting.coefficients[i];
            if (!(std::isfinite(v[i]) && v[i] >= c.min && v[i] <= c.max))
            {
                return false;
            }
        }
        return true;
    }

    Family law(const VectorXd& theta) const
    {
        return fitting.law(values(theta).data());
    }

    //- Starting parameters from (speed, value) samples
    VectorXd initial
    (
        const std::vector<double>& speeds,
        const std::vector<double>& samples
    ) const
    {
        return theta(fitting.initialGuess(speeds, samples));
    }

    //- Fill a LawFit: a coefficient fitted through its logarithm is
    //  reported with its delta-method standard error
    void report
    (
        LawFit& fit,
        const VectorXd& theta,
        const VectorXd& standardErrors
    ) const
    {
        fit.type = fitting.type;
        fit.names.clear();
        fit.values = values(theta);
        fit.standardErrors.clear();
        for (int i = 0; i < size(); ++i)
        {
            fit.names.push_back(fitting.coefficients[i].name);
            fit.standardErrors.push_back
            (
                fitting.coefficients[i].logarithmic
              ? fit.values[i]*standardErrors(i) : standardErrors(i)
            );
        }
    }
};


//- An InputError when a fit leaves a coefficient undetermined
void requireDetermined
(
    const LeastSquares& fit,
    const char* keyword,
    const std::string& type
)
{
    if (!fit.determined)
    {
        throw InputError
        (
            keyword,
            type,
            "the data do not determine this law's coefficients (a best fit"
            " at a bound, such as gamma = 0 when the slow impacts rebound"
            " faster than the restitution law allows); try another law or"
            " minSpeed"
        );
    }
}


void requirePoints
(
    int points,
    int parameters,
    const std::string& what,
    double minSpeed
)
{
    if (points < parameters + 1)
    {
        throw InputError
        (
            "minSpeed",
            toText(minSpeed),
            what + ": " + std::to_string(points) + " rebounding impacts, the"
            " fit needs at least " + std::to_string(parameters + 1)
        );
    }
}


//- The rebound ratios Un'/un measured
VectorXd measuredRatios(const std::vector<Measurement>& impacts)
{
    VectorXd ratios(impacts.size());
    for (std::size_t i = 0; i < impacts.size(); ++i)
    {
        ratios(i) = impacts[i].speedOut/impacts[i].speedIn;
    }
    return ratios;
}


std::vector<double> speeds(const std::vector<Measurement>& impacts)
{
    std::vector<double> v;
    for (const Measurement& m : impacts) v.push_back(m.speedIn);
    return v;
}


std::vector<double> values(const VectorXd& v)
{
    return std::vector<double>(v.data(), v.data() + v.size());
}


//- The laws fitted, the materials, and what the fits compare
struct FitProblem
{
    const ImpactFitSettings& s;
    FittedLaw<RestitutionLaw> restitution;
    FittedLaw<AdhesionLaw> adhesion;

    //- The model of these parameters (no adhesion before its first fit:
    //  an empty adhesion theta), sticking friction, no contact moment, no
    //  rebound floor
    ImpactModel model
    (
        const VectorXd& restitutionTheta,
        const VectorXd& adhesionTheta
    ) const
    {
        return ImpactModel
        (
            s.particle, s.wall, restitution.law(restitutionTheta),
            adhesionTheta.size()
          ? adhesion.law(adhesionTheta) : AdhesionLaw::none(),
            FrictionLaw::sticking(), -1, 0
        );
    }

    //- f(model, particle, speed) of each impact under the laws of these
    //  parameters; HUGE_VAL for every impact when they leave the laws'
    //  ranges (a trial step the fit then rejects)
    template<class Quantity>
    VectorXd evaluate
    (
        const std::vector<Measurement>& impacts,
        const VectorXd& restitutionTheta,
        const VectorXd& adhesionTheta,
        const Quantity& quantity
    ) const
    {
        VectorXd result(impacts.size());
        if
        (
            !restitution.inRange(restitutionTheta)
         || (adhesionTheta.size() && !adhesion.inRange(adhesionTheta))
        )
        {
            return VectorXd::Constant(impacts.size(), HUGE_VAL);
        }
        try
        {
            const ImpactModel m = model(restitutionTheta, adhesionTheta);
            for (std::size_t i = 0; i < impacts.size(); ++i)
            {
                const Measurement& x = impacts[i];
                result(i) = quantity(m, Particle{x.d, s.rho}, x);
            }
        }
        catch (const InputError&)
        {
            result.setConstant(HUGE_VAL);
        }
        return result;
    }

    // What the fits compare, per impact (for evaluate): the model's
    // rebound ratio, gamma from a measured rebound under the restitution
    // law (Eqs. 18 and 22), and the adhesion law's gamma
    static double reboundRatio
    (
        const ImpactModel& m, const Particle& p, const Measurement& x
    )
    {
        return m.impact(p, x.speedIn, 0).unOut/x.speedIn;
    }
    static double measuredGamma
    (
        const ImpactModel& m, const Particle& p, const Measurement& x
    )
    {
        return m.measuredAdhesion(p, x.speedIn, x.speedOut).gamma;
    }
    static double lawGamma
    (
        const ImpactModel& m, const Particle& p, const Measurement& x
    )
    {
        return m.surfaceEnergy(p, x.speedIn);
    }
};


//- Check the measurements; split the rebounds at minSpeed and count the
//  captures
void splitImpacts
(
    const std::vector<Measurement>& data,
    const FitProblem& problem,
    std::vector<Measurement>& fast,
    std::vector<Measurement>& slow,
    int& captured
)
{
    const ImpactFitSettings& s = problem.s;
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
        if (m.speedOut == 0)
        {
            ++captured;
        }
        else
        {
            (m.speedIn > s.minSpeed ? fast : slow).push_back(m);
        }
    }
    if (captured == int(data.size()))
    {
        throw InputError
        (
            "speedOut",
            "0",
            "all " + std::to_string(data.size()) + " impacts are captures:"
            " there is no rebound to fit"
        );
    }
    requirePoints
    (
        fast.size(), problem.restitution.size(),
        "restitution, impacts faster than minSpeed", s.minSpeed
    );
    requirePoints
    (
        slow.size(), problem.adhesion.size(),
        "adhesion, impacts at or below minSpeed", s.minSpeed
    );
}


//- The parameters of both laws and their fits
struct FitState
{
    VectorXd restitutionTheta, adhesionTheta;
    LeastSquares restitutionFit, adhesionFit;
};


//- Alternating passes (one without refine): the restitution law from the
//  fast impacts with the adhesion found so far (none at first), then the
//  adhesion law from the gamma of the slow ones under that restitution
FitState alternatingFit
(
    const FitProblem& problem,
    const std::vector<Measurement>& fast,
    const std::vector<Measurement>& slow,
    ImpactFitResult& result
)
{
    const VectorXd fastRatios = measuredRatios(fast);
    FitState f;
    f.restitutionTheta =
        problem.restitution.initial(speeds(fast), values(fastRatios));
    VectorXd previous;
    for (int pass = 0; pass < (problem.s.refine ? 30 : 1); ++pass)
    {
        result.iterations = pass + 1;
        f.restitutionFit = levenbergMarquardt
        (
            [&](const VectorXd& t)
            {
                return problem.evaluate
                (
                    fast, t, f.adhesionTheta, FitProblem::reboundRatio
                );
            },
            fastRatios,
            f.restitutionTheta
        );
        requireDetermined
        (
            f.restitutionFit, "restitution", problem.restitution.fitting.type
        );
        f.restitutionTheta = f.restitutionFit.theta;
        result.restitution.correlation =
            pearson(fastRatios, f.restitutionFit.fitted);

        const VectorXd gamma = problem.evaluate
        (
            slow, f.restitutionTheta, VectorXd(), FitProblem::measuredGamma
        );
        if (f.adhesionTheta.size() == 0)
        {
            f.adhesionTheta =
                problem.adhesion.initial(speeds(slow), values(gamma));
        }
        f.adhesionFit = levenbergMarquardt
        (
            [&](const VectorXd& t)
            {
                return problem.evaluate
                (
                    slow, f.restitutionTheta, t, FitProblem::lawGamma
                );
            },
            gamma,
            f.adhesionTheta
        );
        requireDetermined
        (
            f.adhesionFit, "adhesion", problem.adhesion.fitting.type
        );
        f.adhesionTheta = f.adhesionFit.theta;
        result.adhesion.correlation = pearson(gamma, f.adhesionFit.fitted);

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


//- Joint fit of both laws to the rebound ratio of every rebounding impact,
//  from the alternating estimate: the least-squares estimate proper, with
//  standard errors from the joint covariance
void jointFit
(
    const FitProblem& problem,
    const std::vector<Measurement>& fast,
    const std::vector<Measurement>& slow,
    FitState& f,
    ImpactFitResult& result
)
{
    std::vector<Measurement> rebounds(fast);
    rebounds.insert(rebounds.end(), slow.begin(), slow.end());
    const int nr = f.restitutionTheta.size(), na = f.adhesionTheta.size();
    VectorXd theta(nr + na);
    theta << f.restitutionTheta, f.adhesionTheta;
    const LeastSquares joint = levenbergMarquardt
    (
        [&](const VectorXd& t)
        {
            return problem.evaluate
            (
                rebounds, t.head(nr), t.tail(na), FitProblem::reboundRatio
            );
        },
        measuredRatios(rebounds),
        theta
    );
    requireDetermined
    (
        joint, "restitution", problem.restitution.fitting.type
      + " with adhesion " + problem.adhesion.fitting.type + " (joint fit)"
    );
    f.restitutionTheta = joint.theta.head(nr);
    f.adhesionTheta = joint.theta.tail(na);
    f.restitutionFit.standardErrors = joint.standardErrors.head(nr);
    f.adhesionFit.standardErrors = joint.standardErrors.tail(na);

    // Correlations as the paper reports them: rebound ratio of the fast
    // impacts, and gamma recovered from the slow ones against the law
    result.restitution.correlation =
        pearson(measuredRatios(fast), joint.fitted.head(fast.size()));
    result.adhesion.correlation = pearson
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
}

} // End anonymous namespace


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
    requirePositive("minSpeed", s.minSpeed);
    const FitProblem problem
    {
        s,
        FittedLaw<RestitutionLaw>(s.restitutionType, "restitution"),
        FittedLaw<AdhesionLaw>(s.adhesionType, "adhesion")
    };

    ImpactFitResult result;
    std::vector<Measurement> fast, slow;
    splitImpacts(data, problem, fast, slow, result.captured);

    FitState f = alternatingFit(problem, fast, slow, result);
    result.restitution.points = fast.size();
    result.adhesion.points = slow.size();
    if (s.refine)
    {
        jointFit(problem, fast, slow, f, result);
    }
    problem.restitution.report
    (
        result.restitution, f.restitutionTheta, f.restitutionFit.standardErrors
    );
    problem.adhesion.report
    (
        result.adhesion, f.adhesionTheta, f.adhesionFit.standardErrors
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
