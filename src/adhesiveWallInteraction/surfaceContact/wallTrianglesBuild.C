// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The construction of the wall triangles: the faces' triangles, the other
// processors' within reach, the candidates of every cell and their planes

#include "wallTriangles.H"
#include "PstreamBuffers.H"
#include "treeDataCell.H"
#include "indexedOctree.H"
#include "releaseCompat.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

Foam::point toFoam(const brachDunn::Vector3& p)
{
    return Foam::point(p.x, p.y, p.z);
}


//- The triangle's bounding box grown by reach
Foam::treeBoundBox grownBox
(
    const brachDunn::PreparedTriangle& t,
    const Foam::scalar reach
)
{
    const Foam::vector grow(reach, reach, reach);
    return Foam::treeBoundBox(toFoam(t.lower) - grow, toFoam(t.upper) + grow);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::wallTriangles::add
(
    const brachDunn::Triangle& t,
    const origin& from
)
{
    triangles_.push_back(brachDunn::prepare(t));
    origins_.push_back(from);
}


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
                add
                (
                    {
                        toCore(points[f[base]]),
                        toCore(points[f[(base + k) % f.size()]]),
                        toCore(points[f[(base + k + 1) % f.size()]])
                    },
                    {Pstream::myProcNo(), patchi, facei}
                );
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
            const brachDunn::PreparedTriangle& t = triangles_[i];
            if (boxes[proci].overlaps(grownBox(t, 0)))
            {
                points.append(toFoam(t.vertex[0]));
                points.append(toFoam(t.vertex[1]));
                points.append(toFoam(t.vertex[2]));
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
            add
            (
                {
                    toCore(points[3*i]),
                    toCore(points[3*i + 1]),
                    toCore(points[3*i + 2])
                },
                {proci, faces[2*i], faces[2*i + 1]}
            );
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


int Foam::wallTriangles::planeOf
(
    const int triangle,
    const std::size_t cellPlanes,
    const scalar reach
)
{
    const brachDunn::PreparedTriangle& t = triangles_[triangle];
    int found = -1;
    for (std::size_t k = cellPlanes; t.flat && k < planes_.size(); ++k)
    {
        // Of the plane: facing its way, every vertex within 1e-9 of the
        // reach of it (the plane tests are exact to that)
        const plane& p = planes_[k];
        const auto inPlane = [&](const brachDunn::Vector3& v)
        {
            return std::abs(dot(p.normal, v) - p.offset) <= 1e-9*reach;
        };
        if
        (
            p.flat
         && dot(p.normal, t.normal) > 0
         && inPlane(t.vertex[0])
         && inPlane(t.vertex[1])
         && inPlane(t.vertex[2])
        )
        {
            found = int(k);
            break;
        }
    }
    if (found < 0)
    {
        found = int(planes_.size());
        const double offset = dot(t.normal, t.vertex[0]);
        planes_.push_back({t.normal, offset, t.flat, 0, 0, t.lower, t.upper});
    }
    // The plane's box holds its triangles' boxes
    plane& p = planes_[found];
    p.lower =
    {
        std::min(p.lower.x, t.lower.x),
        std::min(p.lower.y, t.lower.y),
        std::min(p.lower.z, t.lower.z)
    };
    p.upper =
    {
        std::max(p.upper.x, t.upper.x),
        std::max(p.upper.y, t.upper.y),
        std::max(p.upper.z, t.upper.z)
    };
    return found;
}


void Foam::wallTriangles::sortByPlane
(
    const int begin,
    const std::size_t cellPlanes,
    const std::vector<int>& planeOf,
    const brachDunn::Vector3& centre
)
{
    const auto distSqr = [&](const int t)
    {
        const brachDunn::PreparedTriangle& tri = triangles_[t];
        const brachDunn::Vector3 c =
            (1.0/3.0)*(tri.vertex[0] + tri.vertex[1] + tri.vertex[2]) - centre;
        return dot(c, c);
    };
    std::vector<int> sorted;
    for (std::size_t k = cellPlanes; k < planes_.size(); ++k)
    {
        planes_[k].first = begin + int(sorted.size());
        for (std::size_t i = 0; i < planeOf.size(); ++i)
        {
            if (planeOf[i] == int(k))
            {
                sorted.push_back(cellTriangles_[begin + i]);
            }
        }
        planes_[k].last = begin + int(sorted.size());
        std::stable_sort
        (
            sorted.begin() + (planes_[k].first - begin),
            sorted.end(),
            [&](const int s, const int t)
            {
                return distSqr(s) < distSqr(t);
            }
        );
    }
    std::copy(sorted.begin(), sorted.end(), cellTriangles_.begin() + begin);
}


void Foam::wallTriangles::groupByPlane
(
    const polyMesh& mesh,
    const scalar reach
)
{
    const vectorField& cellCentres = mesh.cellCentres();
    const label nCells = label(cellStart_.size()) - 1;
    cellPlaneStart_.assign(nCells + 1, 0);
    planes_.clear();
    std::vector<int> planes;
    for (label celli = 0; celli < nCells; ++celli)
    {
        const int begin = cellStart_[celli], end = cellStart_[celli + 1];
        const std::size_t cellPlanes = planes_.size();
        planes.assign(end - begin, -1);
        for (int i = begin; i < end; ++i)
        {
            planes[i - begin] = planeOf(cellTriangles_[i], cellPlanes, reach);
        }

        // The cell's triangles in the order of their planes, in a plane
        // the nearest to the cell's centre first (the cell's own faces: a
        // contact's foot is most often in one of them, containing())
        sortByPlane(begin, cellPlanes, planes, toCore(cellCentres[celli]));
        cellPlaneStart_[celli + 1] = int(planes_.size());
    }
}


// ************************************************************************* //
