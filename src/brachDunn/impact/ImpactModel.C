// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "ImpactModel.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brachDunn
{

ImpactModel::ImpactModel
(
    const ElasticMaterial& particleMaterial,
    const ElasticMaterial& wallMaterial,
    const RestitutionLaw& restitution,
    const AdhesionLaw& adhesion,
    const FrictionLaw& friction,
    double momentCoeff,
    double minReboundSpeed
)
:
    particleMaterial_(particleMaterial),
    wallMaterial_(wallMaterial),
    restitution_(restitution),
    adhesion_(adhesion),
    friction_(friction),
    momentCoeff_(momentCoeff),
    minReboundSpeed_(minReboundSpeed)
{
    particleMaterial_.check();
    wallMaterial_.check();
    requireInRange("momentCoeff", momentCoeff_, -1, 1);
    requireInRange("minReboundSpeed", minReboundSpeed_, 0, maxSpeed);

    complianceSum_ = particleMaterial_.compliance() + wallMaterial_.compliance();
    contactModulus_ = contactModulus(particleMaterial_, wallMaterial_);
    contactRadiusFactor_ = 15*pi/8*complianceSum_;
}


void ImpactModel::captured
(
    ImpactResult& res,
    const double m,
    const double elasticKE
) const
{
    const double un = res.un, ut = res.ut;
    res.outcome = Fate::capture;
    res.unOut = 0;
    res.utOut = 0;
    res.spinOut = 0;
    res.normalImpulse = m*un;
    res.tangentialImpulse = m*ut;
    // ut/un, without overflowing for a grazing capture
    constexpr double largest = std::numeric_limits<double>::max();
    res.impulseRatio = (un >= 1 || ut <= un*largest) ? ut/un : largest;
    res.adhesionLoss = elasticKE;
    res.frictionLoss = 0.5*m*ut*ut;
    res.energyLoss = 0.5*m*un*un + res.frictionLoss;
}


void ImpactModel::rebound(ImpactResult& res, const Particle& particle) const
{
    const double m = particle.mass(), r = particle.radius();
    const double un = res.un, ut = res.ut;
    res.outcome = Fate::rebound;
    res.normalImpulse = m*(un + res.unOut);

    // The friction law's impulse, at most the m ut that stops the sliding
    res.tangentialImpulse =
        friction_.tangentialImpulse(m, ut, res.normalImpulse);
    res.utOut =
        res.tangentialImpulse < m*ut ? ut - res.tangentialImpulse/m : 0;
    res.impulseRatio = res.tangentialImpulse/res.normalImpulse;

    // Omega = -e_m (omega + r P_t/I), with r P_t/I = (5/2)(ut - Ut')/r
    res.spinOut = -momentCoeff_*(res.spin + 2.5*(ut - res.utOut)/r);

    res.adhesionLoss = -res.WA;
    res.frictionLoss = 0.5*m*(ut*ut - res.utOut*res.utOut);
    res.energyLoss = res.deformationLoss + res.adhesionLoss + res.frictionLoss;
}


ImpactResult ImpactModel::impact
(
    const Particle& particle,
    double un,
    double ut,
    double spin
) const
{
    particle.check();
    requireInRange("un", un, -maxSpeed, maxSpeed);
    requireInRange("ut", ut, 0, maxSpeed);
    requireFinite("spin", spin);

    ImpactResult res;
    res.un = un;
    res.ut = ut;
    res.spin = spin;

    if (!(un > 0))
    {
        // Moving away from (or along) the wall: left alone
        res.outcome = Fate::notApproaching;
        res.unOut = -un;
        res.utOut = ut;
        res.spinOut = spin;
        return res;
    }

    const double m = particle.mass();
    const double r = particle.radius();
    const double normalKE = 0.5*m*un*un;

    res.R = restitution_(un, particle.rho, contactModulus_);
    // The contact radius (a pow) only when there is adhesion to use it
    const AdhesionLaw::Work work =
        adhesion_.as<adhesion::None>()
      ? AdhesionLaw::Work{0, 0}
      : adhesion_(un, contactRadiusSqr(r, normalKE), r);
    res.gamma = work.gamma;
    res.WA = work.WA;

    const double elasticKE = res.R*res.R*normalKE;
    res.deformationLoss = normalKE - elasticKE;

    // WA <= 0, so elasticKE > 0 whenever the rebound energy is positive
    if (elasticKE + res.WA > 0)
    {
        res.unOut = res.R*un*std::sqrt(1 + res.WA/elasticKE);
        res.cause =
            res.unOut < minReboundSpeed_
          ? CaptureCause::reboundFloor
          : CaptureCause::none;
    }
    else
    {
        res.cause = CaptureCause::adhesion;
    }

    if (res.cause != CaptureCause::none)
    {
        captured(res, m, elasticKE);
    }
    else
    {
        rebound(res, particle);
    }
    return res;
}


Impact3D ImpactModel::impact
(
    const Particle& particle,
    const Vector3& U,
    const Vector3& n,
    const Vector3& omega
) const
{
    for (double component : {U.x, U.y, U.z})
    {
        requireFinite("U", component);
    }
    for (double component : {omega.x, omega.y, omega.z})
    {
        requireFinite("omega", component);
    }
    // OpenFOAM's wall normals are unit vectors already: skip the sqrt and
    // the division for them
    const double nMagSqr = dot(n, n);
    Vector3 normal = n;
    if (!(std::abs(nMagSqr - 1) <= 1e-14))     // and NaN
    {
        const double nMag = std::sqrt(nMagSqr);
        requirePositive("|n|", nMag);
        normal = (1/nMag)*n;
    }

    const double Un = dot(U, normal);
    const Vector3 Ut = U - Un*normal;
    const double ut = mag(Ut);

    // The incident plane is spanned by n and t; without tangential motion,
    // by n and the tangential spin, about which the moment coefficient acts
    Vector3 t;
    if (ut > 0)
    {
        t = (1/ut)*Ut;
    }
    else
    {
        const Vector3 spinTangential = omega - dot(omega, normal)*normal;
        const double spinMag = mag(spinTangential);
        if (spinMag > 0)
        {
            t = cross((1/spinMag)*spinTangential, normal);
        }
    }
    const Vector3 b = cross(normal, t);
    const double spin = dot(omega, b);

    Impact3D out;
    out.result = impact(particle, -Un, ut, spin);

    switch (out.result.outcome)
    {
        case Fate::notApproaching:
            out.U = U;
            out.omega = omega;
            break;
        case Fate::rebound:
            out.U = out.result.unOut*normal + out.result.utOut*t;
            out.omega = omega + (out.result.spinOut - spin)*b;
            break;
        case Fate::capture:
        case Fate::escape:
        case Fate::resuspension:
            break;
    }
    return out;
}


HertzContact ImpactModel::hertz(const Particle& particle, double un) const
{
    particle.check();
    requireAboveAtMost("un", un, 0, maxSpeed);

    const double m = particle.mass();
    const double r = particle.radius();
    const double aSqr = contactRadiusSqr(r, 0.5*m*un*un);
    const double approach = aSqr/r;

    return
    {
        m,
        std::sqrt(aSqr),
        approach,
        4.0/3*contactModulus_*std::sqrt(r)*std::pow(approach, 1.5),
        2.94*approach/un
    };
}


AdhesionLaw::Work ImpactModel::measuredAdhesion
(
    const Particle& particle,
    double un,
    double unOut
) const
{
    particle.check();
    requireAboveAtMost("un", un, 0, maxSpeed);
    requireInRange("unOut", unOut, 0, maxSpeed);

    const double m = particle.mass();
    const double r = particle.radius();
    const double normalKE = 0.5*m*un*un;
    const double R = restitution_(un, particle.rho, contactModulus_);
    const double ratio = unOut/un;
    const double WA = normalKE*(ratio*ratio - R*R);

    return {-WA/(pi*contactRadiusSqr(r, normalKE)), WA};
}


double ImpactModel::surfaceEnergy(const Particle& particle, double un) const
{
    particle.check();
    requireAboveAtMost("un", un, 0, maxSpeed);
    const double r = particle.radius();
    return adhesion_
    (
        un, contactRadiusSqr(r, 0.5*particle.mass()*un*un), r
    ).gamma;
}


double ImpactModel::reboundEnergy
(
    const Particle& particle,
    double speed,
    double adhesionScale,
    double* Rptr
) const
{
    const double m = particle.mass();
    const double r = particle.radius();
    const double normalKE = 0.5*m*speed*speed;
    const double R = restitution_(speed, particle.rho, contactModulus_);
    const double WA = adhesion_(speed, contactRadiusSqr(r, normalKE), r).WA;
    if (Rptr) *Rptr = R;
    return R*R*normalKE + adhesionScale*WA;
}


CriticalSpeed ImpactModel::criticalSpeed
(
    const Particle& particle,
    double eta,
    CriticalMethod method
) const
{
    particle.check();
    requireNonNegative("eta", eta);

    const double obliquity = std::sqrt(1 + eta*eta);

    // Rebound energy as a function of the speed searched: the normal speed
    // (consistent) or the total speed with laws at that speed (paper)
    const double adhesionScale =
        method == CriticalMethod::consistent ? 1 : obliquity*obliquity;
    const auto energy = [&](double speed, double* R = nullptr)
    {
        return reboundEnergy(particle, speed, adhesionScale, R);
    };
    const auto result = [&](CriticalSpeed::Status status, double speed)
    {
        double R = 0;
        energy(std::max(speed, CriticalSpeed::minSpeed), &R);
        const double normal =
            method == CriticalMethod::consistent ? speed : speed/obliquity;
        const double total =
            method == CriticalMethod::consistent ? speed*obliquity : speed;
        return CriticalSpeed{status, normal, total, R};
    };

    // Walk up from the bottom of the range to the first rebounding speed,
    // then bisect between it and the captured speed below it
    constexpr double step = 1.0592537251772889;     // 10^(1/40)
    double lower = CriticalSpeed::minSpeed;
    if (energy(lower) > 0)
    {
        return result(CriticalSpeed::Status::neverCaptured, 0);
    }
    double upper = lower*step;
    while (!(energy(upper) > 0))
    {
        lower = upper;
        upper *= step;
        if (upper > CriticalSpeed::maxSpeed)
        {
            return result
            (
                CriticalSpeed::Status::alwaysCaptured, CriticalSpeed::maxSpeed
            );
        }
    }
    for (int iter = 0; iter < 200 && upper - lower > 1e-15*upper; ++iter)
    {
        const double middle = 0.5*(lower + upper);
        (energy(middle) > 0 ? upper : lower) = middle;
    }
    return result(CriticalSpeed::Status::found, 0.5*(lower + upper));
}

} // End namespace brachDunn
