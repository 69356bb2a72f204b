// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "depositFields.H"
#include "PstreamBuffers.H"
#include "releaseCompat.H"
#include "OSspecific.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

IOobject fieldIO(const fvMesh& mesh, const word& name)
{
    return IOobject
    (
        name,
        compat::timeName(mesh.time()),
        mesh,
        IOobject::READ_IF_PRESENT,
        IOobject::AUTO_WRITE
    );
}


//- The field, read if present; missing collects those that were not
volScalarField field
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims,
    wordList& missing
)
{
    const IOobject io(fieldIO(mesh, name));
    if (!isFile(compat::objectPath(io)))
    {
        missing.append(name);
    }
    return volScalarField(io, mesh, dimensionedScalar("zero", dims, 0));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depositFields::depositFields(const fvMesh& mesh, const word& cloudName)
:
    missing_(),
    massStick_(field(mesh, cloudName + ":massStick", dimMass, missing_)),
    nStick_(field(mesh, cloudName + ":nStick", dimless, missing_)),
    massEscape_(field(mesh, cloudName + ":massEscape", dimMass, missing_)),
    remote_(Pstream::nProcs())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::wordList Foam::depositFields::missing() const
{
    // Each processor reads its own files: missing on any is missing
    wordList result;
    for (const word& name : {massStick_.name(), nStick_.name(), massEscape_.name()})
    {
        bool missing =
            std::find(missing_.begin(), missing_.end(), name) != missing_.end();
        reduce(missing, orOp<bool>());
        if (missing)
        {
            result.append(name);
        }
    }
    return result;
}

void Foam::depositFields::addCapture
(
    const label patchi,
    const label facei,
    const scalar mass,
    const scalar nParticle,
    const label proc
)
{
    if (proc < 0 || proc == Pstream::myProcNo())
    {
        massStick_.boundaryFieldRef()[patchi][facei] += mass;
        nStick_.boundaryFieldRef()[patchi][facei] += nParticle;
    }
    else
    {
        remote_[proc].append({scalar(patchi), scalar(facei), mass, nParticle, 0});
    }
}


void Foam::depositFields::addEscape
(
    const label patchi,
    const label facei,
    const scalar mass,
    const label proc
)
{
    if (proc < 0 || proc == Pstream::myProcNo())
    {
        massEscape_.boundaryFieldRef()[patchi][facei] += mass;
    }
    else
    {
        remote_[proc].append({scalar(patchi), scalar(facei), 0, 0, mass});
    }
}


void Foam::depositFields::exchange()
{
    if (!Pstream::parRun())
    {
        return;
    }
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(remote_, proci)
    {
        if (proci != Pstream::myProcNo())
        {
            UOPstream toProc(proci, buffers);
            toProc << remote_[proci];
            remote_[proci].clear();
        }
    }
    buffers.finishedSends();
    forAll(remote_, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream fromProc(proci, buffers);
        scalarList received(fromProc);
        for (label i = 0; i + 4 < received.size(); i += 5)
        {
            const label patchi = label(received[i]);
            const label facei = label(received[i + 1]);
            massStick_.boundaryFieldRef()[patchi][facei] += received[i + 2];
            nStick_.boundaryFieldRef()[patchi][facei] += received[i + 3];
            massEscape_.boundaryFieldRef()[patchi][facei] += received[i + 4];
        }
    }
}


// ************************************************************************* //
