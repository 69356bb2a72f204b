// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later

#include "surfaceContactCounts.H"
#include "ListOps.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "OSspecific.H"

const Foam::wordList Foam::surfaceContactCounts::columns
({
    "time", "patch", "surfaceContacts", "centreContacts"
});


Foam::surfaceContactCounts::surfaceContactCounts
(
    const polyBoundaryMesh& boundary,
    const labelList& patches
)
:
    patches_(patches),
    names_(patches.size()),
    surface_(boundary.size(), Zero),
    centre_(boundary.size(), Zero),
    storedSurface_(patches.size(), Zero),
    storedCentre_(patches.size(), Zero)
{
    forAll(patches, i)
    {
        names_[i] = boundary[patches[i]].name();
    }
}


void Foam::surfaceContactCounts::keep
(
    std::unique_ptr<modelProperties> properties,
    const fileName& file,
    const word& cloudName
)
{
    properties_ = std::move(properties);
    labelList stored;
    properties_->get("surfaceContact", stored);
    restore(stored);
    if (!file.empty() && Pstream::master())
    {
        file_.reset(new OFstream(file));
        writeHeader(*file_, cloudName);
    }
}


void Foam::surfaceContactCounts::add(const wallEvent& event)
{
    // The impacts taken, as the statistics count them: not a touch whose
    // velocity points away from the wall, which the model leaves alone
    // (no event); a centre's only on the walls of the surface contact
    if (event.via == wallEvent::contact::surface)
    {
        ++surface_[event.patchi];
    }
    else if (event.via == wallEvent::contact::centre && handles(event.patchi))
    {
        ++centre_[event.patchi];
    }
}


void Foam::surfaceContactCounts::stepDone
(
    Ostream& os,
    const word& timeName,
    const bool writeTime
)
{
    const labelList counts(totals());
    print(os, counts);
    if (file_)
    {
        write(*file_, timeName, counts);
    }
    if (writeTime && properties_)
    {
        properties_->set("surfaceContact", counts);
    }
}


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
