// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "AdhesiveWallInteraction.H"
#include "parcelImpacts.H"
#include "wallPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::fileName Foam::AdhesiveWallInteraction<CloudType>::outputDir() const
{
    // As OpenFOAM's cloud function objects: postProcessing/lagrangian/<cloud>
    const Time& time = this->owner().mesh().time();
    return
        time.rootPath()/time.globalCaseName()/"postProcessing"/"lagrangian"
       /this->owner().name()/typeName/compat::timeName(time);
}



template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::count
(
    const parcelType& p,
    const polyPatch& pp,
    const label facei,
    const label faceProc,
    const wallImpact& impact,
    const wallEvent::contact via
)
{
    using brachDunn::Fate;

    const Time& time = this->owner().mesh().time();
    wallEvent e = wallInteractionCloud::parcelEvent
    (
        p, impact.outcome, pp.index(), facei, faceProc,
        time.value() - (1 - p.stepFraction())*time.deltaTValue(),
        outputs_->needsPositions()
      ? compat::position(p, this->owner().mesh()) : point(Zero),
        impact, 0, via
    );
    if (resuspension_ && impact.outcome == Fate::capture)
    {
        // A deposit that may leave is credited to its site
        resuspension_->captured(p);
        const auto site =
            outputs_->keepsDeposits()
          ? resuspension_->siteOf(p) : std::nullopt;
        if (site)
        {
            e.depositPatch = site->patchi;
            e.depositFace = site->facei;
            e.depositProc = site->proc;
        }
    }
    outputs_->add(e);
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::interact
(
    parcelType& p,
    const polyPatch& pp,
    const label facei,
    const label faceProc,
    const vector& nw,
    const vector& Up,
    const wallInteractionEntry& entry,
    const wallEvent::contact via,
    bool& keepParticle
)
{
    using brachDunn::Fate;

    keepParticle = true;
    if (resuspension_ && resuspension_->rollsOn(p, pp.index(), nw, Up))
    {
        return;
    }

    vector omega = Zero;
    if constexpr (wallInteractionCloud::isColliding<parcelType>::value)
    {
        omega = p.omega();
    }
    wallImpact impact;
    try
    {
        impact = entry.impact(p.d(), p.rho(), p.U() - Up, nw, omega);
    }
    catch (const brachDunn::InputError& err)
    {
        FatalErrorInFunction
            << "Parcel at " << compat::position(p, this->owner().mesh())
            << " on patch " << pp.name() << ": " << err.what() << nl
            << exit(FatalError);
    }
    if (impact.outcome == Fate::notApproaching)
    {
        return;
    }
    impact.U += Up;
    keepParticle = wallInteractionCloud::applyImpact
    (
        p, impact, entry.type() == wallInteractionEntry::interaction::adhesive,
        coeffs_.removeCaptured()
    );

    count(p, pp, facei, faceProc, impact, via);
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::declined
(
    const parcelType& p,
    const polyPatch& pp,
    const wallInteractionEntry& entry
)
{
    if (isA<wallPolyPatch>(pp))
    {
        // Declined, OpenFOAM would leave the parcel on the wall face and
        // the time step would never end: stop with the reason instead
        FatalErrorInFunction
            << "Parcel at " << compat::position(p, this->owner().mesh())
            << " hit the wall patch " << pp.name() << ", whose entry "
            << entry.name() << " has type none: nothing would move it"
            << " off the wall. Give walls an adhesive, rebound, stick or"
            << " escape entry" << exit(FatalError);
    }
    // OpenFOAM removes it: a system escape
    outputs_->systemEscape
    (
        compat::parcelInjectorId(p), wallInteractionCloud::classDiameter(p),
        p.nParticle(), p.nParticle()*p.mass(), p.origProc(), p.origId()
    );
    return false;
}



template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::checkDiameter
(
    const parcelType& p,
    const polyPatch& pp
) const
{
    // A diameter that can only be a unit mistake (5 typed for 5 um): no
    // injector's size said so at the start (a table of sizes)
    const brachDunn::Magnitude& diameter = brachDunn::magnitude::diameter;
    if
    (
        (p.d() > diameter.mistakeAbove || p.d() < diameter.mistakeBelow)
     && !coeffs_.magnitudes().extreme
    )
    {
        FatalErrorInFunction
            << "Parcel at " << compat::position(p, this->owner().mesh())
            << " on patch " << pp.name() << ": "
            << brachDunn::unitMistake(diameter, "d", p.d()).c_str()
            << " (extremeValues yes in adhesiveWallInteractionCoeffs takes"
            << " it as given)" << nl
            << exit(FatalError);
    }
}



// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AdhesiveWallInteraction<CloudType>::AdhesiveWallInteraction
(
    const dictionary& dict,
    CloudType& cloud
)
:
    compat::PatchInteractionModel<CloudType>(dict, cloud, typeName),
    coeffs_
    (
        this->coeffs(),
        wallInteractionEntryList::patchesOf(compat::boundaryMesh(cloud.mesh())),
        wallInteractionCloud::particle(cloud),
        compat::baseKeywords()
    ),
    filesDir_(outputDir())
{
    wallInteractionCloud::check
    (
        cloud, this->dict(), typeName, coeffs_.magnitudes()
    );
    coeffs_.printSettings();
    outputs_ = std::make_shared<wallOutputs>
    (
        coeffs_, cloud.mesh(), cloud.name(),
        coeffs_.outputByInjectorId()
      ? wallInteractionCloud::injectorIds(cloud) : labelList(),
        filesDir_
    );
    resuspension_ = WallResuspension<CloudType>::New
    (
        cloud, coeffs_.entries(), wallPatches()
    );
    wallInteractionCloud::checkSurfaceContactPlace(cloud);

    const propertiesOf<AdhesiveWallInteraction<CloudType>> properties(*this);
    outputs_->restore(properties, compat::timeName(cloud.mesh().time()));
    if (resuspension_)
    {
        resuspension_->restore(properties);
    }

    // Without parcels at the start the initial mass is known now: none,
    // less what the injectors gave before the model counted (a model added
    // to a running case); otherwise it is found after the first step, as
    // what the other terms leave over (which then also holds what the
    // first step exchanged with the gas)
    if (!outputs_->started() && !wallInteractionCloud::startsWithParcels(cloud))
    {
        // (0 - m: 0 rather than -0 when nothing was injected)
        outputs_->start(0 - wallInteractionCloud::injectedMass(cloud));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::correct
(
    parcelType& p,
    const polyPatch& pp,
    bool& keepParticle
)
{
    const wallInteractionEntry* entry = coeffs_.entries().entryOf(pp.index());
    if (!entry)
    {
        return false;
    }
    if (entry->type() == wallInteractionEntry::interaction::none)
    {
        return declined(p, pp, *entry);
    }
    checkDiameter(p, pp);

    vector nw, Up;
    this->owner().patchData(p, pp, nw, Up);
    interact
    (
        p, pp, pp.whichFace(p.face()), -1, nw, Up, *entry,
        wallEvent::contact::centre, keepParticle
    );
    return true;
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::touch
(
    parcelType& p,
    const label patchi,
    const label facei,
    const label faceProc,
    const vector& nw,
    bool& keepParticle
)
{
    const polyPatch& pp = compat::boundaryMesh(this->owner().mesh())[patchi];
    const wallInteractionEntry* entry = coeffs_.entries().entryOf(patchi);
    if (!entry || entry->type() == wallInteractionEntry::interaction::none)
    {
        return false;
    }
    checkDiameter(p, pp);
    const bool local = faceProc < 0 || faceProc == Pstream::myProcNo();
    const vector Up =
        local
      ? wallInteractionCloud::wallVelocity(this->owner(), p, pp, facei, nw)
      : vector(Zero);
    interact
    (
        p, pp, facei, faceProc, nw, Up, *entry, wallEvent::contact::surface,
        keepParticle
    );
    return true;
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::writeInfo(Ostream& os)
{
    // In v1912 info() is the only call a patch interaction model gets after
    // a step's tracking: the resuspension's end of step comes first, so
    // that the totals, the balance and what a write time stores hold it.
    // Once a step: a second info() in the step does nothing
    const Time& time = this->owner().mesh().time();
    if (time.timeIndex() == lastInfo_)
    {
        return;
    }
    lastInfo_ = time.timeIndex();
    if (resuspension_)
    {
        resuspension_->endOfStep(*outputs_);
    }
    propertiesOf<AdhesiveWallInteraction<CloudType>> properties(*this);
    if (resuspension_ && this->writeTime())
    {
        resuspension_->store(properties);
    }
    outputs_->endOfStep
    (
        os, compat::timeName(time), this->writeTime(),
        wallInteractionCloud::cloudState(this->owner(), *outputs_),
        properties
    );
}


template<class CloudType>
Foam::labelList Foam::AdhesiveWallInteraction<CloudType>::wallPatches() const
{
    // Not constraint patches taken on with patchType: a symmetry plane or
    // a wedge is a mirror of the flow, which a parcel's centre meets
    using interaction = wallInteractionEntry::interaction;
    const polyBoundaryMesh& boundary = compat::boundaryMesh(this->owner().mesh());
    DynamicList<label> patches;
    forAll(boundary, patchi)
    {
        const wallInteractionEntry* entry = coeffs_.entries().entryOf(patchi);
        if
        (
            entry
         && entry->type() != interaction::escape
         && entry->type() != interaction::none
         && !compat::isConstraint(boundary[patchi])
        )
        {
            patches.append(patchi);
        }
    }
    return labelList(patches);
}



template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::useSurfaceContact
(
    const word& function,
    const std::shared_ptr<wallEventSink>& counts
)
{
    if (!surfaceContactFunction_.empty() && function != surfaceContactFunction_)
    {
        FatalErrorInFunction
            << "Cloud functions " << surfaceContactFunction_ << " and "
            << function << " of cloud " << this->owner().name()
            << " both ask for contact at the surface: each would take the"
            << " same contacts again. Keep one, with maxDiameter the largest"
            << " diameter of the parcels" << exit(FatalError);
    }
    if (!surfaceContactFunction_.empty())
    {
        return;
    }
    surfaceContactFunction_ = function;
    outputs_->attach(counts);
    if (resuspension_)
    {
        resuspension_->useSurfaceContact();
    }
}


// ************************************************************************* //
