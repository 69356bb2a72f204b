// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "WallResuspension.H"
#include "CounterRandom.H"
#include "wallTriangles.H"

#include <algorithm>
#include <map>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
std::unique_ptr<Foam::WallResuspension<CloudType>>
Foam::WallResuspension<CloudType>::New
(
    CloudType& cloud,
    const wallInteractionEntryList& entries,
    const labelList& walls
)
{
    const polyBoundaryMesh& patches = compat::boundaryMesh(cloud.mesh());
    boolList resuspends(patches.size(), false);
    forAll(patches, patchi)
    {
        // (capture remove with a resuspending entry stopped with the
        // coefficients, wallInteractionCoeffs)
        const wallInteractionEntry* entry = entries.entryOf(patchi);
        resuspends[patchi] = entry && entry->resuspension();
    }
    if (findIndex(resuspends, true) < 0)
    {
        return nullptr;
    }
    return std::make_unique<WallResuspension<CloudType>>
    (
        cloud, entries, resuspends, walls
    );
}


template<class CloudType>
Foam::WallResuspension<CloudType>::WallResuspension
(
    CloudType& cloud,
    const wallInteractionEntryList& entries,
    const boolList& resuspends,
    const labelList& walls
)
:
    owner_(cloud),
    settings_(resuspends.size()),
    entryNames_(resuspends.size()),
    sites_(cloud.mesh(), resuspends, walls)
{
    forAll(resuspends, patchi)
    {
        if (resuspends[patchi])
        {
            const wallInteractionEntry& entry = *entries.entryOf(patchi);
            settings_[patchi] =
                std::make_shared<const resuspensionSettings>
                (
                    *entry.resuspension()
                );
            entryNames_[patchi] = entry.name();
            checkSizes(entry);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::WallResuspension<CloudType>::checkSizes
(
    const wallInteractionEntry& entry
) const
{
    // Biasi's fit of the adhesion spread holds below a radius of 35 um: an
    // injector's larger size stops the run now, not at the deposit's first
    // step
    if
    (
        entry.resuspension()->model->law().spread
     != brachDunn::DepositResuspension::Spread::biasi
    )
    {
        return;
    }
    wallInteractionCloud::forEachInjectorSize
    (
        owner_,
        [&](const dictionary& dict, const word& key, const scalar d)
        {
            if (!(d > 0))
            {
                return;     // a distribution's minValue 0
            }
            try
            {
                brachDunn::biasiAdhesion(0.5*d);
            }
            catch (const brachDunn::InputError& err)
            {
                checkedInput::fail
                (
                    dict, key, name(d),
                    "a diameter beyond Biasi's adhesion spread"
                    " (adhesionSpread biasi of entry "
                  + std::string(entry.name()) + "): radius "
                  + err.requirement() + "; give adhesionSpread"
                    " logNormal or none for such particles"
                );
            }
        }
    );
}


template<class CloudType>
bool Foam::WallResuspension<CloudType>::leaves
(
    const parcelType& p,
    const point& position,
    const depositSites::site& s,
    const depositSites::flow& flow,
    const std::uint64_t step
) const
{
    // The parcel's adhesion draw (counter 0) and its step's draw (the
    // step's counter); the key's high bits set apart these streams from
    // other users of (seed, origProc, origId) (exactBrownianMotion)
    constexpr std::uint64_t stream = std::uint64_t(1) << 62;
    const resuspensionSettings& settings = *settings_[s.patchi];
    const scalar dt = owner_.mesh().time().deltaTValue();
    const std::uint64_t key1 = std::uint64_t(p.origProc()) | stream;
    const std::uint64_t key2 = std::uint64_t(p.origId());
    const scalar r = 0.5*p.d();

    scalar leaving = 0;
    try
    {
        const scalar fPrime = settings.model->reducedAdhesion
        (
            r,
            brachDunn::uniformFromBits
            (
                brachDunn::randomBits(settings.seed, key1, key2, 0)
            )
        );
        leaving = settings.model->leavingProbability
        (
            r, fPrime, flow.tauW, flow.rho, flow.nu, dt
        );
    }
    catch (const brachDunn::InputError& err)
    {
        FatalErrorInFunction
            << "Deposit at " << position << " on patch "
            << compat::boundaryMesh(owner_.mesh())[s.patchi].name()
            << " (resuspension): " << err.what() << exit(FatalError);
    }
    return
        leaving >= 1
     || (
            leaving > 0
         && brachDunn::uniformFromBits
            (
                brachDunn::randomBits(settings.seed, key1, key2, step)
            ) < leaving
        );
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::release
(
    parcelType& p,
    const point& position,
    const depositSites::site& s,
    const scalar frictionVelocity,
    wallEventSink& outputs
)
{
    outputs.add
    (
        wallInteractionCloud::parcelEvent
        (
            p, brachDunn::Fate::resuspension, s.patchi, s.facei, s.proc,
            owner_.mesh().time().value(), position, wallImpact(),
            frictionVelocity, wallEvent::contact::none
        )
    );

    // Airborne again, at rest, clear of the wall it sat on
    compat::setActive(p, true);
    p.U() = Zero;
    compat::displace(p, owner_.mesh(), -1e-3*p.d()*s.normal);
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::log
(
    const labelList& tested,
    const scalarList& uStarMin,
    const scalarList& uStarMax
)
{
    forAll(tested, patchi)
    {
        if (!settings_[patchi])
        {
            continue;
        }
        const label n = returnReduce(tested[patchi], sumOp<label>());
        if (!n)
        {
            continue;
        }
        const word& patch = compat::boundaryMesh(owner_.mesh())[patchi].name();
        Info<< "    resuspension " << patch.c_str() << ": " << n
            << " deposits tested, friction velocity u* "
            << returnReduce(uStarMin[patchi], minOp<scalar>()) << " to "
            << returnReduce(uStarMax[patchi], maxOp<scalar>()) << " m/s"
            << endl;
        if
        (
            !laminarSaid_ && !sites_.turbulent()
         && settings_[patchi]->model->turbulentFlowLaw()
        )
        {
            // (the channelResuspension tutorial does this on purpose: a
            // laminar Couette flow of a turbulent channel's wall stress)
            Info<< "    rockNRoll on " << patch.c_str() << ": the carrier"
                << " flow has no RAS or LES turbulence model, so u* is that"
                << " of the laminar"
                << " wall shear stress, taken as a turbulent boundary"
                << " layer's (bursts of frequency frequencyPlus u*^2/nu and"
                << " the fluctuating moment are those of turbulent flow)"
                << endl;
            laminarSaid_ = true;
        }
    }
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::updateDetached
(
    const std::vector<std::pair<label, label>>& released
)
{
    // One pass over the parcels: the detached ones held here, and those of
    // them out of reach (centre farther than a diameter from the model's
    // walls as nearestWall sees them). Reduced over the processors (a
    // parcel may cross; the set's order is the same on all): those out of
    // reach and those none holds (escaped, removed) are forgotten, so that
    // the set, stored at write times, does not grow without bound
    if (!detached_.empty())
    {
        std::map<std::pair<label, label>, label> index;
        for (const auto& key : detached_)
        {
            index.emplace(key, label(index.size()));
        }
        labelList held(detached_.size(), 0);
        labelList away(detached_.size(), 0);
        for (const auto& p : owner_)
        {
            const auto found = index.find({p.origProc(), p.origId()});
            if (found == index.end())
            {
                continue;
            }
            held[found->second] = 1;
            const point position = compat::position(p, owner_.mesh());
            if (compat::isActive(p) && !sites_.nearestWall(p.cell(), position, p.d()))
            {
                away[found->second] = 1;
            }
        }
        compat::maxOverProcessors(held);
        compat::maxOverProcessors(away);
        for (const auto& [key, i] : index)
        {
            if (!held[i] || away[i])
            {
                detached_.erase(key);
            }
        }
    }

    // Then the parcels released in this step, on every processor
    DynamicList<label> mine(2*released.size());
    for (const auto& key : released)
    {
        mine.append(key.first);
        mine.append(key.second);
    }
    List<labelList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = mine;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    for (const labelList& list : all)
    {
        for (label i = 0; i + 1 < list.size(); i += 2)
        {
            detached_.insert({list[i], list[i + 1]});
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::WallResuspension<CloudType>::endOfStep(wallEventSink& outputs)
{
    const fvMesh& mesh = owner_.mesh();
    const Time& time = mesh.time();
    if (time.timeIndex() == lastStep_)
    {
        return;
    }
    lastStep_ = time.timeIndex();

    // The per-step draws: counter = a hash of the step's time name (its
    // index would repeat in a continuation from a time folder without
    // uniform/time, which starts the index again; its value's last bits
    // differ between a straight run, which sums the steps, and a restart,
    // which reads the folder's name; the name is the same in both, and a
    // case never repeats it); the adhesion's counter is 0 (leaves)
    const std::uint64_t step =
        std::max(brachDunn::textCounter(compat::timeName(time)), std::uint64_t(1));

    sites_.update(owner_.U(), owner_.rho(), owner_.mu());

    // Per patch: the deposits tested and the range of their friction
    // velocities, for the log (a user judges the rates by u*)
    const label nPatches = compat::boundaryMesh(mesh).size();
    labelList tested(nPatches, 0);
    scalarList uStarMin(nPatches, std::numeric_limits<scalar>::max());
    scalarList uStarMax(nPatches, scalar(0));

    std::vector<std::pair<label, label>> released;
    for (auto& p : owner_)
    {
        if
        (
            compat::isActive(p)
         || capturedThisStep_.count({p.origProc(), p.origId()})
        )
        {
            continue;
        }
        const point position = compat::position(p, mesh);
        const auto s = sites_.find(p.cell(), position, p.d());
        if (!s)
        {
            continue;
        }
        const depositSites::flow& flow = sites_.flowAt(*s);
        const scalar uStar = Foam::sqrt(flow.tauW/flow.rho);
        ++tested[s->patchi];
        uStarMin[s->patchi] = min(uStarMin[s->patchi], uStar);
        uStarMax[s->patchi] = max(uStarMax[s->patchi], uStar);
        if (leaves(p, position, *s, flow, step))
        {
            release(p, position, *s, uStar, outputs);
            released.push_back({p.origProc(), p.origId()});
        }
    }
    capturedThisStep_.clear();
    updateDetached(released);
    log(tested, uStarMin, uStarMax);
}


template<class CloudType>
std::optional<Foam::depositSites::site>
Foam::WallResuspension<CloudType>::siteOf(const parcelType& p) const
{
    // A deposit that may leave is credited to its site, the face its
    // release takes it off (depositSites::find, of the same position and
    // cell: a deposit does not move): where faces tie (a parcel on the
    // line where two meet) the face the tracking hit may be the other one
    return sites_.find(p.cell(), compat::position(p, owner_.mesh()), p.d());
}


template<class CloudType>
bool Foam::WallResuspension<CloudType>::rollsOn
(
    parcelType& p,
    const label patchi,
    const vector& nw,
    const vector& Up
) const
{
    // A parcel the flow took off a wall, not yet out of the walls' reach:
    // detachment is a rolling motion, not necessarily followed by
    // entrainment (Ibrahim, Dunn & Brach 2003), so a resuspending wall it
    // touches does not capture it again; it keeps its motion along the
    // wall (the part into the wall taken off) and the touch is no impact.
    // A capturing wall without resuspension captures it as any parcel
    if
    (
        detached_.empty() || !settings_[patchi]
     || !detached_.count({p.origProc(), p.origId()})
    )
    {
        return false;
    }
    // Left leaving the wall by a hair (1e-9 of the relative speed): along
    // a face that is not aligned with the axes, a velocity along it to
    // rounding may point into it, which the tracking takes as a hit at
    // once, without progress, again and again
    const scalar un = (p.U() - Up) & nw;
    const scalar away = 1e-9*mag(p.U() - Up);
    if (un > -away)
    {
        p.U() -= (un + away)*nw;
    }
    return true;
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::useSurfaceContact()
{
    sites_.useWalls(wallTriangles::of(owner_.mesh(), owner_.name()));
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::restore
(
    const modelProperties& properties
)
{
    labelList detached;
    properties.get("detached", detached);
    compat::broadcast(detached);
    for (label i = 0; i + 1 < detached.size(); i += 2)
    {
        detached_.insert({detached[i], detached[i + 1]});
    }
}


template<class CloudType>
void Foam::WallResuspension<CloudType>::store
(
    modelProperties& properties
) const
{
    labelList detached(2*detached_.size());
    label i = 0;
    for (const auto& key : detached_)
    {
        detached[i++] = key.first;
        detached[i++] = key.second;
    }
    properties.set("detached", detached);
}


// ************************************************************************* //
