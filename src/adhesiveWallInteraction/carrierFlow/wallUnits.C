// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "wallUnits.H"
#include "carrierTurbulence.H"
#include "wallDistData.H"
#include "wallPointData.H"
#include "wallPolyPatch.H"

namespace Foam
{
    defineTypeNameAndDebug(wallUnits, 0);
}


namespace
{

Foam::IOobject fieldObject(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name, mesh.time().timeName(), mesh,
        Foam::IOobject::NO_READ, Foam::IOobject::NO_WRITE, false
    );
}

} // End anonymous namespace


Foam::wallUnits::wallUnits(const IOobject& io, const fvMesh& mesh)
:
    regIOobject(io),
    y_(fieldObject(mesh, "wallUnits:y"), mesh, dimensionedScalar(dimLength)),
    normal_
    (
        fieldObject(mesh, "wallUnits:normal"), mesh,
        dimensionedVector(dimless, Zero)
    ),
    uStar_
    (
        fieldObject(mesh, "wallUnits:uStar"), mesh,
        dimensionedScalar(dimVelocity)
    )
{}


void Foam::wallUnits::compute
(
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
)
{
    const fvMesh& mesh = U.mesh();
    const carrierTurbulence turbulence(U);
    volVectorField normal(normal_);
    volScalarField uStar(uStar_);
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (!isA<wallPolyPatch>(patch.patch()))
        {
            continue;
        }
        const scalarField rhoW
        (
            rho.boundaryField()[patchi].patchInternalField()
        );
        normal.boundaryFieldRef()[patchi] == -patch.nf();
        uStar.boundaryFieldRef()[patchi] ==
            sqrt(turbulence.wallShearStress(patch, U, rho, mu)/rhoW);
    }
    wallDistData<wallPointData<vector>> normals(mesh, normal, true);
    wallDistData<wallPointData<scalar>> speeds(mesh, uStar, true);
    y_ = normals.y();
    normal_ = normal;
    uStar_ = uStar;
    computedFor_ = U.eventNo();
}


const Foam::wallUnits& Foam::wallUnits::New
(
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
)
{
    const fvMesh& mesh = U.mesh();
    const word name("wallUnits:" + U.name());
    wallUnits* units = mesh.thisDb().getObjectPtr<wallUnits>(name);
    if (!units)
    {
        units = new wallUnits
        (
            IOobject
            (
                name, mesh.time().constant(), mesh.thisDb(),
                IOobject::NO_READ, IOobject::NO_WRITE, true
            ),
            mesh
        );
        units->store();
    }
    if (units->computedFor_ != U.eventNo())
    {
        units->compute(U, rho, mu);
    }
    return *units;
}


// ************************************************************************* //
