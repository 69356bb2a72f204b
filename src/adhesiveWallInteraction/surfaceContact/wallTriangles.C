// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The queries of the wall triangles

#include "wallTriangles.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline bool Foam::wallTriangles::settledByPlane
(
    const plane& p,
    const brachDunn::Vector3& a,
    const brachDunn::Vector3& b,
    const double r,
    const double tol,
    std::optional<brachDunn::Contact>& onPlane
) const
{
    const double hA = dot(p.normal, a) - p.offset;
    const double hB = dot(p.normal, b) - p.offset;
    if ((hA > r && hB > r) || (hA < -r && hB < -r))
    {
        return true;
    }
    // Leaving a plane it starts in contact with (a rebound from it) or
    // sliding along it, to the core's tolerance: no contact with its
    // triangles; handed to the core only with other planes, which needs
    // them as walls the sphere overlaps (the edges they share with those)
    if (brachDunn::slidesOrLeaves(hA, hB, r, tol))
    {
        return true;
    }
    // From beyond reach of the plane (and the tolerance: within it, the
    // core takes the sphere as touching at A), the sphere meets it first
    // where its centre is r from it: when the foot of the centre there lies
    // in one of the plane's triangles, that is the first contact with any
    // of them (none is nearer than their plane), found without sweeping
    // each (most contacts with a flat wall)
    if (std::abs(hA) <= r + tol)
    {
        return false;
    }
    const double side = hA > 0 ? 1 : -1;
    const double fraction = (side*hA - r)/(side*(hA - hB));
    const brachDunn::Vector3 centre = a + fraction*(b - a);
    const brachDunn::Vector3 foot =
        centre - (dot(p.normal, centre) - p.offset)*p.normal;
    const int t = containing(p, foot);
    if (t < 0)
    {
        return false;
    }
    if (!onPlane || fraction < onPlane->fraction)
    {
        onPlane = brachDunn::Contact{fraction, foot, t};
    }
    return true;
}


void Foam::wallTriangles::addLeaving
(
    const label celli,
    const brachDunn::Vector3& a,
    const brachDunn::Vector3& b,
    const double r,
    const double tol,
    std::vector<int>& reached
) const
{
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
            reached.insert
            (
                reached.end(),
                cellTriangles_.begin() + p.first,
                cellTriangles_.begin() + p.last
            );
        }
    }
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
    // The candidates of the planes whose triangles are swept (the buffer
    // taken only when one is: most sub-steps need none)
    std::vector<int>* reached = nullptr;
    std::optional<brachDunn::Contact> onPlane;
    const brachDunn::Vector3 a(toCore(A)), b(toCore(B));
    const double tol = brachDunn::contactTolerance(a, r);
    for (int k = cellPlaneStart_[celli]; k < cellPlaneStart_[celli + 1]; ++k)
    {
        const plane& p = planes_[k];
        if (p.flat && settledByPlane(p, a, b, r, tol, onPlane))
        {
            continue;
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
    addLeaving(celli, a, b, r, tol, *reached);
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
        const brachDunn::Vector3 c = brachDunn::closestPoint(prepared, a);
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
