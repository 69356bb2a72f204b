// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "depositSites.H"
#include "carrierTurbulence.H"
#include "releaseCompat.H"

Foam::depositSites::depositSites
(
    const fvMesh& mesh,
    const boolList& resuspends,
    const labelList& walls
)
:
    mesh_(mesh),
    resuspends_(resuspends),
    walls_(resuspends.size(), false),
    flow_(resuspends.size())
{
    for (const label patchi : walls)
    {
        walls_[patchi] = true;
    }
    forAll(resuspends_, patchi)
    {
        walls_[patchi] = walls_[patchi] || resuspends_[patchi];
    }
}


std::optional<Foam::depositSites::site> Foam::depositSites::find
(
    const label celli,
    const point& p,
    const scalar d
) const
{
    const polyBoundaryMesh& patches = compat::boundaryMesh(mesh_);
    const scalar reach = 0.5*d*(1 + 1e-3);
    std::optional<site> nearest;
    scalar nearestDistance = reach;

    for (const label facei : mesh_.cells()[celli])
    {
        if (mesh_.isInternalFace(facei))
        {
            continue;
        }
        const label patchi = patches.whichPatch(facei);
        if (!walls_[patchi])
        {
            continue;
        }
        const scalar distance =
            mesh_.faces()[facei].nearestPoint(p, mesh_.points()).distance();
        if (distance <= nearestDistance)
        {
            nearestDistance = distance;
            const vector& area = mesh_.faceAreas()[facei];
            nearest = site{patchi, facei - patches[patchi].start(), area/mag(area)};
        }
    }

    if (triangles_)
    {
        const auto triangle = triangles_->nearestLocal(celli, p);
        if (triangle && triangle->second < nearestDistance)
        {
            const wallTriangles::origin& from =
                triangles_->originOf(triangle->first);
            const label facei = patches[from.patchi].start() + from.facei;
            const vector& area = mesh_.faceAreas()[facei];
            nearest = site{from.patchi, from.facei, area/mag(area)};
        }
    }

    // The deposit sits on the nearest wall of the model: on a wall that
    // does not resuspend it stays (in a corner, a deposit on a plain stick
    // wall is not the floor's)
    if (nearest && !resuspends_[nearest->patchi])
    {
        return std::nullopt;
    }
    return nearest;
}


void Foam::depositSites::update
(
    const volVectorField& U,
    const volScalarField& rho,
    const volScalarField& mu
)
{
    const carrierTurbulence turbulence(U);
    turbulent_ = turbulence.turbulent();

    forAll(resuspends_, patchi)
    {
        if (!resuspends_[patchi])
        {
            continue;
        }
        const fvPatch& patch = mesh_.boundary()[patchi];
        const vectorField n(patch.nf());
        const vectorField gradU(U.boundaryField()[patchi].snGrad());
        const scalarField rhoC(rho.boundaryField()[patchi].patchInternalField());
        const scalarField muC(mu.boundaryField()[patchi].patchInternalField());
        const tmp<scalarField> nutW(turbulence.nut(patch));

        List<flow>& faces = flow_[patchi];
        faces.setSize(patch.size());
        forAll(faces, facei)
        {
            const vector tangential = gradU[facei] - (n[facei] & gradU[facei])*n[facei];
            faces[facei] =
            {
                (muC[facei] + rhoC[facei]*nutW()[facei])*mag(tangential),
                rhoC[facei],
                muC[facei]/rhoC[facei]
            };
        }
    }
}
