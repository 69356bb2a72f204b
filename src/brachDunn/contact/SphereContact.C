// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SphereContact.H"
#include "InputError.H"

#include <algorithm>
#include <cmath>

namespace brachDunn
{

namespace
{

//- A triangle whose largest angle has a sine under this is taken as the
//  union of its edges: its normal would be mostly rounding, and none of its
//  points is farther from its edges than 1e-10 times its longest edge
constexpr double degenerateSine = 1e-10;


inline double magSqr(const Vector3& v)
{
    return dot(v, v);
}


using Face = PreparedTriangle;

} // End anonymous namespace


PreparedTriangle prepare(const Triangle& t)
{
    Face f{{t.a, t.b, t.c}, {t.b - t.a, t.c - t.b, t.a - t.c}, {}, false, {}, {}};
    f.lower = {std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}),
               std::min({t.a.z, t.b.z, t.c.z})};
    f.upper = {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}),
               std::max({t.a.z, t.b.z, t.c.z})};

    const double lenSqr[3] =
        {magSqr(f.edge[0]), magSqr(f.edge[1]), magSqr(f.edge[2])};
    const int longest =
        lenSqr[0] >= lenSqr[1]
      ? (lenSqr[0] >= lenSqr[2] ? 0 : 2)
      : (lenSqr[1] >= lenSqr[2] ? 1 : 2);
    if (lenSqr[longest] == 0)
    {
        return f;
    }

    // The cross product of the two shorter edges (they meet at the largest
    // angle) loses the least to rounding; what it still loses along the
    // longest edge would tilt the plane of a sliver, so that is removed
    const int next = (longest + 1) % 3, previous = (longest + 2) % 3;
    Vector3 n = cross(f.edge[next], f.edge[previous]);
    const Vector3& e = f.edge[longest];
    n = n - (dot(n, e)/lenSqr[longest])*e;

    const double nSqr = magSqr(n);
    const double sineSqr = degenerateSine*degenerateSine;
    if (!(nSqr > sineSqr*lenSqr[next]*lenSqr[previous]))
    {
        return f;
    }
    f.normal = (1/std::sqrt(nSqr))*n;
    f.flat = true;
    return f;
}


namespace
{

//- Whether the projection of p on the plane of the flat face f lies in it
//  (boundary included); the part of p - vertex along the normal adds
//  nothing to normal.(edge x (p - vertex))
bool projectsInside(const Face& f, const Vector3& p)
{
    for (int i = 0; i < 3; ++i)
    {
        if (dot(f.normal, cross(f.edge[i], p - f.vertex[i])) < 0)
        {
            return false;
        }
    }
    return true;
}


//- The closest point of the segment from a to a + e to p
Vector3 closestOnSegment(const Vector3& a, const Vector3& e, const Vector3& p)
{
    const double lenSqr = magSqr(e);
    if (lenSqr == 0)
    {
        return a;
    }
    const double s = dot(p - a, e)/lenSqr;
    if (s <= 0)
    {
        return a;
    }
    if (s >= 1)
    {
        return a + e;
    }
    return a + s*e;
}


//- Closest point of the solid triangle to p. The regions of Ericson's
//  5.1.5 are told apart by the signed areas normal.(edge x (p - vertex))
//  themselves: the book's expansion of them into dot products (Lagrange's
//  identity) cancels on thin triangles (distances off by 1e-6 to 1 on
//  needles and slivers 1e-6 to 1e-12 wide).
Vector3 closestPoint(const Face& f, const Vector3& p)
{
    bool outside[3] = {true, true, true};
    if (f.flat)
    {
        bool inside = true;
        for (int i = 0; i < 3; ++i)
        {
            outside[i] =
                dot(f.normal, cross(f.edge[i], p - f.vertex[i])) < 0;
            inside = inside && !outside[i];
        }
        if (inside)
        {
            return p - dot(f.normal, p - f.vertex[0])*f.normal;
        }
    }

    // Outside the face region (or no face): the closest point is on an
    // edge whose line p lies beyond (of a degenerate triangle: any edge)
    Vector3 nearest;
    double nearestSqr = -1;
    for (int i = 0; i < 3; ++i)
    {
        if (outside[i])
        {
            const Vector3 q = closestOnSegment(f.vertex[i], f.edge[i], p);
            const double distSqr = magSqr(p - q);
            if (nearestSqr < 0 || distSqr < nearestSqr)
            {
                nearest = q;
                nearestSqr = distSqr;
            }
        }
    }
    return nearest;
}


//- The real roots of a t^2 + b t + c = 0 (a > 0) in increasing order, in
//  the form that does not cancel; false when there are none
bool quadraticRoots(double a, double b, double c, double& t0, double& t1)
{
    const double discriminant = b*b - 4*a*c;
    if (!(a > 0) || discriminant < 0)
    {
        return false;
    }
    const double q = -0.5*(b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0)
    {
        // b = 0 and a c = 0: the double root 0
        t0 = t1 = 0;
        return true;
    }
    t0 = q/a;
    t1 = c/q;
    if (t0 > t1)
    {
        std::swap(t0, t1);
    }
    return true;
}


//- The box around the sphere of radius r swept from A to B
struct Box
{
    Vector3 lower, upper;
};

Box sweptBox(const Vector3& A, const Vector3& B, double r)
{
    return
    {
        {std::min(A.x, B.x) - r, std::min(A.y, B.y) - r, std::min(A.z, B.z) - r},
        {std::max(A.x, B.x) + r, std::max(A.y, B.y) + r, std::max(A.z, B.z) + r}
    };
}


//- Whether the boxes around the triangle and around the swept sphere are
//  apart: no contact then (a cheap test for the many triangles far away)
inline bool boxesApart(const Face& f, const Box& swept)
{
    return
        f.upper.x < swept.lower.x || f.lower.x > swept.upper.x
     || f.upper.y < swept.lower.y || f.lower.y > swept.upper.y
     || f.upper.z < swept.lower.z || f.lower.z > swept.upper.z;
}


//- The first contact of the sphere (centre A + lambda d) with the face f,
//  when it does not touch at lambda = 0 (d != 0): the smallest of the
//  valid roots of the face, edges and vertices
std::optional<double> sweep
(
    const Face& f,
    const Vector3& A,
    const Vector3& d,
    double r
)
{
    double earliest = 2;
    const auto consider = [&earliest](double lambda)
    {
        return lambda >= 0 && lambda <= 1 && lambda < earliest;
    };

    // Face: the signed height h0 + lambda hd of the centre is +-r. Where
    // the centre, from farther than r, first comes within r of the plane
    // over the triangle, that is the contact: no point of the triangle is
    // nearer than the plane (the usual approach to a wall, without edges
    // and vertices).
    if (f.flat)
    {
        const double h0 = dot(f.normal, A - f.vertex[0]);
        const double hd = dot(f.normal, d);
        if (hd != 0)
        {
            const double entering = (h0 > 0 ? r - h0 : -r - h0)/hd;
            for (const double side : {r, -r})
            {
                const double lambda = (side - h0)/hd;
                if (consider(lambda) && projectsInside(f, A + lambda*d))
                {
                    earliest = lambda;
                }
            }
            if (std::abs(h0) > r && earliest == entering)
            {
                return earliest;
            }
        }
    }

    // Edges: the centre's distance to the edge's line,
    // |(A - v + lambda d) x e|/|e|, is r with the centre's projection on
    // the edge
    for (int i = 0; i < 3; ++i)
    {
        const Vector3& e = f.edge[i];
        const double eSqr = magSqr(e);
        if (eSqr == 0)
        {
            continue;
        }
        const Vector3 w0 = A - f.vertex[i];
        const Vector3 c0 = cross(w0, e), cd = cross(d, e);
        double roots[2];
        if
        (
            quadraticRoots
            (
                magSqr(cd),
                2*dot(c0, cd),
                magSqr(c0) - r*r*eSqr,
                roots[0],
                roots[1]
            )
        )
        {
            for (const double lambda : roots)
            {
                const double along = dot(w0 + lambda*d, e);
                if (consider(lambda) && along >= 0 && along <= eSqr)
                {
                    earliest = lambda;
                }
            }
        }
    }

    // Vertices: |A - v + lambda d| = r; the centre starts farther than r,
    // so the smaller root is where it enters the vertex's sphere
    for (const Vector3& v : f.vertex)
    {
        const Vector3 w0 = A - v;
        double enter, leave;
        if
        (
            quadraticRoots
            (
                magSqr(d),
                2*dot(w0, d),
                magSqr(w0) - r*r,
                enter,
                leave
            )
         && consider(enter)
        )
        {
            earliest = enter;
        }
    }

    if (earliest > 1)
    {
        return std::nullopt;
    }
    return earliest;
}


void requireFiniteVector(const char* keyword, const Vector3& v)
{
    requireFinite(keyword, v.x);
    requireFinite(keyword, v.y);
    requireFinite(keyword, v.z);
}


void checkSegment(const Vector3& A, const Vector3& B, double r)
{
    requireFiniteVector("A", A);
    requireFiniteVector("B", B);
    requireNonNegative("r", r);
}

} // End anonymous namespace


Vector3 closestPoint(const Triangle& t, const Vector3& p)
{
    return closestPoint(prepare(t), p);
}


std::optional<double> firstContact
(
    const Triangle& t,
    const Vector3& A,
    const Vector3& B,
    double r
)
{
    checkSegment(A, B, r);
    const Face f = prepare(t);
    if (boxesApart(f, sweptBox(A, B, r)))
    {
        return std::nullopt;
    }
    if (magSqr(A - closestPoint(f, A)) <= r*r)
    {
        return 0.0;
    }
    const Vector3 d = B - A;
    if (magSqr(d) == 0)
    {
        return std::nullopt;
    }
    return sweep(f, A, d, r);
}


std::optional<Contact> firstContact
(
    const std::vector<PreparedTriangle>& triangles,
    const int* candidatesBegin,
    const int* candidatesEnd,
    const Vector3& A,
    const Vector3& B,
    double r,
    const int* leavingBegin,
    const int* leavingEnd
)
{
    checkSegment(A, B, r);
    const Vector3 d = B - A;
    const bool moving = magSqr(d) > 0;
    const double tol = contactTolerance(A, r);

    // The triangles the sphere overlaps at A without approaching them (a
    // wall it slides along or leaves), and those it reaches through them:
    // a contact at a point of one of these is no first contact with the
    // wall (the next triangle of the same plane, touched at the edge they
    // share). Rarely more than a few, all of them held (the list is kept
    // between calls: no allocation once it has grown).
    static thread_local std::vector<int> overlapped;
    overlapped.clear();
    const auto overlap = [&](int index)
    {
        overlapped.push_back(index);
    };
    const auto onOverlapped = [&](const Vector3& point)
    {
        const double tolSqr = 1e-12*r*r;
        for (const int index : overlapped)
        {
            const Face& f = triangles[index];
            if (magSqr(point - closestPoint(f, point)) <= tolSqr)
            {
                return true;
            }
        }
        return false;
    };

    // At A: in contact when overlapping and approaching (of several, the
    // nearest). Along the segment: the first contacts of the triangles out
    // of reach at A.
    std::optional<Contact> atStart;
    double atStartDistSqr = 0;
    struct Hit
    {
        double fraction;
        double distSqr;
        Contact contact;
    };
    static thread_local std::vector<Hit> hits;
    hits.clear();
    const Box swept = sweptBox(A, B, r);

    // The caller's verdict on the walls the sphere leaves or slides along
    // (their plane's, not each triangle's: a plane of faces that are flat
    // only to the caller's grouping)
    for (const int* index = leavingBegin; index != leavingEnd; ++index)
    {
        if (!boxesApart(triangles[*index], swept))
        {
            overlap(*index);
        }
    }
    for (const int* index = candidatesBegin; index != candidatesEnd; ++index)
    {
        const Face& f = triangles[*index];
        // Both ends farther than r from the plane, on one side: the whole
        // swept sphere is (most triangles near a parcel, cheaply), unless
        // it slides along the plane or leaves it (to the tolerance, which
        // marks the triangle as overlapped); A farther than r and the
        // tolerance from the plane: no contact at A
        bool nearAtA = true;
        bool sliding = false;
        if (f.flat)
        {
            const double hA = dot(f.normal, A - f.vertex[0]);
            const double hB = dot(f.normal, B - f.vertex[0]);
            const bool beyond = (hA > r && hB > r) || (hA < -r && hB < -r);
            // (sliding needs |hA| within tol of r: most candidates are
            // rejected before it is asked)
            if (beyond && std::abs(hA) > r + tol)
            {
                continue;
            }
            sliding = slidesOrLeaves(hA, hB, r, tol);
            if (beyond && !sliding)
            {
                continue;
            }
            nearAtA = std::abs(hA) <= r + tol;
        }
        if (boxesApart(f, swept))
        {
            continue;
        }
        if (sliding)
        {
            overlap(*index);
            continue;
        }
        if (nearAtA)
        {
            const Vector3 point = closestPoint(f, A);
            const double distSqr = magSqr(A - point);
            if (distSqr <= (r + tol)*(r + tol))
            {
                // Touching (to the tolerance): moving away or along, or
                // approaching but ending no deeper than r - tol towards the
                // closest point (rounding, or a slide within the contact
                // band), is no contact; deeper, any approach is one
                // (the root only for an approach: rebounds leave)
                const double towards = dot(d, A - point);
                if
                (
                    towards >= 0
                 || (
                        r > tol
                     && distSqr + towards >= (r - tol)*std::sqrt(distSqr)
                    )
                )
                {
                    overlap(*index);
                }
                else if (!atStart || distSqr < atStartDistSqr)
                {
                    atStart = Contact{0, point, *index};
                    atStartDistSqr = distSqr;
                }
                continue;
            }
        }
        if (moving && !atStart)
        {
            const std::optional<double> lambda = sweep(f, A, d, r);
            if (lambda)
            {
                const Vector3 centre = A + *lambda*d;
                const Vector3 touched = closestPoint(f, centre);
                hits.push_back
                ({
                    *lambda, magSqr(centre - touched),
                    Contact{*lambda, touched, *index}
                });
            }
        }
    }
    if (atStart || hits.empty())
    {
        return atStart;
    }
    std::sort
    (
        hits.begin(), hits.end(),
        [](const Hit& a, const Hit& b)
        {
            return
                a.fraction < b.fraction
             || (a.fraction == b.fraction && a.distSqr < b.distSqr);
        }
    );

    // The first at a point of no wall the sphere overlaps
    for (const Hit& hit : hits)
    {
        if (onOverlapped(hit.contact.point))
        {
            overlap(hit.contact.triangle);
            continue;
        }
        return hit.contact;
    }
    return std::nullopt;
}


std::optional<Contact> firstContact
(
    const std::vector<Triangle>& triangles,
    const Vector3& A,
    const Vector3& B,
    double r
)
{
    std::vector<PreparedTriangle> prepared(triangles.size());
    std::vector<int> all(triangles.size());
    for (std::size_t i = 0; i < all.size(); ++i)
    {
        prepared[i] = prepare(triangles[i]);
        all[i] = int(i);
    }
    return firstContact
    (
        prepared, all.data(), all.data() + all.size(), A, B, r
    );
}

} // End namespace brachDunn
