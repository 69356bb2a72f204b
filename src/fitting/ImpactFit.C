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


//- The restitution law of fitted parameters: (log k, p) or (R)
RestitutionLaw restitutionLaw(const VectorXd& theta)
{
    return
        theta.size() == 2
      ? RestitutionLaw::powerLaw(std::exp(theta(0)), theta(1))
      : RestitutionLaw::constant(std::clamp(theta(0), 0.0, 1.0));
}


//- The adhesion law of fitted parameters: (log c, n) or (gamma); none
//  before the first fit
AdhesionLaw adhesionLaw(const VectorXd& theta)
{
    if (theta.size() == 0) return AdhesionLaw::none();
    return
        theta.size() == 2
      ? AdhesionLaw::powerLaw(std::exp(theta(0)), std::max(theta(1), 0.0))
      : AdhesionLaw::constant(std::max(theta(0), 0.0));
}


//- The model's rebound ratio of each impact for the laws of these
//  parameters; HUGE_VAL for every impact when a trial step leaves the
//  laws' range (p < 0, or an exponent that would overflow)
VectorXd modelRatios
(
    const std::vector<Measurement>& impacts,
    const VectorXd& restitutionTheta,
    const VectorXd& adhesionTheta,
    const ImpactFitSettings& s
)
{
    VectorXd ratios(impacts.size());
    for (const VectorXd* theta : {&restitutionTheta, &adhesionTheta})
    {
        if (theta->size() == 2 && !((*theta)(0) < 700 && std::abs((*theta)(1)) < 50))
        {
            return VectorXd::Constant(impacts.size(), HUGE_VAL);
        }
    }
    try
    {
        const ImpactModel model
        (
            s.particle, s.wall, restitutionLaw(restitutionTheta),
            adhesionLaw(adhesionTheta), FrictionLaw::sticking(), -1, 0
        );
        for (std::size_t i = 0; i < impacts.size(); ++i)
        {
            const Measurement& m = impacts[i];
            ratios(i) = model.impact(Particle{m.d, s.rho}, m.speedIn, 0).unOut/m.speedIn;
        }
    }
    catch (const InputError&)
    {
        ratios.setConstant(HUGE_VAL);
    }
    return ratios;
}


//- gamma of each rebounding impact from its measured rebound (Eqs. 18 and
//  22) under the restitution law of these parameters
VectorXd measuredSurfaceEnergies
(
    const std::vector<Measurement>& impacts,
    const VectorXd& restitutionTheta,
    const ImpactFitSettings& s
)
{
    const ImpactModel measuring
    (
        s.particle, s.wall, restitutionLaw(restitutionTheta),
        AdhesionLaw::none(), FrictionLaw::sticking(), -1, 0
    );
    VectorXd gamma(impacts.size());
    for (std::size_t i = 0; i < impacts.size(); ++i)
    {
        const Measurement& m = impacts[i];
        gamma(i) = measuring.measuredAdhesion
        (
            Particle{m.d, s.rho}, m.speedIn, m.speedOut
        ).gamma;
    }
    return gamma;
}


//- gamma of the adhesion law of these parameters at each speed
VectorXd lawSurfaceEnergies(const VectorXd& theta, const VectorXd& un)
{
    if (theta.size() == 2)
    {
        return VectorXd(std::exp(theta(0))*un.array().pow(theta(1)));
    }
    return VectorXd::Constant(un.size(), theta(0));
}


//- Starting restitution parameters: the median ratio at the median speed
VectorXd initialRestitution
(
    const std::vector<Measurement>& fast,
    const std::string& type
)
{
    std::vector<double> ratios;
    for (const Measurement& m : fast) ratios.push_back(m.speedOut/m.speedIn);
    std::sort(ratios.begin(), ratios.end());
    const double R = std::clamp(ratios[ratios.size()/2], 0.05, 0.99);
    if (type == "powerLaw")
    {
        const double v = fast[fast.size()/2].speedIn;
        return (VectorXd(2) << std::log(R*std::pow(v, 0.7)/(1 - R)), 0.7).finished();
    }
    return VectorXd::Constant(1, R);
}


//- Starting adhesion parameters: a log-log line through the positive
//  values, or their mean
VectorXd initialAdhesion
(
    const VectorXd& un,
    const VectorXd& gamma,
    const std::string& type
)
{
    if (type != "powerLaw")
    {
        return VectorXd::Constant(1, std::max(gamma.mean(), 0.0));
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int count = 0;
    for (int i = 0; i < gamma.size(); ++i)
    {
        if (gamma(i) <= 0) continue;
        const double x = std::log(un(i)), y = std::log(gamma(i));
        sx += x; sy += y; sxx += x*x; sxy += x*y; ++count;
    }
    const double slope =
        count > 1 && count*sxx - sx*sx > 0
      ? (count*sxy - sx*sy)/(count*sxx - sx*sx) : 0.5;
    const double intercept = count ? (sy - slope*sx)/count : -1;
    return (VectorXd(2) << intercept, slope).finished();
}


//- Check the measurements; split the rebounds at minSpeed and count the
//  captures
void splitImpacts
(
    const std::vector<Measurement>& data,
    const ImpactFitSettings& s,
    std::vector<Measurement>& fast,
    std::vector<Measurement>& slow,
    int& captured
)
{
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
        fast.size(), s.restitutionType == "powerLaw" ? 2 : 1,
        "restitution, impacts faster than minSpeed", s.minSpeed
    );
    requirePoints
    (
        slow.size(), s.adhesionType == "powerLaw" ? 2 : 1,
        "adhesion, impacts at or below minSpeed", s.minSpeed
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
    checkType("restitution", s.restitutionType);
    checkType("adhesion", s.adhesionType);

    ImpactFitResult result;
    std::vector<Measurement> fast, slow;
    splitImpacts(data, s, fast, slow, result.captured);

    const VectorXd fastRatios = measuredRatios(fast);
    VectorXd slowSpeeds(slow.size());
    for (std::size_t i = 0; i < slow.size(); ++i)
    {
        slowSpeeds(i) = slow[i].speedIn;
    }

    // Alternating passes (one without refine): the restitution law from the
    // fast impacts with the adhesion found so far (none at first), then the
    // adhesion law from the gamma of the slow ones under that restitution
    VectorXd restitutionTheta = initialRestitution(fast, s.restitutionType);
    VectorXd adhesionTheta;
    LeastSquares restitutionFit, adhesionFit;
    VectorXd previous;
    for (int pass = 0; pass < (s.refine ? 30 : 1); ++pass)
    {
        result.iterations = pass + 1;

        restitutionFit = levenbergMarquardt
        (
            [&](const VectorXd& t)
            {
                return modelRatios(fast, t, adhesionTheta, s);
            },
            fastRatios,
            restitutionTheta
        );
        requireDetermined(restitutionFit, "restitution", s.restitutionType);
        restitutionTheta = restitutionFit.theta;
        result.restitution.correlation =
            pearson(fastRatios, restitutionFit.fitted);

        const VectorXd gamma =
            measuredSurfaceEnergies(slow, restitutionTheta, s);
        if (adhesionTheta.size() == 0)
        {
            adhesionTheta = initialAdhesion(slowSpeeds, gamma, s.adhesionType);
        }
        adhesionFit = levenbergMarquardt
        (
            [&](const VectorXd& t) { return lawSurfaceEnergies(t, slowSpeeds); },
            gamma,
            adhesionTheta
        );
        requireDetermined(adhesionFit, "adhesion", s.adhesionType);
        adhesionTheta = adhesionFit.theta;
        result.adhesion.correlation = pearson(gamma, adhesionFit.fitted);

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
    result.restitution.points = fast.size();
    result.adhesion.points = slow.size();

    // Joint fit of both laws to the rebound ratio of every rebounding
    // impact, from the alternating estimate: the least-squares estimate
    // proper, with standard errors from the joint covariance
    if (s.refine)
    {
        std::vector<Measurement> rebounds(fast);
        rebounds.insert(rebounds.end(), slow.begin(), slow.end());
        const int nr = restitutionTheta.size(), na = adhesionTheta.size();
        VectorXd theta(nr + na);
        theta << restitutionTheta, adhesionTheta;
        const LeastSquares joint = levenbergMarquardt
        (
            [&](const VectorXd& t)
            {
                return modelRatios(rebounds, t.head(nr), t.tail(na), s);
            },
            measuredRatios(rebounds),
            theta
        );
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
        result.restitution.correlation =
            pearson(fastRatios, joint.fitted.head(fast.size()));
        result.adhesion.correlation = pearson
        (
            measuredSurfaceEnergies(slow, restitutionTheta, s),
            lawSurfaceEnergies(adhesionTheta, slowSpeeds)
        );
    }

    report(result.restitution, s.restitutionType, {"k", "p"}, {"R"},
           restitutionTheta, restitutionFit.standardErrors);
    report(result.adhesion, s.adhesionType, {"c", "n"}, {"gamma"},
           adhesionTheta, adhesionFit.standardErrors);
    return result;
}

ImpactModel fittedModel
(
    const ImpactFitResult& fit,
    const ImpactFitSettings& s
)
{
    // The fits' parameters: the first coefficient of a power law by its
    // logarithm
    const auto theta = [](const LawFit& law)
    {
        VectorXd t = Eigen::Map<const VectorXd>(law.values.data(), law.values.size());
        if (law.type == "powerLaw") t(0) = std::log(t(0));
        return t;
    };
    return ImpactModel
    (
        s.particle, s.wall, restitutionLaw(theta(fit.restitution)),
        adhesionLaw(theta(fit.adhesion)), FrictionLaw::sticking(), -1, 0
    );
}

} // End namespace brachDunn
