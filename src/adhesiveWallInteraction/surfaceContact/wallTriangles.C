// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later

#include "wallTriangles.H"
#include "PstreamBuffers.H"
#include "treeDataCell.H"
#include "indexedOctree.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

brachDunn::Vector3 toCore(const Foam::point& p)
{
    return {p.x(), p.y(), p.z()};
}


Foam::point toFoam(const brachDunn::Vector3& p)
{
    return Foam::point(p.x, p.y, p.z);
}


//- The triangle's bounding box grown by reach
Foam::treeBoundBox grownBox(const brachDunn::Triangle& t, const Foam::scalar reach)
{
    using Foam::min;
    using Foam::max;
    const Foam::point a(toFoam(t.a)), b(toFoam(t.b)), c(toFoam(t.c));
    const Foam::vector grow(reach, reach, reach);
    return Foam::treeBoundBox(min(a, min(b, c)) - grow, max(a, max(b, c)) + grow);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wallTriangles::addLocal
(
    const polyMesh& mesh,
    const labelList& patches
)
{
    const pointField& points = mesh.points();
    const labelList& basePoints = mesh.tetBasePtIs();
    for (const label patchi : patches)
    {
        const polyPatch& pp = compat::boundaryMesh(mesh)[patchi];
        forAll(pp, facei)
        {
            const face& f = pp[facei];
            // The fan from the tracking's base point (0 where it has none)
            const label base = max(basePoints[pp.start() + facei], 0);
            for (label k = 1; k + 1 < f.size(); ++k)
            {
                triangles_.push_back
                ({
                    toCore(points[f[base]]),
                    toCore(points[f[(base + k) % f.size()]]),
                    toCore(points[f[(base + k + 1) % f.size()]])
                });
                origins_.push_back({Pstream::myProcNo(), patchi, facei});
            }
        }
    }
}


void Foam::wallTriangles::addRemote(const polyMesh& mesh, const scalar reach)
{
    if (!Pstream::parRun())
    {
        return;
    }

    // Every processor's box, grown by reach
    List<treeBoundBox> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = treeBoundBox(boundBox(mesh.points(), false));
    const vector grow(reach, reach, reach);
    boxes[Pstream::myProcNo()].min() -= grow;
    boxes[Pstream::myProcNo()].max() += grow;
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);

    // Send each processor the local triangles within its box: the three
    // points and the patch and face
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    const label nLocal = size();
    forAll(boxes, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        DynamicList<point> points;
        DynamicList<label> faces;
        for (label i = 0; i < nLocal; ++i)
        {
            const brachDunn::Triangle& t = triangles_[i];
            if (boxes[proci].overlaps(grownBox(t, 0)))
            {
                points.append(toFoam(t.a));
                points.append(toFoam(t.b));
                points.append(toFoam(t.c));
                faces.append(origins_[i].patchi);
                faces.append(origins_[i].facei);
            }
        }
        UOPstream toProc(proci, buffers);
        toProc << points << faces;
    }
    buffers.finishedSends();

    forAll(boxes, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream fromProc(proci, buffers);
        List<point> points;
        labelList faces;
        fromProc >> points >> faces;
        for (label i = 0; i < faces.size()/2; ++i)
        {
            triangles_.push_back
            ({
                toCore(points[3*i]),
                toCore(points[3*i + 1]),
                toCore(points[3*i + 2])
            });
            origins_.push_back({proci, faces[2*i], faces[2*i + 1]});
        }
    }
    nRemote_ = size() - nLocal;
}


void Foam::wallTriangles::addCandidates
(
    const polyMesh& mesh,
    const scalar reach
)
{
    // Count, then fill the compressed rows
    const indexedOctree<treeDataCell>& cells = mesh.cellTree();
    List<labelList> cellsOf(size());
    std::vector<int> nOf(mesh.nCells() + 1, 0);
    for (label i = 0; i < size(); ++i)
    {
        cellsOf[i] = cells.findBox(grownBox(triangles_[i], reach));
        for (const label celli : cellsOf[i])
        {
            ++nOf[celli];
        }
    }

    cellStart_.assign(mesh.nCells() + 1, 0);
    for (label celli = 0; celli < mesh.nCells(); ++celli)
    {
        cellStart_[celli + 1] = cellStart_[celli] + nOf[celli];
    }
    cellTriangles_.assign(cellStart_.back(), 0);
    std::vector<int> filled(cellStart_.begin(), cellStart_.end() - 1);
    for (label i = 0; i < size(); ++i)
    {
        for (const label celli : cellsOf[i])
        {
            cellTriangles_[filled[celli]++] = int(i);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallTriangles::wallTriangles
(
    const polyMesh& mesh,
    const labelList& patches,
    const scalar reach
)
{
    addLocal(mesh, patches);
    addRemote(mesh, reach);
    addCandidates(mesh, reach);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::optional<brachDunn::Contact> Foam::wallTriangles::firstContact
(
    const label celli,
    const point& A,
    const point& B,
    const scalar r
) const
{
    const int* begin = cellTriangles_.data() + cellStart_[celli];
    const int* end = cellTriangles_.data() + cellStart_[celli + 1];
    return brachDunn::firstContact
    (
        triangles_, begin, end, toCore(A), toCore(B), r
    );
}


// ************************************************************************* //
