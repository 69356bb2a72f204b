// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "depositFields.H"
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
    massEscape_(field(mesh, cloudName + ":massEscape", dimMass, missing_))
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
