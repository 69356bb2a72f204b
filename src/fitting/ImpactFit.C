#include "ImpactFit.H"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace brachDunn
{

namespace
{

using Eigen::MatrixXd;
using Eigen::VectorXd;

struct LeastSquares
{
    VectorXd theta;
    VectorXd standardErrors;
    VectorXd fitted;
    bool determined;    //!< J^T J of full rank at the solution
};


//- Levenberg-Marquardt on model(theta) against y, with a central
//  difference Jacobian; standard errors from s^2 (J^T J)^-1
LeastSquares levenbergMarquardt
(
    const std::function<VectorXd(const VectorXd&)>& model,
    const VectorXd& y,
    VectorXd theta
)
{
    const int n = y.size(), p = theta.size();
    const auto rss = [&](const VectorXd& t)
    {
        const double s = (model(t) - y).squaredNorm();
        return std::isfinite(s) ? s : HUGE_VAL;
    };
    const auto jacobian = [&](const VectorXd& t)
    {
        MatrixXd J(n, p);
        for (int j = 0; j < p; ++j)
        {
            const double h = 1e-6*std::max(std::abs(t(j)), 1e-3);
            VectorXd up = t, down = t;
            up(j) += h;
            down(j) -= h;
            J.col(j) = (model(up) - model(down))/(2*h);
        }
        return J;
    };

    double lambda = 1e-3;
    double current = rss(theta);
    for (int iter = 0; iter < 500; ++iter)
    {
        const MatrixXd J = jacobian(theta);
        const MatrixXd A = J.transpose()*J;
        const VectorXd g = J.transpose()*(model(theta) - y);
        MatrixXd damped = A;
        damped.diagonal() += lambda*A.diagonal().cwiseMax(1e-300);
        const VectorXd step = -damped.ldlt().solve(g);
        const VectorXd trial = theta + step;
        const double next = rss(trial);
        if (next < current)
        {
            const bool settled =
                step.norm() <= 1e-13*(theta.norm() + 1e-13)
             || current - next <= 1e-16*current;
            theta = trial;
            current = next;
            lambda = std::max(lambda/10, 1e-12);
            if (settled) break;
        }
        else
        {
            lambda *= 10;
            if (lambda > 1e12) break;
        }
    }

    const MatrixXd J = jacobian(theta);
    const Eigen::FullPivLU<MatrixXd> lu(J.transpose()*J);
    if (lu.rank() < p)
    {
        // A coefficient does not move the model (e.g. held at its bound)
        return {theta, VectorXd::Zero(p), model(theta), false};
    }
    const double s2 = n > p ? current/(n - p) : 0;
    const MatrixXd covariance = s2*lu.inverse();
    return {theta, covariance.diagonal().cwiseSqrt(), model(theta), true};
}


double pearson(const VectorXd& a, const VectorXd& b)
{
    const VectorXd da = a.array() - a.mean();
    const VectorXd db = b.array() - b.mean();
    const double denominator = da.norm()*db.norm();
    return denominator > 0 ? da.dot(db)/denominator : 0;
}


//- Keep the law types to the two the fits know
void checkType(const char* keyword, const std::string& type)
{
    if (type != "powerLaw" && type != "constant")
    {
        throw InputError(keyword, type, "valid fits: powerLaw, constant");
    }
}


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


//- Fill a LawFit from fitted parameters. A power law's first coefficient
//  (k or c) was fitted through its logarithm, to stay positive: report it
//  with its delta-method standard error
void report
(
    LawFit& fit,
    const std::string& type,
    const std::vector<std::string>& powerLawNames,
    const std::vector<std::string>& constantNames,
    const VectorXd& theta,
    const VectorXd& standardErrors
)
{
    fit.type = type;
    if (type == "powerLaw")
    {
        const double scale = std::exp(theta(0));
        fit.names = powerLawNames;
        fit.values = {scale, theta(1)};
        fit.standardErrors = {scale*standardErrors(0), standardErrors(1)};
    }
    else
    {
        fit.names = constantNames;
        fit.values = {theta(0)};
        fit.standardErrors = {standardErrors(0)};
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
    checkType("restitution", s.restitutionType);
    checkType("adhesion", s.adhesionType);

    ImpactFitResult result;
    std::vector<Measurement> fast, slow;
    for (const Measurement& m : data)
    {
        const std::string where = " (line " + std::to_string(m.line) + ")";
        requirePositive(("diameter" + where).c_str(), m.d);
        requirePositive(("speedIn" + where).c_str(), m.speedIn);
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
            ++result.captured;
        }
        else
        {
            (m.speedIn > s.minSpeed ? fast : slow).push_back(m);
        }
    }
    if (result.captured == int(data.size()))
    {
        throw InputError
        (
            "speedOut",
            "0",
            "all " + std::to_string(data.size()) + " impacts are captures:"
            " there is no rebound to fit"
        );
    }
    const int restitutionParameters = s.restitutionType == "powerLaw" ? 2 : 1;
    const int adhesionParameters = s.adhesionType == "powerLaw" ? 2 : 1;
    requirePoints
    (
        fast.size(), restitutionParameters,
        "restitution, impacts faster than minSpeed", s.minSpeed
    );
    requirePoints
    (
        slow.size(), adhesionParameters,
        "adhesion, impacts at or below minSpeed", s.minSpeed
    );

    // Current laws; adhesion none until first fitted
    VectorXd restitutionTheta
        = s.restitutionType == "powerLaw" ? VectorXd(2) : VectorXd(1);
    {
        // Start from the mean ratio at the median speed
        std::vector<double> ratios;
        for (const Measurement& m : fast) ratios.push_back(m.speedOut/m.speedIn);
        std::sort(ratios.begin(), ratios.end());
        const double R = std::clamp(ratios[ratios.size()/2], 0.05, 0.99);
        if (restitutionTheta.size() == 2)
        {
            const double v = fast[fast.size()/2].speedIn;
            restitutionTheta << std::log(R*std::pow(v, 0.7)/(1 - R)), 0.7;
        }
        else
        {
            restitutionTheta << R;
        }
    }
    const auto restitutionLaw = [&](const VectorXd& t)
    {
        return
            t.size() == 2
          ? RestitutionLaw::powerLaw(std::exp(t(0)), t(1))
          : RestitutionLaw::constant(std::clamp(t(0), 0.0, 1.0));
    };
    AdhesionLaw adhesion = AdhesionLaw::none();
    VectorXd adhesionTheta;

    LeastSquares restitutionFit, adhesionFit;
    VectorXd previous;
    const int passes = s.refine ? 30 : 1;
    for (int pass = 0; pass < passes; ++pass)
    {
        result.iterations = pass + 1;

        // 1. Restitution from the fast impacts, with the current adhesion
        VectorXd y(fast.size());
        for (std::size_t i = 0; i < fast.size(); ++i)
        {
            y(i) = fast[i].speedOut/fast[i].speedIn;
        }
        const auto ratioModel = [&](const VectorXd& t)
        {
            VectorXd ratio(fast.size());
            if (t.size() == 2 && !(std::abs(t(0)) < 700 && std::abs(t(1)) < 50))
            {
                return VectorXd(VectorXd::Constant(fast.size(), HUGE_VAL));
            }
            try
            {
                const ImpactModel model
                (
                    s.particle, s.wall, restitutionLaw(t), adhesion,
                    FrictionLaw::sticking(), -1, 0
                );
                for (std::size_t i = 0; i < fast.size(); ++i)
                {
                    const Particle p{fast[i].d, s.rho};
                    ratio(i) =
                        model.impact(p, fast[i].speedIn, 0).unOut
                       /fast[i].speedIn;
                }
            }
            catch (const InputError&)
            {
                // A trial step outside the law's range (p < 0): rejected
                ratio.setConstant(HUGE_VAL);
            }
            return ratio;
        };
        restitutionFit = levenbergMarquardt(ratioModel, y, restitutionTheta);
        requireDetermined(restitutionFit, "restitution", s.restitutionType);
        restitutionTheta = restitutionFit.theta;
        result.restitution.correlation = pearson(y, restitutionFit.fitted);
        result.restitution.points = fast.size();

        // 2. gamma of each slow rebounding impact (Eqs. 18, 22), then its law
        const ImpactModel measuring
        (
            s.particle, s.wall, restitutionLaw(restitutionTheta),
            AdhesionLaw::none(), FrictionLaw::sticking(), -1, 0
        );
        result.surfaceEnergies.clear();
        VectorXd un(slow.size()), gamma(slow.size());
        for (std::size_t i = 0; i < slow.size(); ++i)
        {
            un(i) = slow[i].speedIn;
            gamma(i) = measuring.measuredAdhesion
            (
                Particle{slow[i].d, s.rho}, slow[i].speedIn, slow[i].speedOut
            ).gamma;
            result.surfaceEnergies.push_back({un(i), gamma(i)});
        }
        if (adhesionTheta.size() == 0)
        {
            // Start from a log-log line through the positive values
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int count = 0;
            for (int i = 0; i < gamma.size(); ++i)
            {
                if (gamma(i) <= 0) continue;
                const double x = std::log(un(i)), yy = std::log(gamma(i));
                sx += x; sy += yy; sxx += x*x; sxy += x*yy; ++count;
            }
            const double slope =
                count > 1 && count*sxx - sx*sx > 0
              ? (count*sxy - sx*sy)/(count*sxx - sx*sx) : 0.5;
            const double intercept = count ? (sy - slope*sx)/count : -1;
            if (s.adhesionType == "powerLaw")
            {
                adhesionTheta.resize(2);
                adhesionTheta << intercept, slope;
            }
            else
            {
                adhesionTheta = VectorXd::Constant(1, std::max(gamma.mean(), 0.0));
            }
        }
        const auto gammaModel = [&](const VectorXd& t)
        {
            if (t.size() == 2)
            {
                return VectorXd
                (
                    std::exp(t(0))*un.array().pow(t(1))
                );
            }
            return VectorXd(VectorXd::Constant(un.size(), t(0)));
        };
        adhesionFit = levenbergMarquardt(gammaModel, gamma, adhesionTheta);
        requireDetermined(adhesionFit, "adhesion", s.adhesionType);
        adhesionTheta = adhesionFit.theta;
        result.adhesion.correlation = pearson(gamma, adhesionFit.fitted);
        result.adhesion.points = slow.size();
        adhesion =
            s.adhesionType == "powerLaw"
          ? AdhesionLaw::powerLaw(std::exp(adhesionTheta(0)), std::max(adhesionTheta(1), 0.0))
          : AdhesionLaw::constant(std::max(adhesionTheta(0), 0.0));

        // 3. Settled?
        VectorXd all(restitutionTheta.size() + adhesionTheta.size());
        all << restitutionTheta, adhesionTheta;
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

    // 4. Joint fit of both laws to the rebound ratio of every rebounding
    //    impact, from the alternating estimate: the least-squares estimate
    //    proper, with standard errors from the joint covariance
    if (s.refine)
    {
        std::vector<Measurement> rebounds(fast);
        rebounds.insert(rebounds.end(), slow.begin(), slow.end());
        VectorXd y(rebounds.size());
        for (std::size_t i = 0; i < rebounds.size(); ++i)
        {
            y(i) = rebounds[i].speedOut/rebounds[i].speedIn;
        }
        const int nr = restitutionTheta.size(), na = adhesionTheta.size();
        const auto adhesionLaw = [&](const VectorXd& t)
        {
            return
                na == 2
              ? AdhesionLaw::powerLaw(std::exp(t(nr)), std::max(t(nr + 1), 0.0))
              : AdhesionLaw::constant(std::max(t(nr), 0.0));
        };
        const auto jointModel = [&](const VectorXd& t)
        {
            if (nr == 2 && !(std::abs(t(0)) < 700 && std::abs(t(1)) < 50))
            {
                return VectorXd(VectorXd::Constant(rebounds.size(), HUGE_VAL));
            }
            VectorXd ratio(rebounds.size());
            try
            {
                const ImpactModel model
                (
                    s.particle, s.wall, restitutionLaw(t.head(nr)),
                    adhesionLaw(t), FrictionLaw::sticking(), -1, 0
                );
                for (std::size_t i = 0; i < rebounds.size(); ++i)
                {
                    ratio(i) = model.impact
                    (
                        Particle{rebounds[i].d, s.rho}, rebounds[i].speedIn, 0
                    ).unOut/rebounds[i].speedIn;
                }
            }
            catch (const InputError&)
            {
                ratio.setConstant(HUGE_VAL);
            }
            return ratio;
        };
        VectorXd theta(nr + na);
        theta << restitutionTheta, adhesionTheta;
        const LeastSquares joint = levenbergMarquardt(jointModel, y, theta);
        requireDetermined
        (
            joint, "restitution", s.restitutionType + " with adhesion "
          + s.adhesionType + " (joint fit)"
        );
        restitutionTheta = joint.theta.head(nr);
        adhesionTheta = joint.theta.tail(na);
        restitutionFit.standardErrors = joint.standardErrors.head(nr);
        adhesionFit.standardErrors = joint.standardErrors.tail(na);

        // Correlations as the paper reports them: rebound ratio of the fast
        // impacts, and gamma recovered from the slow ones against the law
        const VectorXd fitted = joint.fitted;
        result.restitution.correlation =
            pearson(y.head(fast.size()), fitted.head(fast.size()));
        const ImpactModel measuring
        (
            s.particle, s.wall, restitutionLaw(restitutionTheta),
            AdhesionLaw::none(), FrictionLaw::sticking(), -1, 0
        );
        const AdhesionLaw law = adhesionLaw(joint.theta);
        VectorXd gamma(slow.size()), gammaFitted(slow.size());
        result.surfaceEnergies.clear();
        for (std::size_t i = 0; i < slow.size(); ++i)
        {
            const Particle p{slow[i].d, s.rho};
            gamma(i) = measuring.measuredAdhesion
            (
                p, slow[i].speedIn, slow[i].speedOut
            ).gamma;
            gammaFitted(i) = law(slow[i].speedIn, 1, p.radius()).gamma;
            result.surfaceEnergies.push_back({slow[i].speedIn, gamma(i)});
        }
        result.adhesion.correlation = pearson(gamma, gammaFitted);
    }

    report(result.restitution, s.restitutionType, {"k", "p"}, {"R"},
           restitutionTheta, restitutionFit.standardErrors);
    report(result.adhesion, s.adhesionType, {"c", "n"}, {"gamma"},
           adhesionTheta, adhesionFit.standardErrors);
    return result;
}

} // End namespace brachDunn
