// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// A kinematic colliding cloud moved through a case's frozen flow as
// icoUncoupledKinematicParcelFoam moves it (the cloud's own evolve(), which
// calls its info() once), with the cloud's info() called a second time
// after each step: what a solver or function object that asks the cloud
// for its information again does. The patch interaction model's end of
// step (the resuspension's, called from its info hook) must run once a
// step all the same; tests/cases/resuspension/test compares this run's
// outputs with the solver's.
//
//     Test-infoTwice [-cloud name]    (in a case; default kinematicCloud)

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "basicKinematicCollidingCloud.H"

int main(int argc, char* argv[])
{
    argList::addOption("cloud", "name", "The cloud (default kinematicCloud)");
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    const word cloudName =
        args.lookupOrDefault<word>("cloud", "kinematicCloud");

    IOdictionary transportProperties
    (
        IOobject
        (
            "transportProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const dimensionedScalar rhoInfValue
    (
        "rhoInf", dimDensity, transportProperties
    );
    volScalarField rhoInf
    (
        IOobject
        (
            "rho", runTime.timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE
        ),
        mesh,
        rhoInfValue
    );
    volVectorField U
    (
        IOobject
        (
            "U", runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        ),
        mesh
    );
    #include "createPhi.H"
    singlePhaseTransportModel laminarTransport(U, phi);
    autoPtr<incompressible::turbulenceModel> turbulence
    (
        incompressible::turbulenceModel::New(U, phi, laminarTransport)
    );
    volScalarField mu
    (
        IOobject
        (
            "mu", runTime.timeName(), mesh,
            IOobject::NO_READ, IOobject::NO_WRITE
        ),
        laminarTransport.nu()*rhoInfValue
    );

    basicKinematicCollidingCloud cloud(cloudName, rhoInf, U, mu, g);

    while (runTime.loop())
    {
        Info<< "Time = " << runTime.timeName() << nl << endl;
        cloud.evolve();
        Info<< "The cloud's info() a second time in this step" << endl;
        cloud.info();
        runTime.write();
    }
    Info<< "End" << endl;
    return 0;
}
