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


template<class CloudType>
Foam::scalar Foam::AdhesiveWallSurfaceContact<CloudType>::reach
(
    const typename CloudType::parcelType& p,
    const point& position0
) const
{
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
    return reach;
}


template<class CloudType>
inline void Foam::AdhesiveWallSurfaceContact<CloudType>::touch
(
    typename CloudType::parcelType& p,
    const scalar dt,
    const point& position0,
    const point& end,
    const brachDunn::Contact& contact,
    bool& keepParticle
)
{
    // Back to where the sphere touched, and the step's time with it
    const point centre = position0 + contact.fraction*(end - position0);
    if (contact.fraction < 1)
    {
        surfaceTracking::moveBackTo
        (
            p,
            *positions_,
            centre - end,
            centre,
            (1 - contact.fraction)*dt/movedOver(),
            debug != 0
        );
        // (OpenFOAM aged it by the whole sub-step before postMove)
        p.age() -= (1 - contact.fraction)*dt;
    }

    // The wall normal out of the domain, from the centre to the closest
    // point (a centre on the wall, a parcel of zero size: the direction of
    // motion)
    const wallTriangles::origin& origin = walls_->originOf(contact.triangle);
    const point touched(contact.point.x, contact.point.y, contact.point.z);
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

    // From farther than the sphere's reach from every wall near the cell,
    // it touches none, and the end of the sub-step need not be found (most
    // sub-steps in a wall cell). The margin of 1e-9 covers the rounding of
    // the positions.
    if (walls_->apart(p.cell(), position0, reach(p, position0)*(1 + 1e-9)))
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
    if (!wedged(p, contact) && contact)
    {
        touch(p, dt, position0, end, *contact, keepParticle);
    }
}


// ************************************************************************* //

#include "AdhesiveWallSurfaceContactChecks.C"

// ************************************************************************* //
