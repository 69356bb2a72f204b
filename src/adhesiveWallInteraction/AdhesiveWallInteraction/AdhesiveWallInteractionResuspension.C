// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// AdhesiveWallInteraction's resuspension: the deposits the flow takes off
// their walls at the end of each step, and the parcels so detached
// (included by AdhesiveWallInteraction.H with the rest of the template)

#include "AdhesiveWallInteraction.H"

#include <map>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::setUpResuspension()
{
    const polyBoundaryMesh& patches = compat::boundaryMesh(this->owner().mesh());
    boolList resuspends(patches.size(), false);
    bool any = false;
    forAll(patches, patchi)
    {
        const wallInteractionEntry* entry = coeffs_.entries().entryOf(patchi);
        // (capture remove with a resuspending entry stopped with the
        // coefficients, wallInteractionCoeffs)
        resuspends[patchi] = entry && entry->resuspension();
        any = any || resuspends[patchi];

        // Biasi's fit of the adhesion spread holds below a radius of
        // 35 um: an injector's larger size stops the run now, not at the
        // deposit's first step
        if
        (
            resuspends[patchi]
         && entry->resuspension()->model.spread
         == brachDunn::DepositResuspension::Spread::biasi
        )
        {
            wallInteractionCloud::forEachInjectorSize
            (
                this->owner(),
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
                          + std::string(entry->name()) + "): radius "
                          + err.requirement() + "; give adhesionSpread"
                            " logNormal or none for such particles"
                        );
                    }
                }
            );
        }
    }
    if (any)
    {
        sites_ = std::make_shared<depositSites>
        (
            this->owner().mesh(), resuspends, wallPatches()
        );
    }
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::resuspend()
{
    const fvMesh& mesh = this->owner().mesh();
    const Time& time = mesh.time();
    // The per-step draws: counter = a hash of the step's time name (its
    // index would repeat in a continuation from a time folder without
    // uniform/time, which starts the index again; its value's last bits
    // differ between a straight run, which sums the steps, and a restart,
    // which reads the folder's name; the name is the same in both, and a
    // case never repeats it); the adhesion's counter is 0 (leaves)
    const std::uint64_t step =
        std::max(brachDunn::textCounter(compat::timeName(time)), std::uint64_t(1));

    sites_->update(this->owner().U(), this->owner().rho(), this->owner().mu());

    // Per patch: the deposits tested and the range of their friction
    // velocities, for the log (a user judges the rates by u*)
    const label nPatches = compat::boundaryMesh(mesh).size();
    labelList tested(nPatches, 0);
    scalarList uStarMin(nPatches, std::numeric_limits<scalar>::max());
    scalarList uStarMax(nPatches, scalar(0));

    std::vector<std::pair<label, label>> released;
    for (auto& p : this->owner())
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
        const auto s = sites_->find(p.cell(), position, p.d());
        if (!s)
        {
            continue;
        }
        const depositSites::flow& flow = sites_->flowAt(*s);
        const scalar uStar = Foam::sqrt(flow.tauW/flow.rho);
        ++tested[s->patchi];
        uStarMin[s->patchi] = min(uStarMin[s->patchi], uStar);
        uStarMax[s->patchi] = max(uStarMax[s->patchi], uStar);
        if (leaves(p, position, *s, flow, step))
        {
            release(p, position, *s, uStar);
            released.push_back({p.origProc(), p.origId()});
        }
    }
    capturedThisStep_.clear();
    updateDetached(released);

    logResuspension(tested, uStarMin, uStarMax);
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::leaves
(
    const typename CloudType::parcelType& p,
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
    const resuspensionSettings& settings =
        *coeffs_.entries().entryOf(s.patchi)->resuspension();
    const scalar dt = this->owner().mesh().time().deltaTValue();
    const std::uint64_t key1 = std::uint64_t(p.origProc()) | stream;
    const std::uint64_t key2 = std::uint64_t(p.origId());
    const scalar r = 0.5*p.d();

    scalar leaving = 0;
    try
    {
        const scalar fPrime = settings.model.reducedAdhesion
        (
            r,
            brachDunn::uniformFromBits
            (
                brachDunn::randomBits(settings.seed, key1, key2, 0)
            )
        );
        leaving = settings.model.leavingProbability
        (
            r, fPrime, flow.tauW, flow.rho, flow.nu, dt
        );
    }
    catch (const brachDunn::InputError& err)
    {
        FatalErrorInFunction
            << "Deposit at " << position << " on patch "
            << compat::boundaryMesh(this->owner().mesh())[s.patchi].name()
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
void Foam::AdhesiveWallInteraction<CloudType>::logResuspension
(
    const labelList& tested,
    const scalarList& uStarMin,
    const scalarList& uStarMax
)
{
    const fvMesh& mesh = this->owner().mesh();
    forAll(tested, patchi)
    {
        const wallInteractionEntry* entry = coeffs_.entries().entryOf(patchi);
        if (!entry || !entry->resuspension())
        {
            continue;
        }
        const label n = returnReduce(tested[patchi], sumOp<label>());
        if (!n)
        {
            continue;
        }
        const word& patch = compat::boundaryMesh(mesh)[patchi].name();
        Info<< "    resuspension " << patch.c_str() << ": " << n
            << " deposits tested, friction velocity u* "
            << returnReduce(uStarMin[patchi], minOp<scalar>()) << " to "
            << returnReduce(uStarMax[patchi], maxOp<scalar>()) << " m/s"
            << endl;
        if
        (
            !laminarSaid_ && !sites_->turbulent()
         && entry->resuspension()->model.kind
            == brachDunn::DepositResuspension::Kind::rockNRoll
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
void Foam::AdhesiveWallInteraction<CloudType>::updateDetached
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
        const fvMesh& mesh = this->owner().mesh();
        for (const auto& p : this->owner())
        {
            const auto found = index.find({p.origProc(), p.origId()});
            if (found == index.end())
            {
                continue;
            }
            held[found->second] = 1;
            if
            (
                compat::isActive(p)
             && !sites_->nearestWall(p.cell(), compat::position(p, mesh), p.d())
            )
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


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::rollsOn
(
    typename CloudType::parcelType& p,
    const vector& nw,
    const vector& Up,
    const wallInteractionEntry& entry
) const
{
    // A parcel the flow took off a wall, not yet out of the walls' reach:
    // detachment is a rolling motion, not necessarily followed by
    // entrainment (Ibrahim, Dunn & Brach 2003), so a resuspending wall it
    // touches does not capture it again; it keeps its motion along the
    // wall (the part into the wall taken off) and the touch is no impact.
    // A capturing wall without resuspension captures it as any parcel
    using interaction = wallInteractionEntry::interaction;
    if
    (
        detached_.empty() || !entry.resuspension()
     || (entry.type() != interaction::adhesive && entry.type() != interaction::stick)
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
void Foam::AdhesiveWallInteraction<CloudType>::creditCapture
(
    const typename CloudType::parcelType& p,
    const label patchi,
    const label facei,
    const label faceProc,
    const scalar mass,
    const scalar nParticle
)
{
    // A deposit that may leave is credited to its site, the face its
    // release takes it off (depositSites::find, of the same position and
    // cell: a deposit does not move): where faces tie (a parcel on the
    // line where two meet) the face the tracking hit may be the other one
    if (sites_)
    {
        const auto s = sites_->find
        (
            p.cell(), compat::position(p, this->owner().mesh()), p.d()
        );
        if (s)
        {
            deposits_->addCapture(s->patchi, s->facei, mass, nParticle, s->proc);
            return;
        }
    }
    deposits_->addCapture(patchi, facei, mass, nParticle, faceProc);
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::release
(
    typename CloudType::parcelType& p,
    const point& position,
    const depositSites::site& s,
    const scalar frictionVelocity
)
{
    const polyPatch& pp = compat::boundaryMesh(this->owner().mesh())[s.patchi];
    const scalar nParticle = p.nParticle();
    const scalar mass = nParticle*p.mass();

    statistics_.add
    (
        statistics_.rowOf(s.patchi, compat::parcelInjectorId(p), p.d()),
        brachDunn::Fate::resuspension, nParticle, mass, frictionVelocity, 0
    );
    if (grade_)
    {
        grade_->fated
        (
            gradeGroup(p), brachDunn::Fate::resuspension, nParticle, mass,
            p.origProc(), p.origId()
        );
    }
    if (deposits_)
    {
        deposits_->addCapture(s.patchi, s.facei, -mass, -nParticle, s.proc);
    }
    if (records_ && records_->active())
    {
        records_->add
        ({
            this->owner().mesh().time().value(),
            scalar(pp.index()), scalar(s.facei),
            position.x(), position.y(), position.z(),
            p.d(), nParticle, 0, 0, scalar(brachDunn::Fate::resuspension),
            0, 0, 0, 0
        });
    }

    // Airborne again, at rest, clear of the wall it sat on
    compat::setActive(p, true);
    p.U() = Zero;
    compat::displace(p, this->owner().mesh(), -1e-3*p.d()*s.normal);
}


// ************************************************************************* //
