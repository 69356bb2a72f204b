// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallOutputs.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "releaseCompat.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallOutputs::wallOutputs
(
    const wallInteractionCoeffs& coeffs,
    const fvMesh& mesh,
    const word& cloudName,
    const labelList& injectorIds,
    const fileName& dir
)
:
    cloudName_(cloudName),
    logTables_(coeffs.logTables()),
    statistics_
    (
        coeffs.entries().patchNames(),
        coeffs.entries().handled(),
        injectorIds,
        coeffs.sizeClassEdges()
    )
{
    if (coeffs.writeFields())
    {
        deposits_.reset(new depositFields(mesh, cloudName));
        Info<< "    Deposited mass and number per face written to "
            << cloudName << ":massStick and " << cloudName
            << ":nStick, escaped mass to " << cloudName << ":massEscape"
            << endl;
    }
    if (coeffs.writeToFile())
    {
        grade_.reset(new gradeEfficiency(injectorIds, coeffs.sizeClassEdges()));
    }
    const bool files = coeffs.writeToFile() || coeffs.maxImpactRecords() > 0;
    if (files && Pstream::master())
    {
        mkDir(dir);
    }
    if (coeffs.maxImpactRecords() > 0)
    {
        records_.reset
        (
            new impactRecords
            (
                dir/"impacts.csv",
                coeffs.maxImpactRecords(),
                coeffs.entries().patchNames(),
                coeffs.recordedPatches()
            )
        );
    }
    if (coeffs.writeToFile() && Pstream::master())
    {
        openFiles(dir);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wallOutputs::openFiles(const fileName& dir)
{
    statisticsFile_.reset(new OFstream(dir/"statistics.dat"));
    statistics_.writeHeader(*statisticsFile_, cloudName_);
    balance_.writeTo(dir/"massBalance.dat", cloudName_);
    gradeFile_.reset(new OFstream(dir/"gradeEfficiency.dat"));
    grade_->writeHeader(*gradeFile_, cloudName_);
}


void Foam::wallOutputs::updateGradeEfficiency
(
    const cloudState& cloud,
    const word& timeName
)
{
    grade_->update(cloud.parcels());
    if (gradeFile_)
    {
        grade_->write(*gradeFile_, timeName);
    }
}


void Foam::wallOutputs::store
(
    const List<fateStatistics::row>& totals,
    modelProperties& properties
)
{
    properties.set("initialMass", balance_.storedText());
    if (grade_)
    {
        properties.set("gradeEfficiency", grade_->storedText());
    }
    forAll(statistics_.patchNames(), patch)
    {
        properties.set
        (
            statistics_.patchNames()[patch],
            statistics_.storedText(totals, patch)
        );
    }
    statistics_.store(totals);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::wallOutputs::add(const wallEvent& e)
{
    using brachDunn::Fate;

    // The statistics' speed and angle from the normal [m/s, degrees] of an
    // impact; of a resuspension, the friction velocity and 0
    const wallImpact& impact = e.impact;
    const bool resuspension = e.outcome == Fate::resuspension;
    statistics_.add
    (
        statistics_.rowOf(e.patchi, e.injectorId, e.d),
        e.outcome, e.nParticle, e.mass,
        resuspension
      ? e.frictionVelocity : Foam::sqrt(sqr(impact.un) + sqr(impact.ut)),
        resuspension
      ? 0 : Foam::atan2(impact.ut, impact.un)*180/constant::mathematical::pi
    );
    if (grade_)
    {
        grade_->fated
        (
            gradeGroup(e.injectorId, e.classDiameter),
            e.outcome, e.nParticle, e.mass, e.origProc, e.origId
        );
    }
    if (deposits_ && e.outcome == Fate::capture)
    {
        deposits_->addCapture
        (
            e.depositPatch, e.depositFace, e.mass, e.nParticle, e.depositProc
        );
    }
    else if (deposits_ && e.outcome == Fate::resuspension)
    {
        deposits_->addCapture
        (
            e.depositPatch, e.depositFace, -e.mass, -e.nParticle,
            e.depositProc
        );
    }
    else if (deposits_ && e.outcome == Fate::escape)
    {
        deposits_->addEscape(e.patchi, e.facei, e.mass, e.faceProc);
    }
    if (records_ && records_->active())
    {
        records_->add
        ({
            e.time, scalar(e.patchi), scalar(e.facei),
            e.position.x(), e.position.y(), e.position.z(),
            e.d, e.nParticle, impact.un, impact.ut, scalar(e.outcome),
            impact.R, impact.WA, impact.unOut, impact.utOut
        });
    }
    for (const auto& sink : sinks_)
    {
        sink->add(e);
    }
}


void Foam::wallOutputs::attach(const std::shared_ptr<wallEventSink>& sink)
{
    sinks_.push_back(sink);
    remoteFaces_ = true;
}


void Foam::wallOutputs::systemEscape
(
    const label injectorId,
    const scalar classDiameter,
    const scalar nParticle,
    const scalar mass,
    const label origProc,
    const label origId
)
{
    if (grade_)
    {
        grade_->leaving
        (
            gradeGroup(injectorId, classDiameter), nParticle, mass, origProc,
            origId
        );
    }
}


Foam::label Foam::wallOutputs::gradeGroup
(
    const label injectorId,
    const scalar classDiameter
) const
{
    return grade_->groups().of(injectorId, classDiameter);
}


void Foam::wallOutputs::restore
(
    const modelProperties& properties,
    const word& timeName
)
{
    forAll(statistics_.patchNames(), patch)
    {
        stringList stored;
        properties.get(statistics_.patchNames()[patch], stored);
        statistics_.restore(patch, stored);
    }
    if (grade_)
    {
        stringList stored;
        properties.get("gradeEfficiency", stored);
        grade_->restore(stored);
    }
    string initial;
    properties.get("initialMass", initial);
    compat::broadcast(initial);
    balance_.restore(initial);

    // The deposit fields must hold what the stored totals count
    const List<fateStatistics::row> totals(statistics_.totals());
    const scalar deposited =
        fateStatistics::parcels(totals, brachDunn::Fate::capture)
      + fateStatistics::parcels(totals, brachDunn::Fate::escape);
    if (deposits_ && deposited > 0 && deposits_->missing().size())
    {
        FatalErrorInFunction
            << "Fields " << deposits_->missing() << " are missing at time "
            << timeName << ", where the stored statistics of cloud "
            << cloudName_ << " count " << deposited << " parcels captured or"
            << " escaped since the start of the case: started from zero the"
            << " fields would disagree with them. Restore the fields of this"
            << " time (or restart from a time that has them), or set"
            << " writeFields no" << exit(FatalError);
    }
}


void Foam::wallOutputs::endOfStep
(
    Ostream& os,
    const word& timeName,
    const bool writeTime,
    const cloudState& cloud,
    modelProperties& properties
)
{
    // The full tables at write times (or every step, logTables yes),
    // else one line per patch
    const List<fateStatistics::row> totals(statistics_.totals());
    if (logTables_ || writeTime)
    {
        statistics_.print(os, totals);
    }
    else
    {
        statistics_.printSummary(os, totals);
    }
    if (statisticsFile_)
    {
        statistics_.write(*statisticsFile_, timeName, totals);
    }
    if (records_)
    {
        records_->write();
    }
    if (grade_)
    {
        updateGradeEfficiency(cloud, timeName);
    }

    // Deposits on other processors' faces reach their fields
    if (deposits_ && remoteFaces_)
    {
        deposits_->exchange();
    }

    for (const auto& sink : sinks_)
    {
        sink->stepDone(os, timeName, writeTime);
    }

    // The first step fixes the initial mass unless known at the start;
    // write times print the balance
    if (writeTime || !balance_.started())
    {
        balance_.update
        (
            cloud.injectedMass(),
            cloud.airborneMass(),
            fateStatistics::mass(totals, brachDunn::Fate::capture),
            fateStatistics::mass(totals, brachDunn::Fate::escape),
            fateStatistics::mass(totals, brachDunn::Fate::resuspension)
        );
    }
    if (writeTime)
    {
        balance_.write(os, timeName);
        store(totals, properties);
    }
}


// ************************************************************************* //
