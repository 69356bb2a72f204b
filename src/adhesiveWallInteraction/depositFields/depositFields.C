#include "depositFields.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

volScalarField field
(
    const fvMesh& mesh,
    const word& name,
    const dimensionSet& dims
)
{
    return volScalarField
    (
        IOobject
        (
            name,
            compat::timeName(mesh.time()),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("zero", dims, 0)
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::depositFields::depositFields(const fvMesh& mesh, const word& cloudName)
:
    massStick_(field(mesh, cloudName + ":massStick", dimMass)),
    nStick_(field(mesh, cloudName + ":nStick", dimless)),
    massEscape_(field(mesh, cloudName + ":massEscape", dimMass))
{}
