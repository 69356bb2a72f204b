// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "depositSites.H"
#include "carrierTurbulence.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
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
    // The deposit sits on the nearest wall of the model: on a wall that
    // does not resuspend it stays (in a corner, a deposit on a plain stick
    // wall is not the floor's)
    const std::optional<site> nearest = nearestWall(celli, p, 0.5*d*(1 + 1e-3));
    if (nearest && !resuspends_[nearest->patchi])
    {
        return std::nullopt;
    }
    return nearest;
}


std::optional<Foam::depositSites::site> Foam::depositSites::nearestWall
(
    const label celli,
    const point& p,
    const scalar reach
) const
{
    const polyBoundaryMesh& patches = compat::boundaryMesh(mesh_);
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
            nearest = site{patchi, facei - patches[patchi].start(), area/mag(area), -1};
        }
    }

    if (triangles_)
    {
        const auto triangle = triangles_->nearest(celli, p);
        if (triangle && triangle->second < nearestDistance)
        {
            const wallTriangles::origin& from =
                triangles_->originOf(triangle->first);
            if (from.proc != Pstream::myProcNo() && !resuspends_[from.patchi])
            {
                // Another processor's wall that does not resuspend (its
                // normal is not needed)
                return site{from.patchi, from.facei, Zero, from.proc};
            }
            // (a remote face's area vector from its triangles, ask())
            const vector& area =
                from.proc == Pstream::myProcNo()
              ? mesh_.faceAreas()[patches[from.patchi].start() + from.facei]
              : remoteArea_[from.proc]
                [
                    remoteIndex_[from.proc][labelPair(from.patchi, from.facei)]
                ];
            nearest = site
            {
                from.patchi, from.facei, area/mag(area),
                from.proc == Pstream::myProcNo() ? -1 : from.proc
            };
        }
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
        const scalarField rhoC(rho.boundaryField()[patchi].patchInternalField());
        const scalarField muC(mu.boundaryField()[patchi].patchInternalField());
        const tmp<scalarField> tau
        (
            turbulence.wallShearStress(patch, U, rho, mu)
        );

        List<flow>& faces = flow_[patchi];
        faces.setSize(patch.size());
        forAll(faces, facei)
        {
            faces[facei] =
                {tau()[facei], rhoC[facei], muC[facei]/rhoC[facei]};
        }
    }
    exchange();
}


const Foam::depositSites::flow& Foam::depositSites::flowAt
(
    const site& s
) const
{
    if (s.proc < 0)
    {
        return flow_[s.patchi][s.facei];
    }
    const auto found = remoteIndex_[s.proc].cfind(labelPair(s.patchi, s.facei));
    if (found.found())
    {
        return remoteFlow_[s.proc][*found];
    }
    FatalErrorInFunction
        << "No flow of face " << s.facei << " of patch " << s.patchi
        << " of processor " << s.proc << " was asked for"
        << exit(FatalError);
    return remoteFlow_[s.proc][0];
}


Foam::List<Foam::DynamicList<Foam::labelPair>>
Foam::depositSites::remoteFaces()
{
    // The resuspending faces of other processors held here within reach
    // of this processor's cells, once each, and their area vectors
    const std::vector<bool> candidate(triangles_->candidates());
    List<DynamicList<labelPair>> faces(Pstream::nProcs());
    List<DynamicList<vector>> areas(Pstream::nProcs());
    for (label t = 0; t < triangles_->size(); ++t)
    {
        const wallTriangles::origin& from = triangles_->originOf(t);
        if
        (
            from.proc == Pstream::myProcNo() || !resuspends_[from.patchi]
         || !candidate[t]
        )
        {
            continue;
        }
        const labelPair face(from.patchi, from.facei);
        if (remoteIndex_[from.proc].insert(face, faces[from.proc].size()))
        {
            faces[from.proc].append(face);
            areas[from.proc].append(Zero);
        }
        areas[from.proc][remoteIndex_[from.proc][face]] += triangles_->areaVector(t);
    }
    forAll(areas, proc)
    {
        remoteArea_[proc] = areas[proc];
    }
    return faces;
}


void Foam::depositSites::ask()
{
    asking_ = true;
    remoteIndex_.setSize(Pstream::nProcs());
    remoteArea_.setSize(Pstream::nProcs());
    askedHere_.setSize(Pstream::nProcs());
    asked_.setSize(Pstream::nProcs());
    remoteFlow_.setSize(Pstream::nProcs());
    if (!triangles_ || !Pstream::parRun())
    {
        return;
    }

    const List<DynamicList<labelPair>> faces(remoteFaces());

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(faces, proc)
    {
        askedHere_[proc] = faces[proc];
        if (proc != Pstream::myProcNo() && faces[proc].size())
        {
            labelList flat(2*faces[proc].size());
            forAll(faces[proc], i)
            {
                flat[2*i] = faces[proc][i].first();
                flat[2*i + 1] = faces[proc][i].second();
            }
            UOPstream toProc(proc, buffers);
            toProc << flat;
        }
    }
    labelList received;
    buffers.finishedSends(received);
    forAll(asked_, proc)
    {
        if (proc != Pstream::myProcNo() && received[proc] > 0)
        {
            labelList flat;
            UIPstream fromProc(proc, buffers);
            fromProc >> flat;
            asked_[proc].setSize(flat.size()/2);
            forAll(asked_[proc], i)
            {
                asked_[proc][i] = labelPair(flat[2*i], flat[2*i + 1]);
            }
        }
    }
}


void Foam::depositSites::exchange()
{
    if (!asking_)
    {
        ask();
    }
    if (!triangles_ || !Pstream::parRun())
    {
        return;
    }
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(asked_, proc)
    {
        if (asked_[proc].empty())
        {
            continue;
        }
        scalarList values(3*asked_[proc].size());
        forAll(asked_[proc], i)
        {
            const flow& f = flow_[asked_[proc][i].first()][asked_[proc][i].second()];
            values[3*i] = f.tauW;
            values[3*i + 1] = f.rho;
            values[3*i + 2] = f.nu;
        }
        UOPstream toProc(proc, buffers);
        toProc << values;
    }
    buffers.finishedSends();
    forAll(askedHere_, proc)
    {
        remoteFlow_[proc].setSize(askedHere_[proc].size());
        if (askedHere_[proc].empty())
        {
            continue;
        }
        scalarList values;
        UIPstream fromProc(proc, buffers);
        fromProc >> values;
        forAll(remoteFlow_[proc], i)
        {
            remoteFlow_[proc][i] = {values[3*i], values[3*i + 1], values[3*i + 2]};
        }
    }
}
