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
    std::vector<int> sorted;
    for (label celli = 0; celli < nCells; ++celli)
    {
        const int begin = cellStart_[celli], end = cellStart_[celli + 1];
        const std::size_t cellPlanes = planes_.size();
        std::vector<int> planeOf(end - begin, -1);
        for (int i = begin; i < end; ++i)
        {
            const brachDunn::PreparedTriangle& t =
                triangles_[cellTriangles_[i]];
            const double offset = dot(t.normal, t.vertex[0]);
            for (std::size_t k = cellPlanes; t.flat && k < planes_.size(); ++k)
            {
                // Of the plane: facing its way, every vertex within 1e-9 of
                // the reach of it (the plane tests are exact to that)
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
                    planeOf[i - begin] = int(k);
                    break;
                }
            }
            if (planeOf[i - begin] < 0)
            {
                planeOf[i - begin] = int(planes_.size());
                planes_.push_back
                (
                    {t.normal, offset, t.flat, 0, 0, t.lower, t.upper}
                );
            }
            // The plane's box holds its triangles' boxes
            plane& p = planes_[planeOf[i - begin]];
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
        }

        // The cell's triangles in the order of their planes, in a plane
        // the nearest to the cell's centre first (the cell's own faces: a
        // contact's foot is most often in one of them, containing())
        sorted.clear();
        const brachDunn::Vector3 centre(toCore(cellCentres[celli]));
        const auto distSqr = [&](const int t)
        {
            const brachDunn::PreparedTriangle& tri = triangles_[t];
            const brachDunn::Vector3 c =
                (1.0/3.0)*(tri.vertex[0] + tri.vertex[1] + tri.vertex[2])
              - centre;
            return dot(c, c);
        };
        for (std::size_t k = cellPlanes; k < planes_.size(); ++k)
        {
            planes_[k].first = begin + int(sorted.size());
            for (int i = begin; i < end; ++i)
            {
                if (planeOf[i - begin] == int(k))
                {
                    sorted.push_back(cellTriangles_[i]);
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
        cellPlaneStart_[celli + 1] = int(planes_.size());
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::optional<brachDunn::Contact> Foam::wallTriangles::firstContact
(
    const label celli,
    const point& A,
    const point& B,
    const scalar r
) const
{
    // The candidates of the planes whose triangles are swept (the buffer
    // taken only when one is: most sub-steps need none)
    std::vector<int>* reached = nullptr;
    std::optional<brachDunn::Contact> onPlane;
    const brachDunn::Vector3 a(toCore(A)), b(toCore(B));
    const double tol = brachDunn::contactTolerance(a, r);
    for (int k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
    {
        const plane& p = planes_[k];
        if (p.flat)
        {
            const double hA = dot(p.normal, a) - p.offset;
            const double hB = dot(p.normal, b) - p.offset;
            if ((hA > r && hB > r) || (hA < -r && hB < -r))
            {
                continue;
            }
            // Leaving a plane it starts in contact with (a rebound from it)
            // or sliding along it, to the core's tolerance: no contact with
            // its triangles; handed to the core only with other planes,
            // which needs them as walls the sphere overlaps (the edges they
            // share with those)
            if (brachDunn::slidesOrLeaves(hA, hB, r, tol))
            {
                continue;
            }
            // From beyond reach of the plane (and the tolerance: within it,
            // the core takes the sphere as touching at A), the sphere meets
            // it first where its centre is r from it: when the foot of the
            // centre there lies in one of the plane's triangles, that is
            // the first contact with any of them (none is nearer than their
            // plane), found without sweeping each (most contacts with a
            // flat wall)
            if (std::abs(hA) > r + tol)
            {
                const double side = hA > 0 ? 1 : -1;
                const double fraction = (side*hA - r)/(side*(hA - hB));
                const brachDunn::Vector3 centre = a + fraction*(b - a);
                const brachDunn::Vector3 foot =
                    centre - (dot(p.normal, centre) - p.offset)*p.normal;
                if (const int t = containing(p, foot); t >= 0)
                {
                    if (!onPlane || fraction < onPlane->fraction)
                    {
                        onPlane = brachDunn::Contact{fraction, foot, t};
                    }
                    continue;
                }
            }
        }
        if (!reached)
        {
            static thread_local std::vector<int> buffer;
            reached = &buffer;
            reached->clear();
        }
        reached->insert
        (
            reached->end(),
            cellTriangles_.begin() + p.first,
            cellTriangles_.begin() + p.last
        );
    }
    if (!reached)
    {
        return onPlane;
    }

    // The planes the sphere leaves or slides along, after the swept
    // candidates: the core takes them as overlapped on this verdict of
    // their plane (its own test of each triangle could differ for faces
    // flat only to the grouping's 1e-9 of the reach, more than the
    // tolerance of a smaller parcel, and find a contact at the start)
    const std::size_t nSwept = reached->size();
    for (int k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
    {
        const plane& p = planes_[k];
        if
        (
            p.flat
         && brachDunn::slidesOrLeaves
            (
                dot(p.normal, a) - p.offset, dot(p.normal, b) - p.offset,
                r, tol
            )
        )
        {
            reached->insert
            (
                reached->end(),
                cellTriangles_.begin() + p.first,
                cellTriangles_.begin() + p.last
            );
        }
    }
    const std::optional<brachDunn::Contact> swept = brachDunn::firstContact
    (
        triangles_, reached->data(), reached->data() + nSwept, a, b, r,
        reached->data() + nSwept, reached->data() + reached->size()
    );
    return
        onPlane && (!swept || onPlane->fraction <= swept->fraction)
      ? onPlane : swept;
}


int Foam::wallTriangles::containing
(
    const plane& p,
    const brachDunn::Vector3& x
) const
{
    for (int i = p.first; i < p.last; ++i)
    {
        const brachDunn::PreparedTriangle& t = triangles_[cellTriangles_[i]];
        // Outside its box (grown by a little for the point's rounding off
        // the plane): not in it; a triangle wrongly passed over here is
        // swept instead, with the same result
        const double tol =
            1e-9
           *(
                t.upper.x - t.lower.x + t.upper.y - t.lower.y
              + t.upper.z - t.lower.z
            );
        if
        (
            x.x < t.lower.x - tol || x.x > t.upper.x + tol
         || x.y < t.lower.y - tol || x.y > t.upper.y + tol
         || x.z < t.lower.z - tol || x.z > t.upper.z + tol
        )
        {
            continue;
        }
        // Inside or on the edges: on the inner side of each edge (the
        // normal is that of the vertices' order, prepare())
        bool inside = true;
        for (int e = 0; inside && e < 3; ++e)
        {
            inside = dot(cross(t.edge[e], x - t.vertex[e]), t.normal) >= 0;
        }
        if (inside)
        {
            return cellTriangles_[i];
        }
    }
    return -1;
}


std::optional<std::pair<int, Foam::scalar>> Foam::wallTriangles::nearest
(
    const label celli,
    const point& p
) const
{
    std::optional<std::pair<int, scalar>> nearest;
    const brachDunn::Vector3 a(toCore(p));
    for (int k = cellStart_[celli]; k < cellStart_[celli + 1]; ++k)
    {
        const int t = cellTriangles_[k];
        const brachDunn::PreparedTriangle& prepared = triangles_[t];
        const brachDunn::Vector3 c = brachDunn::closestPoint
        (
            {prepared.vertex[0], prepared.vertex[1], prepared.vertex[2]}, a
        );
        const scalar distance = std::sqrt(dot(c - a, c - a));
        if (!nearest || distance < nearest->second)
        {
            nearest = std::make_pair(t, distance);
        }
    }
    return nearest;
}


Foam::vector Foam::wallTriangles::areaVector(const int triangle) const
{
    const brachDunn::PreparedTriangle& t = triangles_[triangle];
    const brachDunn::Vector3 n =
        cross(t.vertex[1] - t.vertex[0], t.vertex[2] - t.vertex[0]);
    return 0.5*vector(n.x, n.y, n.z);
}


std::vector<bool> Foam::wallTriangles::candidates() const
{
    std::vector<bool> used(triangles_.size(), false);
    for (const int t : cellTriangles_)
    {
        used[t] = true;
    }
    return used;
}


// ************************************************************************* //
