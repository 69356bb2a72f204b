// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later

#include "surfaceContactCounts.H"
#include "ListOps.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

const Foam::wordList Foam::surfaceContactCounts::columns
({
    "time", "patch", "surfaceContacts", "centreContacts"
});


Foam::surfaceContactCounts::surfaceContactCounts
(
    const labelList& patches,
    const wordList& names,
    const label nMeshPatches
)
:
    patches_(patches),
    names_(names),
    surface_(nMeshPatches, Zero),
    centre_(nMeshPatches, Zero),
    storedSurface_(patches.size(), Zero),
    storedCentre_(patches.size(), Zero)
{}


bool Foam::surfaceContactCounts::handles(const label patchi) const
{
    return patches_.found(patchi);
}


Foam::labelList Foam::surfaceContactCounts::totals() const
{
    labelList totals(2*patches_.size());
    forAll(patches_, i)
    {
        totals[2*i] = returnReduce(surface_[patches_[i]], sumOp<label>())
          + storedSurface_[i];
        totals[2*i + 1] = returnReduce(centre_[patches_[i]], sumOp<label>())
          + storedCentre_[i];
    }
    return totals;
}


void Foam::surfaceContactCounts::restore(const labelList& stored)
{
    if (stored.size() != 2*patches_.size())
    {
        return;
    }
    forAll(patches_, i)
    {
        storedSurface_[i] = stored[2*i];
        storedCentre_[i] = stored[2*i + 1];
    }
}


void Foam::surfaceContactCounts::print
(
    Ostream& os,
    const labelList& totals
) const
{
    forAll(patches_, i)
    {
        os  << "    adhesiveWallSurfaceContact " << names_[i]
            << ": contacts at the surface " << totals[2*i]
            << ", at the centre (fallback) " << totals[2*i + 1] << nl;
    }
}


void Foam::surfaceContactCounts::writeHeader
(
    Ostream& os,
    const word& cloudName
) const
{
    os  << "# adhesiveWallSurfaceContact of cloud " << cloudName
        << ": impacts since the start of the case where the parcel's surface"
        << " touched a wall (surfaceContacts) and where its centre reached a"
        << " wall face first (centreContacts, the fallback)" << nl << '#';
    forAll(columns, i)
    {
        os  << (i ? "\t" : " ") << columns[i];
    }
    os  << nl;
}


void Foam::surfaceContactCounts::write
(
    Ostream& os,
    const word& timeName,
    const labelList& totals
) const
{
    forAll(patches_, i)
    {
        os  << timeName << '\t' << names_[i] << '\t' << totals[2*i] << '\t'
            << totals[2*i + 1] << nl;
    }
    os.flush();
}


// ************************************************************************* //
