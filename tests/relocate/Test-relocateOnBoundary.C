// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// surfaceTracking::relocateInCell against v1912's particle::relocate at positions
// on a cell's boundary faces as rounding puts them: the centres of the
// case's floor faces (z = 0 exactly) and those points moved out of the
// mesh by 1e-13 of the cell's size (a few hundred units in the last place
// of the coordinates); and at a position inside the cell. Run in a case
// with a floor patch (tests/relocate/test builds one).
// Expected: relocate stops at the points just outside (the premise: v1912
// takes them as "outside of the mesh"); relocateInCell puts the parcel at
// each point to 1e-9 of the cell's size, in the same cell; inside the
// cell both agree exactly; a point a tenth of the cell beyond the face
// stops relocateInCell too.

#include "fvCFD.H"
#include "passiveParticle.H"
#include "surfaceTracking.H"

namespace
{

// Whether the call stopped the run (FatalError thrown)
template<class Call>
bool stops(Call call)
{
    try
    {
        const Foam::compat::fatalErrorsThrow throwing;
        call();
    }
    catch (const Foam::error&)
    {
        return true;
    }
    return false;
}

} // End namespace


int main(int argc, char* argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const polyPatch& floor = mesh.boundaryMesh()[mesh.boundaryMesh().findPatchID("floor")];
    label failures = 0;
    label premise = 0;
    forAll(floor, k)
    {
        const label facei = floor.start() + k;
        const label celli = mesh.faceOwner()[facei];
        const vector outward = mesh.faceAreas()[facei]/mag(mesh.faceAreas()[facei]);
        const point onFace = mesh.faceCentres()[facei];
        const point centre = mesh.cellCentres()[celli];
        const scalar size = Foam::cbrt(mesh.cellVolumes()[celli]);
        for (const scalar out : {0.0, 1e-13})
        {
            const point target = onFace + out*size*outward;
            passiveParticle plain(mesh, centre, celli);
            if (out > 0 && stops([&]{ plain.relocate(target, celli); }))
            {
                ++premise;
            }

            passiveParticle p(mesh, centre, celli);
            if (stops([&]{ surfaceTracking::relocateInCell(p, target); }))
            {
                Info<< "face " << k << " (" << out << "): relocateInCell stopped" << nl;
                ++failures;
            }
            else if (p.cell() != celli || mag(p.position() - target) > 1e-9*size)
            {
                Info<< "face " << k << " (" << out << "): at " << p.position()
                    << " in cell " << p.cell() << ", not " << target << " in "
                    << celli << nl;
                ++failures;
            }
        }
        const point target = onFace;

        // Inside the cell: as relocate
        const point inside = 0.5*(target + centre);
        passiveParticle q(mesh, centre, celli), r(mesh, centre, celli);
        q.relocate(inside, celli);
        surfaceTracking::relocateInCell(r, inside);
        if (q.position() != r.position() || q.cell() != r.cell())
        {
            Info<< "face " << k << ": inside, " << r.position() << " not "
                << q.position() << nl;
            ++failures;
        }

        // Beyond the face: outside the mesh, which still stops
        passiveParticle s(mesh, centre, celli);
        if (!stops([&]{ surfaceTracking::relocateInCell(s, target + 0.1*(target - centre)); }))
        {
            Info<< "face " << k << ": a position beyond the face ran on" << nl;
            ++failures;
        }
    }
    Info<< floor.size() << " floor faces: relocate stopped at " << premise
        << " of the points just outside them; " << failures << " failures" << endl;
    // (the premise, seen on v1912 at every face: without it the catch is
    // not exercised)
    return failures || premise != floor.size() ? 1 : 0;
}
