// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "TriangleContact.H"

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

} // End anonymous namespace


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


namespace
{

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


//- The sphere of radius r whose centre moves from A to A + d, and the
//  earliest root in [0, 1] of a triangle's features so far (2: none)
struct Sweep
{
    const Vector3& A;
    const Vector3& d;
    const double r;
    double earliest = 2;

    //- Whether lambda is a root in [0, 1] earlier than the earliest so far
    bool earlier(const double lambda) const
    {
        return lambda >= 0 && lambda <= 1 && lambda < earliest;
    }

    //- Face: the signed height h0 + lambda hd of the centre is +-r, the
    //  centre projecting inside the triangle. True when that root is the
    //  contact: where the centre, from farther than r, first comes within r
    //  of the plane over the triangle, no point of the triangle is nearer
    //  than the plane (the usual approach to a wall, without edges and
    //  vertices)
    bool face(const Face& f)
    {
        const double h0 = dot(f.normal, A - f.vertex[0]);
        const double hd = dot(f.normal, d);
        if (hd == 0)
        {
            return false;
        }
        const double entering = (h0 > 0 ? r - h0 : -r - h0)/hd;
        for (const double side : {r, -r})
        {
            const double lambda = (side - h0)/hd;
            if (earlier(lambda) && projectsInside(f, A + lambda*d))
            {
                earliest = lambda;
            }
        }
        return std::abs(h0) > r && earliest == entering;
    }

    //- Edges: the centre's distance to the edge's line,
    //  |(A - v + lambda d) x e|/|e|, is r with the centre's projection on
    //  the edge
    void edges(const Face& f)
    {
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
                !quadraticRoots
                (
                    magSqr(cd), 2*dot(c0, cd), magSqr(c0) - r*r*eSqr,
                    roots[0], roots[1]
                )
            )
            {
                continue;
            }
            for (const double lambda : roots)
            {
                const double along = dot(w0 + lambda*d, e);
                if (earlier(lambda) && along >= 0 && along <= eSqr)
                {
                    earliest = lambda;
                }
            }
        }
    }

    //- Vertices: |A - v + lambda d| = r; the centre starts farther than r,
    //  so the smaller root is where it enters the vertex's sphere
    void vertices(const Face& f)
    {
        for (const Vector3& v : f.vertex)
        {
            const Vector3 w0 = A - v;
            double enter, leave;
            if
            (
                quadraticRoots
                (
                    magSqr(d), 2*dot(w0, d), magSqr(w0) - r*r, enter, leave
                )
             && earlier(enter)
            )
            {
                earliest = enter;
            }
        }
    }
};

} // End anonymous namespace


Vector3 closestPoint(const Triangle& t, const Vector3& p)
{
    return closestPoint(prepare(t), p);
}


std::optional<double> sweptContact
(
    const PreparedTriangle& f,
    const Vector3& A,
    const Vector3& d,
    const double r
)
{
    Sweep sweep{A, d, r};
    if (f.flat && sweep.face(f))
    {
        return sweep.earliest;
    }
    sweep.edges(f);
    sweep.vertices(f);
    if (sweep.earliest > 1)
    {
        return std::nullopt;
    }
    return sweep.earliest;
}

} // End namespace brachDunn
