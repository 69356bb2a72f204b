// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallTriangles.H"
#include "Time.H"

namespace Foam
{
    defineTypeNameAndDebug(wallTriangles, 0);
}

namespace
{

Foam::word registeredName(const Foam::word& cloudName)
{
    return cloudName + ":wallTriangles";
}

} // End anonymous namespace


Foam::wallTriangles::wallTriangles
(
    const IOobject& io,
    const polyMesh& mesh,
    const labelList& patches,
    const scalar reach
)
:
    regIOobject(io)
{
    addLocal(mesh, patches);
    addRemote(mesh, reach);
    addCandidates(mesh, reach);
    groupByPlane(mesh, reach);
}


const Foam::wallTriangles& Foam::wallTriangles::New
(
    const polyMesh& mesh,
    const word& cloudName,
    const labelList& patches,
    const scalar reach
)
{
    // One surface contact per cloud: a second one of the cloud gets these
    // and stops when it asks the model for contact at the surface
    // (AdhesiveWallInteraction::useSurfaceContact)
    const word name(registeredName(cloudName));
    if (mesh.thisDb().foundObject<wallTriangles>(name))
    {
        return mesh.thisDb().lookupObject<wallTriangles>(name);
    }
    wallTriangles* built = new wallTriangles
    (
        IOobject
        (
            name, mesh.time().constant(), mesh.thisDb(),
            IOobject::NO_READ, IOobject::NO_WRITE, true
        ),
        mesh, patches, reach
    );
    built->store();
    return *built;
}


const Foam::wallTriangles& Foam::wallTriangles::of
(
    const polyMesh& mesh,
    const word& cloudName
)
{
    return mesh.thisDb().lookupObject<wallTriangles>(registeredName(cloudName));
}


// ************************************************************************* //
