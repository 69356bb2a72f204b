// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "NearWallDispersionForce.H"
#include "CounterRandom.H"
#include "carrierTurbulence.H"
#include "checkedInput.H"
#include "fvcGrad.H"
#include "gasState.H"
#include "releaseCompat.H"
#include "wallPolyPatch.H"

#include COMPAT_TURBULENCE_MODEL_H

namespace Foam
{
namespace nearWallDispersion
{

inline brachDunn::Vector3 toCore(const vector& v)
{
    return {v.x(), v.y(), v.z()};
}

inline vector toFoam(const brachDunn::Vector3& v)
{
    return vector(v.x, v.y, v.z);
}

} // End namespace nearWallDispersion
} // End namespace Foam


template<class CloudType>
Foam::NearWallDispersionForce<CloudType>::NearWallDispersionForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    seed_(0),
    units_(nullptr),
    checked_(false),
    leastSubSteps_(0)
{
    const dictionary& coeffs = checkedInput::withKnownKeywords
    (
        this->coeffs(),
        {
            "seed", "blendFrom", "blendTo", "C0", "crossing",
            "timeFraction", "rmsChange", "maxSubSteps"
        },
        "nearWallDispersion"
    );
    seed_ = checkedInput::readCount(coeffs, "seed", 0);
    settings_.blendFrom =
        checkedInput::readNumber(coeffs, "blendFrom", settings_.blendFrom);
    settings_.blendTo =
        checkedInput::readNumber(coeffs, "blendTo", settings_.blendTo);
    settings_.C0 = checkedInput::readNumber(coeffs, "C0", settings_.C0);
    settings_.crossing =
        checkedInput::readNumber(coeffs, "crossing", settings_.crossing);
    path_.timeFraction =
        checkedInput::readNumber(coeffs, "timeFraction", path_.timeFraction);
    path_.rmsChange =
        checkedInput::readNumber(coeffs, "rmsChange", path_.rmsChange);
    path_.maxSubSteps = static_cast<int>
    (
        checkedInput::readCount(coeffs, "maxSubSteps", path_.maxSubSteps)
    );
    checkedInput::coreCall(coeffs, [&] { settings_.check(); });
    checkedInput::coreCall(coeffs, [&] { path_.check(); });
    Info<< "    nearWallDispersion: seed " << label(seed_)
        << ", blend y+ " << settings_.blendFrom << " to "
        << settings_.blendTo << ", C0 " << settings_.C0
        << ", crossing " << settings_.crossing
        << ", timeFraction " << path_.timeFraction
        << ", rmsChange " << path_.rmsChange
        << ", maxSubSteps " << path_.maxSubSteps << endl;
}


template<class CloudType>
Foam::NearWallDispersionForce<CloudType>::NearWallDispersionForce
(
    const NearWallDispersionForce& f
)
:
    ParticleForce<CloudType>(f),
    seed_(f.seed_),
    settings_(f.settings_),
    path_(f.path_),
    units_(nullptr),
    checked_(false),
    walks_(),
    leastSubSteps_(0)
{}


template<class CloudType>
void Foam::NearWallDispersionForce<CloudType>::cacheFields(const bool store)
{
    walks_.clear();
    if (!store)
    {
        reportLeastSubSteps();
        k_.clear();
        epsilon_.clear();
        gradK_.clear();
        return;
    }
    const CloudType& cloud = this->owner();
    const carrierTurbulence turbulence(cloud.U());
    const word type =
        turbulence.model()
      ? turbulence.model()->template lookupOrDefault<word>
        (
            "simulationType", "laminar"
        )
      : word("none");
    if (type != "RAS")
    {
        FatalErrorInFunction
            << "nearWallDispersion takes k and epsilon of the carrier "
            << "flow's RAS model: the carrier of cloud " << cloud.name()
            << " has a turbulence model of simulationType " << type
            << exit(FatalError);
    }
    bool walls = false;
    for (const fvPatch& patch : this->mesh().boundary())
    {
        walls = walls || isA<wallPolyPatch>(patch.patch());
    }
    if (!returnReduce(walls, orOp<bool>()))
    {
        FatalErrorInFunction
            << "nearWallDispersion needs a wall patch: the mesh of cloud "
            << cloud.name() << " has none" << exit(FatalError);
    }
    if (this->mesh().moving())
    {
        FatalErrorInFunction
            << "nearWallDispersion takes the walls' distances, normals and "
            << "friction velocities computed once per carrier velocity "
            << "field: the mesh of cloud " << cloud.name() << " moves. "
            << "Run it on a static mesh" << exit(FatalError);
    }
    units_ = &wallUnits::New(cloud.U(), cloud.rho(), cloud.mu());
    k_ = turbulence.model()->k();
    epsilon_ = turbulence.model()->epsilon();
    gradK_ = fvc::grad(k_());
    checkFlow();
}


template<class CloudType>
brachDunn::FlowAtParticle
Foam::NearWallDispersionForce<CloudType>::flowAt
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar muc,
    const scalar tauP,
    brachDunn::WallFrame& frame
) const
{
    using namespace nearWallDispersion;
    const fvMesh& mesh = this->mesh();
    const label celli = p.cell();
    const vector offset =
        compat::position(p, mesh) - mesh.cellCentres()[celli];
    const vector& n = units_->normal()[celli];
    frame = brachDunn::WallFrame::of(toCore(n), toCore(td.Uc()));
    const scalar y = max(units_->y()[celli] + (offset & n), scalar(0));
    const scalar uStar = units_->uStar()[celli];
    const scalar nu = muc/td.rhoc();
    // The mean slip of crossing trajectories (Csanady 1963): the settling
    // drift tau_p (1 - rho_c/rho_p) g, not the instantaneous relative
    // velocity, which holds the fluctuation itself and would make the time
    // scale depend on it
    const vector slip =
        tauP*(1 - td.rhoc()/p.rho())*this->owner().g().value();
    // k at the parcel by the cell's gradient, not yet bounded (the walk
    // takes it on to where it starts and bounds it once there), and the
    // cell's epsilon
    const vector& gradK = gradK_()[celli];
    return
    {
        y*uStar/nu,
        uStar,
        nu,
        k_()[celli] + (gradK & offset),
        epsilon_()[celli],
        frame.local(toCore(gradK)),
        frame.local(toCore(slip))
    };
}


template<class CloudType>
brachDunn::PathStep Foam::NearWallDispersionForce<CloudType>::walk
(
    const typename CloudType::parcelType& p,
    brachDunn::FlowAtParticle flow,
    const brachDunn::WallFrame& frame,
    const scalar tauP,
    const scalar normalVelocity,
    const label stepIndex
) const
{
    using namespace nearWallDispersion;
    const std::uint64_t step = static_cast<std::uint64_t>(stepIndex);
    const std::uint64_t proc =
        static_cast<std::uint64_t>(static_cast<std::int64_t>(p.origProc()));
    const std::uint64_t id =
        static_cast<std::uint64_t>(static_cast<std::int64_t>(p.origId()));

    // The state: w at the walk's start (UTurb, its components along the
    // wall's frame's axes given as a global vector, so that a parcel whose
    // nearest wall changes keeps the direction of its fluctuation) and the
    // wall distance there (tTurb > 0: where the parcel ended its last
    // step); 0 a new parcel (w drawn from the stationary law); < 0 (an
    // earlier version's completed step) the walk starts where it is
    vector& w = compat::walkVector(p);
    scalar& start = compat::walkScalar(p);
    const scalar y = flow.yPlus*flow.nu/flow.uStar;
    if (start == 0)
    {
        brachDunn::CounterRandom random(seed_, proc, id, 2*step + 1);
        w = vector(random.normal(), random.normal(), random.normal());
    }
    if (start <= 0)
    {
        start = max(y, VSMALL);
    }
    // k at the start, along the wall normal from the parcel, at least a
    // thousandth of the cell's (bounded once, here), epsilon keeping the
    // cell's k/epsilon
    const scalar kCell = k_()[p.cell()];
    flow.k = max(flow.k + flow.gradK.y*(start - y), 1e-3*kCell);
    if (kCell > 0)
    {
        flow.epsilon *= flow.k/kCell;
    }
    flow.yPlus = start*flow.uStar/flow.nu;

    // The walk's numbers are keyed on the index of the time step it is
    // taken in (restored on a restart from uniform/time): the walk that the
    // step completing before it predicts is the one it takes
    brachDunn::CounterRandom random(seed_, proc, id, 2*step);
    const scalar trackTime = this->owner().solution().trackTime();
    return checkedInput::coreCall
    (
        this->coeffs(),
        [&]
        {
            return brachDunn::seenVelocityPath
            (
                {frame.local(toCore(w)), normalVelocity, tauP, frame},
                flow,
                settings_, path_,
                trackTime, random
            );
        }
    );
}


template<class CloudType>
std::uint64_t Foam::NearWallDispersionForce<CloudType>::walkKey
(
    const typename CloudType::parcelType& p
)
{
    return
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.origProc()))
        << 32)
      | static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.origId()));
}


template<class CloudType>
const brachDunn::PathStep&
Foam::NearWallDispersionForce<CloudType>::walkOfSubStep
(
    const typename CloudType::parcelType& p,
    const scalar dt,
    const brachDunn::FlowAtParticle& flow,
    const brachDunn::WallFrame& frame,
    const scalar tauP,
    const scalar normalVelocity
) const
{
    const std::uint64_t key = walkKey(p);
    const scalar startFraction = subStepStart(p, dt);
    // A sub-step of the rounding after the step completed takes the next
    // step's walk (the one its completion started)
    const bool completed = startFraction >= stepEnd;
    auto found = walks_.find(key);
    if
    (
        found == walks_.end()
     || found->second.cell != p.cell()
     || mag(found->second.endFraction - startFraction) > 1e-12
    )
    {
        lastWalk last
        {
            p.cell(), 0,
            walk
            (
                p, flow, frame, tauP, normalVelocity,
                this->mesh().time().timeIndex() + (completed ? 1 : 0)
            )
        };
        found = walks_.insert_or_assign(key, last).first;
    }
    found->second.endFraction = p.stepFraction();
    return found->second.walked;
}


template<class CloudType>
bool Foam::NearWallDispersionForce<CloudType>::completesStep
(
    const typename CloudType::parcelType& p,
    const scalar dt
) const
{
    // The sub-step that reaches the step's end, not one of the rounding
    // left after it
    return p.stepFraction() >= stepEnd && subStepStart(p, dt) < stepEnd;
}


template<class CloudType>
Foam::scalar Foam::NearWallDispersionForce<CloudType>::subStepStart
(
    const typename CloudType::parcelType& p,
    const scalar dt
) const
{
    return p.stepFraction() - dt/this->owner().solution().trackTime();
}


template<class CloudType>
Foam::vector Foam::NearWallDispersionForce<CloudType>::startNextStep
(
    const typename CloudType::parcelType& p,
    const brachDunn::FlowAtParticle& flow,
    const brachDunn::WallFrame& frame,
    const scalar tauP,
    const scalar normalVelocity,
    const brachDunn::PathStep& walked
) const
{
    using namespace nearWallDispersion;
    // The end's w and the wall distance where the step ends are the next
    // step's state; the parcel goes into the next step with the mean of
    // the walk from there (the next step takes that walk again at its
    // first sub-step, from the same state with the same numbers)
    compat::walkVector(p) = toFoam(frame.global(walked.w));
    compat::walkScalar(p) = max(flow.yPlus*flow.nu/flow.uStar, VSMALL);
    const brachDunn::PathStep next = walk
    (
        p, flow, frame, tauP, normalVelocity,
        this->mesh().time().timeIndex() + 1
    );
    walks_.insert_or_assign
    (
        walkKey(p), lastWalk{p.cell(), p.stepFraction(), next}
    );
    return toFoam(frame.global(next.meanFluctuation));
}


template<class CloudType>
Foam::forceSuSp Foam::NearWallDispersionForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    using namespace nearWallDispersion;
    forceSuSp value(Zero);
    if (!compat::isActive(p))
    {
        return value;
    }
    if (!checked_)
    {
        checkCloud();
    }
    // Every call: a colliding cloud may move its parcels over whole steps
    // (its first use) before it moves them in collision sub-cycles
    aerosolForces::checkWholeSteps(this->owner(), "nearWallDispersion");
    const scalar Sp = aerosolForces::dragFriction
    (
        this->owner(), p, td, dt, mass, Re, muc, "nearWallDispersion"
    );
    const scalar tauP = this->owner().forces().massEff(p, td, mass)/Sp;
    brachDunn::WallFrame frame;
    const brachDunn::FlowAtParticle flow = flowAt(p, td, muc, tauP, frame);
    if (!(flow.uStar > 0))
    {
        FatalErrorInFunction
            << "nearWallDispersion works in wall units: the carrier's "
            << "friction velocity at the wall nearest to cell " << p.cell()
            << " (parcel " << p.origId() << " of processor "
            << p.origProc() << ") is " << flow.uStar
            << " (no shear at that wall)" << exit(FatalError);
    }
    // The walk's own path of the parcel starts with its wall-normal
    // velocity relative to the carrier (its inertia carries it on)
    const scalar normalVelocity = frame.local(toCore(p.U() - td.Uc())).y;
    const brachDunn::PathStep& walked =
        walkOfSubStep(p, dt, flow, frame, tauP, normalVelocity);
    value.Su() = Sp*toFoam(frame.global(walked.meanFluctuation));
    if (walked.atLeastSubStep)
    {
        ++leastSubSteps_;
    }

    if (completesStep(p, dt))
    {
        value.Su() =
            Sp*startNextStep(p, flow, frame, tauP, normalVelocity, walked);
    }
    return value;
}


#include "NearWallDispersionForceChecks.C"


// ************************************************************************* //
