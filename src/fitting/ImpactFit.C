// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "ImpactFit.H"
#include "LeastSquares.H"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>

namespace brachDunn
{

namespace
{

using Eigen::VectorXd;

//- The least value of a coefficient fitted through its logarithm whose
//  range starts at 0 (a fit that drives it there finds it undetermined)
constexpr double tinyCoefficient = 1e-200;


//- The law of a family chosen for a fit and its parameters theta: the
//  coefficient values, through their logarithm for those fitted so (to stay
//  positive), as the law type's coefficient table says
template<class Family>
struct FittedLaw
{
    LawFitting<Family> fitting;
    const char* keyword;

    FittedLaw(const std::string& type, const char* keyword)
    :
        fitting(Family::fitting(type, keyword)),
        keyword(keyword)
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

    //- theta within the coefficients' ranges
    VectorXd project(const VectorXd& theta) const
    {
        VectorXd t(theta);
        for (int i = 0; i < size(); ++i)
        {
            const Coefficient& c = fitting.coefficients[i];
            t(i) =
                c.logarithmic
              ? std::clamp
                (
                    t(i),
                    std::log(std::max(c.min, tinyCoefficient)),
                    std::log(c.max)
                )
              : std::clamp(t(i), c.min, c.max);
        }
        return t;
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
    //  reported with its delta-method standard error and an interval
    //  symmetric in its logarithm; intervals within the coefficients'
    //  ranges
    void report
    (
        LawFit& fit,
        const VectorXd& theta,
        const VectorXd& standardErrors,
        int degreesOfFreedom
    ) const
    {
        fit.type = fitting.type;
        fit.values = values(theta);
        fit.degreesOfFreedom = degreesOfFreedom;
        fit.t = studentTQuantile(0.5 + 0.5*confidence, degreesOfFreedom);
        fit.names.clear();
        fit.standardErrors.clear();
        fit.lower.clear();
        fit.upper.clear();
        fit.logarithmic.clear();
        fit.atBound.clear();
        const VectorXd projected = project(VectorXd::Constant(size(), -HUGE_VAL));
        const VectorXd top = project(VectorXd::Constant(size(), HUGE_VAL));
        for (int i = 0; i < size(); ++i)
        {
            const Coefficient& c = fitting.coefficients[i];
            fit.atBound.push_back
            (
                theta(i) <= projected(i) || theta(i) >= top(i)
            );
            const double half = fit.t*standardErrors(i);
            const double scale = c.logarithmic ? fit.values[i] : 1;
            fit.names.push_back(c.name);
            fit.logarithmic.push_back(c.logarithmic);
            fit.standardErrors.push_back(scale*standardErrors(i));
            fit.lower.push_back(std::max(c.min, bound(i, theta(i) - half)));
            fit.upper.push_back(std::min(c.max, bound(i, theta(i) + half)));
        }
    }

    //- A coefficient's value at this parameter
    double bound(int i, double theta) const
    {
        return fitting.coefficients[i].logarithmic ? std::exp(theta) : theta;
    }

    //- The law as a side of the split between fast and slow rebounds
    SplitSide side() const
    {
        return
        {
            std::string(keyword) + " " + fitting.type, size(),
            "-" + std::string(keyword)
        };
    }

    //- What to change when the data do not determine this law
    std::string hint() const
    {
        return
            size() > 1
          ? "give -" + std::string(keyword) + " constant (one coefficient),"
            " or " : std::string("give ");
    }
};


//- An InputError when a fit leaves a coefficient undetermined, under the
//  law's keyword, saying what to change
void requireDetermined
(
    const LeastSquares& fit,
    const char* keyword,
    const std::string& type,
    const std::string& change
)
{
    if (!fit.determined)
    {
        throw InputError
        (
            keyword,
            type,
            "the data do not determine this law's coefficients (they cannot"
            " be told apart, as a power law's c and n when the slow impacts"
            " need no adhesion: c goes to 0 and n has no effect, or speeds"
            " too alike); " + change
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


//- The parameters of both laws and their fits
struct FitState
{
    VectorXd restitutionTheta, adhesionTheta;
    LeastSquares restitutionFit, adhesionFit;
};


//- One law of the alternating passes fitted to its target from its
//  parameters, in its coefficients' ranges; a failure to determine it is an
//  error when final (not refining), saying what to change
template<class Family>
LeastSquares fitLaw
(
    const FitProblem& problem,
    const FittedLaw<Family>& law,
    const std::function<VectorXd(const VectorXd&)>& model,
    const VectorXd& target,
    const VectorXd& theta,
    const char* change
)
{
    LeastSquares fit = levenbergMarquardt
    (
        model, target, theta,
        [&](const VectorXd& t) { return law.project(t); }
    );
    if (!problem.s.refine)
    {
        requireDetermined
        (
            fit, law.keyword, law.fitting.type, law.hint() + change
        );
    }
    return fit;
}


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


//- Alternating passes at a split: the restitution law from the fast
//  impacts with the adhesion found so far, then the adhesion law from the
//  slow ones, until they settle or for so many passes; beginning with the
//  restitution law and no adhesion (the paper's order), or with the
//  adhesion law's initial guess from the slow rebounds taken as elastic
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
