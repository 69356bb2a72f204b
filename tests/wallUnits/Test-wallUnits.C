// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// wallUnits in a case: its carrier U of the start time, the density rhoInf
// and viscosity rhoInf nu of constant/transportProperties; writes the wall
// distance, normal and friction velocity of every cell to the start time
// (wallUnits:y, wallUnits:normal, wallUnits:uStar) for tests/wallUnits/test
// to compare with the flow's exact values. Asked a second time for the
// same U, wallUnits gives the same object without computing again.

#include "fvCFD.H"
#include "wallUnits.H"

int main(int argc, char* argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    IOdictionary transportProperties
    (
        IOobject
        (
            "transportProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const dimensionedScalar rhoInf("rhoInf", dimDensity, transportProperties);
    const dimensionedScalar nu("nu", dimViscosity, transportProperties);
    volVectorField U
    (
        IOobject
        (
            "U", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        ),
        mesh
    );
    const volScalarField rho
    (
        IOobject("rho", runTime.timeName(), mesh),
        mesh,
        rhoInf
    );
    const volScalarField mu
    (
        IOobject("mu", runTime.timeName(), mesh),
        mesh,
        rhoInf*nu
    );

    const wallUnits& units = wallUnits::New(U, rho, mu);
    if (&wallUnits::New(U, rho, mu) != &units)
    {
        FatalErrorInFunction << "a second wallUnits" << exit(FatalError);
    }
    for
    (
        const regIOobject* field :
        {
            static_cast<const regIOobject*>(&units.y()),
            static_cast<const regIOobject*>(&units.normal()),
            static_cast<const regIOobject*>(&units.uStar())
        }
    )
    {
        field->write();
    }
    Info<< "End" << endl;
    return 0;
}
