// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later

#include "AdhesiveWallSurfaceContact.H"
#include "checkedInput.H"
#include "meshTools.H"
#include "wallPolyPatch.H"

#include <limits>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::setUp()
{
    const polyMesh& mesh = this->owner().mesh();
    if (mesh.moving() || mesh.topoChanging())
    {
        FatalErrorInFunction
            << "Cloud function " << this->modelName() << " (type "
            << typeName << ") of cloud " << this->owner().name()
            << ": the mesh moves or changes, and contact at the surface is"
            << " written for static meshes only. Remove " << this->modelName()
            << " from cloudFunctions (contact at the centre, OpenFOAM's own)"
            << exit(FatalError);
    }
    if (walls_)
    {
        return;
    }

    model_ = dynamic_cast<surfaceContactTarget<CloudType>*>
    (
        &this->owner().patchInteraction()
    );
    if (!model_)
    {
        FatalErrorInFunction
            << "Cloud function " << this->modelName() << " (type "
            << typeName << ") of cloud " << this->owner().name()
            << " needs patchInteractionModel adhesiveWallInteraction, not "
            << this->owner().patchInteraction().type() << exit(FatalError);
    }
    checkOnlyMoves();
    checkMaxDiameter();
    walls_ = &wallTriangles::New
    (
        mesh, this->owner().name(), model_->wallPatches(), 0.5*maxDiameter_
    );

    // The counts of how parcels met the walls, kept in this function's
    // properties and written beside the model's files
    using properties = propertiesOf<AdhesiveWallSurfaceContact<CloudType>>;
    const fileName dir(model_->filesDir());
    counts_ = std::make_shared<surfaceContactCounts>
    (
        compat::boundaryMesh(mesh), model_->wallPatches()
    );
    counts_->keep
    (
        std::make_unique<properties>(*this),
        dir.empty() ? fileName() : dir/"surfaceContact.dat",
        this->owner().name()
    );
    model_->useSurfaceContact(this->modelName(), counts_);
    threeD_ = mesh.nGeometricD() == 3;
    positions_.emplace(mesh);
    Info<< "    " << this->modelName() << ": contact at the surface with "
        << returnReduce(walls_->size() - walls_->nRemote(), sumOp<label>())
        << " wall triangles of " << model_->wallPatches().size()
        << " patches (all processors), and copies of "
        << returnReduce(walls_->nRemote(), sumOp<label>())
        << " held by a neighbouring processor, reach "
        << name(0.5*maxDiameter_).c_str() << " m" << endl;
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkMaxDiameter() const
{
    // 20 typed for 20 um: a search to 10 m from every cell. Taken as
    // given (extremeValues), it is said; the impact model's range of
    // diameters is not the search's concern
    const std::string warning = checkedInput::checkMagnitude
    (
        this->coeffDict(), "maxDiameter", maxDiameter_,
        brachDunn::magnitude::diameter, model_->extremeValues()
    );
    if
    (
        !brachDunn::unitMistake
        (
            brachDunn::magnitude::diameter, "maxDiameter", maxDiameter_
        ).empty()
    )
    {
        WarningInFunction
            << "In dictionary " << this->coeffDict().name() << ": "
            << warning.c_str() << endl;
    }

    // Smaller than an injector's size: known now, not only when such a
    // parcel moves; far larger: the search costs memory and time for
    // nothing
    scalar largest = 0;
    wallInteractionCloud::forEachInjectorSize
    (
        this->owner(),
        [&](const dictionary& dict, const word& key, const scalar d)
        {
            if (d > maxDiameter_)
            {
                checkedInput::fail
                (
                    this->coeffDict(), "maxDiameter", name(maxDiameter_),
                    "at least the largest diameter of the parcels: "
                  + dict.name() + '.' + key + " is " + name(d) + " m"
                );
            }
            largest = max(largest, d);
        }
    );
    if (largest > 0 && maxDiameter_ > 10*largest)
    {
        WarningInFunction
            << "Cloud function " << this->modelName() << ": maxDiameter "
            << maxDiameter_ << " m is more than ten times the largest"
            << " diameter the injectors name (" << largest << " m); the"
            << " wall search reaches maxDiameter/2 from every cell, which"
            << " costs memory and time. Set it to the largest diameter of"
            << " the parcels" << endl;
    }
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkOnlyMoves() const
{
    const std::string why =
        ": contact at the surface moves a parcel back to where it touched a"
        " wall, and OpenFOAM has by then exchanged the whole sub-step with"
        " the carrier and the parcel (calc before the cloud functions'"
        " postMove); the part taken back would count twice. Contact at the"
        " surface is for clouds whose sub-steps only move their parcels:"
        " remove " + this->modelName() + " from cloudFunctions (contact at"
        " the centre) or ";
    const cloudSolution& solution = this->owner().solution();
    if (solution.coupled())
    {
        checkedInput::fail
        (
            solution.dict(), "coupled",
            checkedInput::entryText(*checkedInput::find(solution.dict(), "coupled")),
            "two-way coupling" + why + "set coupled false (one-way coupling,"
            " as in dilute aerosols)"
        );
    }
    const dictionary& subModels = this->owner().subModelProperties();
    if (checkedInput::readSwitch(subModels, "radiation", false))
    {
        checkedInput::fail
        (
            subModels, "radiation",
            checkedInput::entryText(*checkedInput::find(subModels, "radiation")),
            "the parcels' radiation" + why + "set radiation off"
        );
    }
    for
    (
        const char* keyword :
        {
            "heatTransferModel", "phaseChangeModel", "devolatilisationModel",
            "surfaceReactionModel", "heterogeneousReactingModel",
            "atomizationModel", "breakupModel"
        }
    )
    {
        if
        (
            checkedInput::find(subModels, keyword)
         && checkedInput::readWord(subModels, keyword) != "none"
        )
        {
            checkedInput::fail
            (
                subModels, keyword, checkedInput::readWord(subModels, keyword),
                "changes the parcels' temperature, mass or size over a"
                " sub-step" + why + "set " + keyword + " none"
            );
        }
    }
}


template<class CloudType>
Foam::scalar Foam::AdhesiveWallSurfaceContact<CloudType>::readMaxDiameter
(
    const dictionary& dict
)
{
    checkedInput::requireKnownKeywords
    (
        dict, {"type", "maxDiameter"},
        "cloud function adhesiveWallSurfaceContact"
    );
    const scalar maxDiameter = checkedInput::readNumber(dict, "maxDiameter");
    if (!(maxDiameter > 0))
    {
        checkedInput::fail
        (
            dict, "maxDiameter", name(maxDiameter), "a diameter > 0 [m]"
        );
    }
    return maxDiameter;
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::stopTooLarge
(
    const typename CloudType::parcelType& p
) const
{
    FatalErrorInFunction
        << "Cloud function " << this->modelName() << " of cloud "
        << this->owner().name() << ": a parcel of diameter " << p.d()
        << " m at " << compat::position(p, this->owner().mesh())
        << " is larger than maxDiameter " << maxDiameter_
        << " m, so walls it touches could be missed. Set maxDiameter to"
        << " the largest diameter the parcels reach (spray parcels grow as"
        << " they heat)" << exit(FatalError);
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkPosition
(
    const typename CloudType::parcelType& p,
    const point& end
) const
{
    const point exact = compat::position(p, this->owner().mesh());
    if (end.x() != exact.x() || end.y() != exact.y() || end.z() != exact.z())
    {
        FatalErrorInFunction
            << "Cloud function " << this->modelName() << " of cloud "
            << this->owner().name() << ": the position from the parcel's tet "
            << setprecision(17) << end << " differs from OpenFOAM's " << exact
            << " (cell " << p.cell() << ", face " << p.tetFace()
            << ", tet point " << p.tetPt() << ")" << exit(FatalError);
    }
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::takeMotionVelocity
(
    typename CloudType::parcelType& p,
    const point& position0,
    const point& end,
    const scalar dt
) const
{
    // OpenFOAM's tracking moves a parcel over a sub-step by its velocity at
    // the sub-step's start (the displacement over the sub-step's time); its
    // velocity now is the end's, which a force may have turned away from
    // the wall within the sub-step, or which holds the next step's draw of
    // exactBrownianMotion (in the sub-step that completes a time step).
    // The displacement gives the start's velocity to the rounding of the
    // positions, some eps |coordinates| / |displacement| of it: wherever
    // that is below 1e-3 it is taken (relative to the coordinates, so that
    // where the mesh's origin is does not matter). A velocity that equals
    // the end's to that rounding (at least 1e-9: no force acted) keeps the
    // end's, exact.
    const vector moved = end - position0;
    const scalar rounding =
        8*std::numeric_limits<scalar>::epsilon()
       *(cmptSum(cmptMag(position0)) + cmptSum(cmptMag(end)))
       /max(cmptSum(cmptMag(moved)), VSMALL);
    if (!(dt > 0 && rounding < 1e-3))
    {
        return;
    }
    vector U = moved/dt;

    // In 2-D the motion in the empty direction is pulled back to the mesh's
    // centre plane: that component stays the parcel's own
    const Vector<label>& solved = this->owner().mesh().solutionD();
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solved[d] < 0)
        {
            U[d] = p.U()[d];
        }
    }
    if (magSqr(U - p.U()) > sqr(max(1e-9, rounding))*magSqr(U))
    {
        p.U() = U;
    }
}


template<class CloudType>
Foam::scalar Foam::AdhesiveWallSurfaceContact<CloudType>::movedOver() const
{
    // v1912's clouds move their parcels over the time's step (a transient
    // cloud's trackTime), and a colliding cloud's collision sub-cycles over
    // the sub-cycle's step, to which the time is set meanwhile
    // (CollidingCloud::motion): a sub-step's dt is that step's part.
    // Steady clouds are refused by the model (wallInteractionCloud::check).
    // Not in a parcel's injection move (InjectionModel::inject moves it
    // over the rest of the step after its injection time, which a cloud
    // function does not see): there too little is taken back (header)
    return this->owner().db().time().deltaTValue();
}


template<class CloudType>
bool Foam::AdhesiveWallSurfaceContact<CloudType>::wedged
(
    const typename CloudType::parcelType& p,
    const std::optional<brachDunn::Contact>& contact
)
{
    // Contacts at the start of the sub-steps in a row, none without one
    // between them (a parcel sliding along a wall touches it at the start
    // of every other sub-step only)
    const labelPair parcel(p.origProc(), p.origId());
    if (!contact || contact->fraction > 0 || parcel != wedged_)
    {
        wedged_ = parcel;
        wedgedContacts_ = 0;
        return false;
    }
    return ++wedgedContacts_ > 100;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AdhesiveWallSurfaceContact<CloudType>::AdhesiveWallSurfaceContact
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    compat::CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    maxDiameter_(readMaxDiameter(this->coeffDict()))
{}


template<class CloudType>
Foam::AdhesiveWallSurfaceContact<CloudType>::AdhesiveWallSurfaceContact
(
    const AdhesiveWallSurfaceContact<CloudType>& other
)
:
    compat::CloudFunctionObject<CloudType>(other),
    maxDiameter_(other.maxDiameter_),
    walls_(other.walls_),
    model_(other.model_),
    counts_(other.counts_),
    threeD_(other.threeD_),
    positions_(other.positions_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::checkMovingWalls() const
{
    // A wall face held here for another processor has no velocity here:
    // its contacts would take the wall as still (the result would depend
    // on the decomposition). Moving walls (a lid, a belt: the tangential
    // velocity their U condition sets) are refused in parallel runs
    if (!Pstream::parRun() || !returnReduce(walls_->nRemote(), sumOp<label>()))
    {
        return;
    }
    const polyBoundaryMesh& patches = compat::boundaryMesh(this->owner().mesh());
    for (const label patchi : model_->wallPatches())
    {
        const fvPatchVectorField& Uw = this->owner().U().boundaryField()[patchi];
        const scalar speed =
            isA<wallPolyPatch>(patches[patchi]) && Uw.fixesValue() && Uw.size()
          ? max(mag(Uw)) : 0;
        const scalar fastest = returnReduce(speed, maxOp<scalar>());
        if (fastest > 0)
        {
            FatalErrorInFunction
                << "Cloud function " << this->modelName() << " of cloud "
                << this->owner().name() << ": wall patch "
                << patches[patchi].name() << " moves (its U condition sets "
                << "up to " << fastest << " m/s) in a parallel run, and contact at the surface"
                << " takes the faces it holds for a neighbouring processor as"
                << " still. Run this case in serial, or without "
                << this->modelName() << " (contact at the centre)"
                << exit(FatalError);
        }
    }
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::beforeEvolve()
{
    setUp();
    checkMovingWalls();
}


template<class CloudType>
void Foam::AdhesiveWallSurfaceContact<CloudType>::afterMove
(
    typename CloudType::parcelType& p,
    const scalar dt,
    const point& position0,
    bool& keepParticle
)
{
    // Only moving parcels in cells within reach of a handled wall pay
    if (!compat::isActive(p) || !keepParticle || !walls_->nearWall(p.cell()))
    {
        return;
    }
    checkDiameter(p);

    // A sub-step moves the centre at most maxCo times the cell's length
    // scale, and in 2-D by the start's deviation from the mesh's centre
    // plane besides (KinematicParcel::move): from farther than that and
    // the radius from every wall near the cell, the sphere touches none,
    // and the end of the sub-step need not be found (most sub-steps in a
    // wall cell). The margin of 1e-9 covers the rounding of the positions.
    scalar reach =
        0.5*p.d()
      + this->owner().solution().maxCo()
       *this->owner().cellLengthScale()[p.cell()];
    if (!threeD_)
    {
        point centred = position0;
        meshTools::constrainToMeshCentre(this->owner().mesh(), centred);
        reach += mag(position0 - centred);
    }
    if (walls_->apart(p.cell(), position0, reach*(1 + 1e-9)))
    {
        return;
    }

    const point end = (*positions_)(p);
    if (debug)
    {
        checkPosition(p, end);
    }
    const std::optional<brachDunn::Contact> contact =
        walls_->firstContact(p.cell(), position0, end, 0.5*p.d());
    if (wedged(p, contact) || !contact)
    {
        return;
    }

    // Back to where the sphere touched, and the step's time with it
    const point centre = position0 + contact->fraction*(end - position0);
    if (contact->fraction < 1)
    {
        surfaceTracking::moveBackTo
        (
            p,
            *positions_,
            centre - end,
            centre,
            (1 - contact->fraction)*dt/movedOver(),
            debug != 0
        );
        // (OpenFOAM aged it by the whole sub-step before postMove)
        p.age() -= (1 - contact->fraction)*dt;
    }

    // The wall normal out of the domain, from the centre to the closest
    // point (a centre on the wall, a parcel of zero size: the direction of
    // motion)
    const wallTriangles::origin& origin = walls_->originOf(contact->triangle);
    const point touched(contact->point.x, contact->point.y, contact->point.z);
    vector nw = touched - centre;
    if (mag(nw) <= VSMALL)
    {
        nw = end - position0;
    }
    nw /= mag(nw);

    takeMotionVelocity(p, position0, end, dt);
    model_->touch
    (
        p, origin.patchi, origin.facei, origin.proc, nw, keepParticle
    );
}


// ************************************************************************* //
