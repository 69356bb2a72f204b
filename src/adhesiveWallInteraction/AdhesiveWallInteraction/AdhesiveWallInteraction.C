// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "AdhesiveWallInteraction.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "wallPolyPatch.H"
#include "CounterRandom.H"

#include <algorithm>

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
    const typename CloudType::parcelType& p,
    const polyPatch& pp,
    const label facei,
    const label faceProc,
    const wallImpact& impact
)
{
    using brachDunn::Fate;

    const scalar nParticle = p.nParticle();
    const scalar mass = nParticle*p.mass();
    statistics_.add
    (
        statistics_.rowOf(pp.index(), compat::parcelInjectorId(p), p.d()),
        impact.outcome,
        nParticle,
        mass,
        Foam::sqrt(sqr(impact.un) + sqr(impact.ut)),
        Foam::atan2(impact.ut, impact.un)*180/constant::mathematical::pi
    );

    if (grade_)
    {
        grade_->fated
        (
            gradeGroup(p),
            impact.outcome, nParticle, mass, p.origProc(), p.origId()
        );
    }

    if (sites_ && impact.outcome == Fate::capture)
    {
        capturedThisStep_.insert({p.origProc(), p.origId()});
    }

    if (deposits_ && impact.outcome != Fate::rebound)
    {
        if (impact.outcome == Fate::capture)
        {
            creditCapture(p, pp.index(), facei, faceProc, mass, nParticle);
        }
        else
        {
            deposits_->addEscape(pp.index(), facei, mass, faceProc);
        }
    }

    if (records_ && records_->active())
    {
        const Time& time = this->owner().mesh().time();
        const point position = compat::position(p, this->owner().mesh());
        records_->add
        ({
            time.value() - (1 - p.stepFraction())*time.deltaTValue(),
            scalar(pp.index()), scalar(facei),
            position.x(), position.y(), position.z(),
            p.d(), nParticle, impact.un, impact.ut, scalar(impact.outcome),
            impact.R, impact.WA, impact.unOut, impact.utOut
        });
    }
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::checkSurfaceContactPlace() const
{
    // A cloudFunctions block in subModels is never read: the run would go
    // on with contact at the centre, and only missing log lines tell
    const entry* functions = compat::findEntry
    (
        this->owner().subModelProperties(), "cloudFunctions"
    );
    if (!functions || !functions->isDict())
    {
        return;
    }
    for (const entry& function : functions->dict())
    {
        if (wallInteractionCloud::isSurfaceContact(function))
        {
            checkedInput::fail
            (
                functions->dict(), function.keyword(),
                "{ type " + wallInteractionCloud::surfaceContactType
              + "; ... }",
                "a cloud function in subModels, where OpenFOAM does not read"
                " cloudFunctions: move the cloudFunctions block to the top"
                " level of the cloud's properties"
            );
        }
    }
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::restore()
{
    // Totals of earlier runs, and the parcels the case started with
    forAll(statistics_.patchNames(), patch)
    {
        stringList stored;
        this->getModelProperty(statistics_.patchNames()[patch], stored);
        statistics_.restore(patch, stored);
    }
    if (grade_)
    {
        stringList stored;
        this->getModelProperty("gradeEfficiency", stored);
        grade_->restore(stored);
    }
    string initial;
    this->getModelProperty("initialMass", initial);
    compat::broadcast(initial);
    balance_.restore(initial);
    labelList detached;
    this->getModelProperty("detached", detached);
    compat::broadcast(detached);
    for (label i = 0; i + 1 < detached.size(); i += 2)
    {
        detached_.insert({detached[i], detached[i + 1]});
    }

    // The deposit fields must hold what the stored totals count
    const List<fateStatistics::row> totals(statistics_.totals());
    const scalar deposited =
        fateStatistics::parcels(totals, brachDunn::Fate::capture)
      + fateStatistics::parcels(totals, brachDunn::Fate::escape);
    if (deposits_ && deposited > 0 && deposits_->missing().size())
    {
        FatalErrorInFunction
            << "Fields " << deposits_->missing() << " are missing at time "
            << compat::timeName(this->owner().mesh().time()) << ", where the"
            << " stored statistics of cloud " << this->owner().name()
            << " count " << deposited << " parcels captured or escaped"
            << " since the start of the case: started from zero the fields"
            << " would disagree with them. Restore the fields of this time"
            << " (or restart from a time that has them), or set writeFields"
            << " no" << exit(FatalError);
    }
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::apply
(
    typename CloudType::parcelType& p,
    const wallImpact& impact,
    const bool adhesive
) const
{
    constexpr bool colliding =
        wallInteractionCloud::isColliding<typename CloudType::parcelType>::value;

    if (impact.outcome == brachDunn::Fate::rebound)
    {
        compat::setActive(p, true);
        p.U() = impact.U;
        if constexpr (colliding)
        {
            // Rebound entries leave the spin, as standardWallInteraction
            if (adhesive)
            {
                p.angularMomentum() = p.momentOfInertia()*impact.omega;
            }
        }
        return true;
    }

    // Captured or escaped
    compat::setActive(p, false);
    p.U() = Zero;
    if constexpr (colliding)
    {
        p.angularMomentum() = Zero;
    }
    return
        impact.outcome == brachDunn::Fate::capture
     && !coeffs_.removeCaptured();
}


template<class CloudType>
Foam::label Foam::AdhesiveWallInteraction<CloudType>::gradeGroup
(
    const typename CloudType::parcelType& p
) const
{
    return grade_->groups().of
    (
        compat::parcelInjectorId(p), wallInteractionCloud::classDiameter(p)
    );
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::updateGradeEfficiency()
{
    List<gradeEfficiency::parcel> parcels(this->owner().size());
    label i = 0;
    for (const auto& p : this->owner())
    {
        parcels[i++] =
        {
            gradeGroup(p),
            p.origProc(), p.origId(), compat::isActive(p), p.nParticle(),
            p.nParticle()*p.mass()
        };
    }
    grade_->update(parcels);
    if (gradeFile_)
    {
        grade_->write(*gradeFile_, compat::timeName(this->owner().mesh().time()));
    }
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::printSettings() const
{
    const std::vector<std::string>* warningLists[] =
    {
        &coeffs_.entries().warnings(), coeffs_.magnitudes().warnings.get()
    };
    for (const auto* warnings : warningLists)
    {
        for (const std::string& warning : *warnings)
        {
            WarningInFunction << warning.c_str() << endl;
        }
    }
    if (coeffs_.particle())
    {
        const auto& particle = *coeffs_.particle();
        Info<< "    particle: E " << particle.material.E << " nu "
            << particle.material.nu << " (" << particle.origin.c_str() << ")"
            << nl;
    }
    for (const wallInteractionEntry& entry : coeffs_.entries().entries())
    {
        Info<< "    " << entry.describe().c_str() << nl;
    }

}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::openFiles
(
    const word& cloudName
)
{
    filesDir_ = outputDir();
    const bool files = coeffs_.writeToFile() || coeffs_.maxImpactRecords() > 0;
    if (files && Pstream::master())
    {
        mkDir(outputDir());
    }
    if (coeffs_.maxImpactRecords() > 0)
    {
        records_ = std::make_shared<impactRecords>
        (
            outputDir()/"impacts.csv",
            coeffs_.maxImpactRecords(),
            coeffs_.entries().patchNames(),
            coeffs_.recordedPatches()
        );
    }
    if (coeffs_.writeToFile() && Pstream::master())
    {
        statisticsFile_ = std::make_shared<OFstream>(outputDir()/"statistics.dat");
        statistics_.writeHeader(*statisticsFile_, cloudName);
        balance_.writeTo(outputDir()/"massBalance.dat", cloudName);
        gradeFile_ = std::make_shared<OFstream>(outputDir()/"gradeEfficiency.dat");
        grade_->writeHeader(*gradeFile_, cloudName);
    }
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::declined
(
    const typename CloudType::parcelType& p,
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
    if (grade_)
    {
        // OpenFOAM removes it: a system escape
        grade_->leaving
        (
            gradeGroup(p), p.nParticle(), p.nParticle()*p.mass(),
            p.origProc(), p.origId()
        );
    }
    return false;
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::checkDiameter
(
    const typename CloudType::parcelType& p,
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
    statistics_
    (
        coeffs_.entries().patchNames(),
        coeffs_.entries().handled(),
        coeffs_.outputByInjectorId()
      ? wallInteractionCloud::injectorIds(cloud) : labelList(),
        coeffs_.sizeClassEdges()
    )
{
    wallInteractionCloud::check
    (
        cloud, this->dict(), typeName, coeffs_.magnitudes()
    );
    printSettings();
    if (coeffs_.writeFields())
    {
        deposits_ = std::make_shared<depositFields>(cloud.mesh(), cloud.name());
        Info<< "    Deposited mass and number per face written to "
            << cloud.name() << ":massStick and " << cloud.name()
            << ":nStick, escaped mass to " << cloud.name() << ":massEscape"
            << endl;
    }
    if (coeffs_.writeToFile())
    {
        grade_ = std::make_shared<gradeEfficiency>
        (
            coeffs_.outputByInjectorId()
          ? wallInteractionCloud::injectorIds(cloud) : labelList(),
            coeffs_.sizeClassEdges()
        );
    }
    setUpResuspension();
    checkSurfaceContactPlace();
    restore();

    // Without parcels at the start the initial mass is known now: none,
    // less what the injectors gave before the model counted (a model added
    // to a running case); otherwise it is found after the first step, as
    // what the other terms leave over (which then also holds what the
    // first step exchanged with the gas)
    if (!balance_.started() && !wallInteractionCloud::startsWithParcels(cloud))
    {
        // (0 - m: 0 rather than -0 when nothing was injected)
        balance_.start(0 - wallInteractionCloud::injectedMass(cloud));
    }

    openFiles(cloud.name());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::correct
(
    typename CloudType::parcelType& p,
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
    const brachDunn::Fate outcome = interact
    (
        p, pp, pp.whichFace(p.face()), -1, nw, Up, *entry, keepParticle
    );
    if
    (
        contacts_ && contacts_->handles(pp.index())
     && outcome != brachDunn::Fate::notApproaching
    )
    {
        contacts_->addCentre(pp.index());
    }
    return true;
}


template<class CloudType>
bool Foam::AdhesiveWallInteraction<CloudType>::touch
(
    typename CloudType::parcelType& p,
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
    const vector Up = local ? wallVelocity(p, pp, facei, nw) : Zero;
    const brachDunn::Fate outcome =
        interact(p, pp, facei, faceProc, nw, Up, *entry, keepParticle);
    // (the impacts taken, as the statistics count them: not a touch whose
    // velocity points away from the wall, which the model leaves alone)
    if (contacts_ && outcome != brachDunn::Fate::notApproaching)
    {
        contacts_->addSurface(patchi);
    }
    return true;
}


template<class CloudType>
Foam::vector Foam::AdhesiveWallInteraction<CloudType>::wallVelocity
(
    const typename CloudType::parcelType& p,
    const polyPatch& pp,
    const label facei,
    const vector& nw
) const
{
    // As KinematicCloud::patchData on a static mesh: the tangential part
    // of a wall's velocity that its boundary condition sets (a lid, a belt)
    const fvPatchVectorField& Uw1 = this->owner().U().boundaryField()[pp.index()];
    if (!isA<wallPolyPatch>(pp) || !Uw1.fixesValue())
    {
        return Zero;
    }
    const vector& Uw0 =
        this->owner().U().oldTime().boundaryField()[pp.index()][facei];
    const vector Uw = Uw0 + p.currentTimeFraction()*(Uw1[facei] - Uw0);
    return Uw - (nw & Uw)*nw;
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
void Foam::AdhesiveWallInteraction<CloudType>::countSurfaceContacts
(
    const word& function
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
    surfaceContactFunction_ = function;
    if (contacts_)
    {
        return;
    }
    const polyBoundaryMesh& patches = compat::boundaryMesh(this->owner().mesh());
    const labelList walls(wallPatches());
    wordList names(walls.size());
    forAll(walls, i)
    {
        names[i] = patches[walls[i]].name();
    }
    contacts_ = std::make_shared<surfaceContactCounts>(walls, names, patches.size());

    labelList stored;
    this->getModelProperty("surfaceContact", stored);
    contacts_->restore(stored);

    if (coeffs_.writeToFile() && Pstream::master())
    {
        contactFile_ = std::make_shared<OFstream>(filesDir_/"surfaceContact.dat");
        contacts_->writeHeader(*contactFile_, this->owner().name());
    }
}


template<class CloudType>
brachDunn::Fate Foam::AdhesiveWallInteraction<CloudType>::interact
(
    typename CloudType::parcelType& p,
    const polyPatch& pp,
    const label facei,
    const label faceProc,
    const vector& nw,
    const vector& Up,
    const wallInteractionEntry& entry,
    bool& keepParticle
)
{
    using brachDunn::Fate;
    constexpr bool colliding =
        wallInteractionCloud::isColliding<typename CloudType::parcelType>::value;

    if (rollsOn(p, nw, Up, entry))
    {
        keepParticle = true;
        return Fate::notApproaching;
    }

    vector omega = Zero;
    if constexpr (colliding)
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
        keepParticle = true;
        return impact.outcome;
    }
    impact.U += Up;
    keepParticle = apply
    (
        p, impact, entry.type() == wallInteractionEntry::interaction::adhesive
    );
    count(p, pp, facei, faceProc, impact);
    return impact.outcome;
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::writeInfo(Ostream& os)
{
    // Resuspension first, so that the totals, the balance and what a write
    // time stores hold it (writeInfo is the model's end-of-step call)
    if (sites_)
    {
        resuspend();
    }

    // The full tables at write times (or every step, logTables yes),
    // else one line per patch
    const List<fateStatistics::row> totals(statistics_.totals());
    if (coeffs_.logTables() || this->writeTime())
    {
        statistics_.print(os, totals);
    }
    else
    {
        statistics_.printSummary(os, totals);
    }

    if (statisticsFile_)
    {
        statistics_.write
        (
            *statisticsFile_, compat::timeName(this->owner().mesh().time()),
            totals
        );
    }
    if (records_)
    {
        records_->write();
    }
    if (grade_)
    {
        updateGradeEfficiency();
    }
    if (contacts_)
    {
        writeSurfaceContacts(os);
    }

    // The first step fixes the initial mass unless known at the start;
    // write times print the balance
    if (this->writeTime() || !balance_.started())
    {
        balance_.update
        (
            wallInteractionCloud::injectedMass(this->owner()),
            wallInteractionCloud::airborneMass(this->owner()),
            fateStatistics::mass(totals, brachDunn::Fate::capture),
            fateStatistics::mass(totals, brachDunn::Fate::escape),
            fateStatistics::mass(totals, brachDunn::Fate::resuspension)
        );
    }
    if (this->writeTime())
    {
        balance_.write(os, compat::timeName(this->owner().mesh().time()));
        store(totals);
    }
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::store
(
    const List<fateStatistics::row>& totals
)
{
    this->setModelProperty("initialMass", balance_.storedText());
    if (sites_)
    {
        labelList detached(2*detached_.size());
        label i = 0;
        for (const auto& key : detached_)
        {
            detached[i++] = key.first;
            detached[i++] = key.second;
        }
        this->setModelProperty("detached", detached);
    }
    if (grade_)
    {
        this->setModelProperty("gradeEfficiency", grade_->storedText());
    }
    forAll(statistics_.patchNames(), patch)
    {
        this->setModelProperty
        (
            statistics_.patchNames()[patch],
            statistics_.storedText(totals, patch)
        );
    }
    statistics_.store(totals);
}


template<class CloudType>
void Foam::AdhesiveWallInteraction<CloudType>::writeSurfaceContacts
(
    Ostream& os
)
{
    // Deposits on other processors' faces reach their fields first
    if (deposits_)
    {
        deposits_->exchange();
    }
    const labelList totals(contacts_->totals());
    contacts_->print(os, totals);
    if (contactFile_)
    {
        contacts_->write
        (
            *contactFile_, compat::timeName(this->owner().mesh().time()), totals
        );
    }
    if (this->writeTime())
    {
        this->setModelProperty("surfaceContact", totals);
    }
}


// ************************************************************************* //
