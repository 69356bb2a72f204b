// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// Contact at the particle's surface (SphereContact): closest points of a
// triangle and the first contact of a moving sphere, against values worked
// out by hand from the geometry (planes, cylinders around edges, spheres
// around vertices) and against dense sampling of an independent distance.
// Every hand-made case is also checked in a rotated, shifted frame.

#include "SphereContact.H"
#include "testCases.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <type_traits>

using namespace brachDunn;

namespace
{

//- Lambda from the closed forms, to rounding
constexpr double lambdaTol = 1e-13;

//- Positions of size 1-100, to rounding
constexpr double pointTol = 1e-12;


//- A rigid motion: rotation about (1, 2, 2)/3 by 0.7 rad, then a shift
struct Frame
{
    bool identity;

    Vector3 operator()(const Vector3& v) const
    {
        if (identity)
        {
            return v;
        }
        const Vector3 k{1.0/3, 2.0/3, 2.0/3};
        const double c = std::cos(0.7), s = std::sin(0.7);
        const Vector3 rotated =
            c*v + s*cross(k, v) + ((1 - c)*dot(k, v))*k;
        return rotated + Vector3{0.3, -1.7, 2.9};
    }

    //- A template only so that braces {x, y, z} always mean a point
    template<class T, class = std::enable_if_t<std::is_same_v<T, Triangle>>>
    Triangle operator()(const T& t) const
    {
        return {(*this)(t.a), (*this)(t.b), (*this)(t.c)};
    }
};

const Frame frames[] = {{true}, {false}};


//- Whether the points agree to tol in each coordinate
::testing::AssertionResult pointsNear
(
    const Vector3& actual,
    const Vector3& expected,
    double tol
)
{
    if
    (
        std::abs(actual.x - expected.x) <= tol
     && std::abs(actual.y - expected.y) <= tol
     && std::abs(actual.z - expected.z) <= tol
    )
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
        << "(" << actual.x << ", " << actual.y << ", " << actual.z
        << ") is not within " << tol << " of ("
        << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

#define EXPECT_POINT_NEAR(actual, expected, tol)                              \
    EXPECT_TRUE(pointsNear(actual, expected, tol))


// Reference distance, written independently of the code under test: the
// height over the plane when the 2x2 normal equations of the barycentric
// coordinates put the projection inside, else the nearest of the segments

double segmentDistance(const Vector3& a, const Vector3& b, const Vector3& p)
{
    const Vector3 ab = b - a;
    const double lenSqr = dot(ab, ab);
    const double s =
        lenSqr > 0 ? std::clamp(dot(p - a, ab)/lenSqr, 0.0, 1.0) : 0.0;
    return mag(p - (a + s*ab));
}


double referenceDistance(const Triangle& t, const Vector3& p)
{
    const Vector3 u = t.b - t.a, v = t.c - t.a, w = p - t.a;
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v);
    const double det = uu*vv - uv*uv;
    if (det > 1e-12*uu*vv)
    {
        const double s = (vv*dot(w, u) - uv*dot(w, v))/det;
        const double q = (uu*dot(w, v) - uv*dot(w, u))/det;
        if (s >= 0 && q >= 0 && s + q <= 1)
        {
            const Vector3 n = cross(u, v);
            return std::abs(dot(w, n))/mag(n);
        }
    }
    return std::min
    ({
        segmentDistance(t.a, t.b, p),
        segmentDistance(t.b, t.c, p),
        segmentDistance(t.c, t.a, p)
    });
}


//- The smaller root of a t^2 + b t + c = 0 (the textbook formula)
double smallerRoot(double a, double b, double c)
{
    return (-b - std::sqrt(b*b - 4*a*c))/(2*a);
}


//- A big triangle in the plane z = 0 around the origin
const Triangle floorTriangle{{-100, -100, 0}, {100, -100, 0}, {0, 100, 0}};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Closest points  * * * * * * * * * * * * * //

TEST(SphereContactClosestPoint, EachVoronoiRegion)
{
    // a = (0, 0, 0), b = (4, 0, 0), c = (0, 4, 0): edge bc on x + y = 4
    const Triangle t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    const struct { Vector3 p, expected; } cases[] =
    {
        {{-1, -2, 3}, {0, 0, 0}},   // vertex a
        {{5, -1, 3}, {4, 0, 0}},    // vertex b
        {{-1, 6, -2}, {0, 4, 0}},   // vertex c
        {{6, 1, 2}, {4, 0, 0}},     // vertex b, beyond both its edges
        {{2, -3, 1}, {2, 0, 0}},    // edge ab
        {{-2, 1, 5}, {0, 1, 0}},    // edge ca
        {{3, 3, -1}, {2, 2, 0}},    // edge bc: (3, 3) projects to (2, 2)
        {{4, 1, 0}, {3.5, 0.5, 0}}, // edge bc, in the plane
        {{1, 1, 7}, {1, 1, 0}},     // face, above
        {{1, 2, -3}, {1, 2, 0}},    // face, below
        {{1, 1, 0}, {1, 1, 0}},     // on the face
        {{2, 2, 5}, {2, 2, 0}},     // over edge bc
        {{0, 0, -5}, {0, 0, 0}}     // under vertex a
    };
    for (const Frame& frame : frames)
    {
        for (const auto& c : cases)
        {
            EXPECT_POINT_NEAR
            (
                closestPoint(frame(t), frame(c.p)),
                frame(c.expected),
                pointTol
            ) << "p = (" << c.p.x << ", " << c.p.y << ", " << c.p.z << ")";
        }
    }
}


TEST(SphereContactClosestPoint, DegenerateTriangles)
{
    const testCases::TrapFloatingPointErrors trap;

    // Collinear, c between a and b, and c outside
    for (const Triangle& t :
         {Triangle{{0, 0, 0}, {3, 0, 0}, {1, 0, 0}},
          Triangle{{0, 0, 0}, {1, 0, 0}, {3, 0, 0}}})
    {
        EXPECT_POINT_NEAR(closestPoint(t, {2, 1, 5}), Vector3({2, 0, 0}), 0);
        EXPECT_POINT_NEAR(closestPoint(t, {-1, 1, 0}), Vector3(), 0);
        EXPECT_POINT_NEAR
        (
            closestPoint(t, {4, -1, 2}), Vector3({3, 0, 0}), 0
        );
    }

    // Two vertices the same: the segment; all three: the point
    const Triangle segment{{1, 1, 1}, {1, 1, 1}, {1, 3, 1}};
    EXPECT_POINT_NEAR
    (
        closestPoint(segment, {0, 2, 0}), Vector3({1, 2, 1}), pointTol
    );
    const Triangle point{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    EXPECT_POINT_NEAR(closestPoint(point, {5, 5, 5}), Vector3({1, 2, 3}), 0);

    // A sliver (largest angle near 180 degrees): within 1e-13 of c
    const Triangle sliver{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-13, 0}};
    EXPECT_POINT_NEAR
    (
        closestPoint(sliver, {0.5, 0.5, 2}), sliver.c, 1e-15
    );

    // A needle 1e-9 wide at its base: above it, and beside it (on edge bc)
    const Triangle needle{{0, 0, 0}, {0, 1e-9, 0}, {1, 0, 0}};
    EXPECT_POINT_NEAR
    (
        closestPoint(needle, {0.5, 2e-10, 0.7}),
        Vector3({0.5, 2e-10, 0}),
        1e-15
    );
    const Vector3 beside{0.5, 0.3, 0.2};
    const Vector3 bc = needle.c - needle.b;
    const Vector3 onBc =
        needle.b + (dot(beside - needle.b, bc)/dot(bc, bc))*bc;
    EXPECT_POINT_NEAR(closestPoint(needle, beside), onBc, 1e-16);
}


TEST(SphereContactClosestPoint, RandomAgainstReference)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    const auto random = [&] {
        return Vector3{coordinate(rng), coordinate(rng), coordinate(rng)};
    };
    for (int i = 0; i < 100000; ++i)
    {
        Triangle t{random(), random(), random()};
        if (i % 10 == 0)
        {
            t.c = t.a + 0.37*(t.b - t.a);   // collinear
        }
        const Vector3 p = 2*random();
        const Vector3 q = closestPoint(t, p);
        ASSERT_NEAR(mag(p - q), referenceDistance(t, p), 1e-13) << i;
        ASSERT_NEAR(referenceDistance(t, q), 0, 1e-13) << i;
    }
}


TEST(SphereContactClosestPoint, ThinTrianglesOverTheFace)
{
    // Needles (an edge 'width' long) and slivers (a vertex 'width' from the
    // opposite edge) in the plane z = 0, a point at height h over a point
    // inside: the distance is |h|, and a sphere falling from h to -h meets
    // the face at lambda = (|h| - r)/(2 |h|). Rotated, the vertices move by
    // rounding (1e-16), the distance by no more. (Ericson's dot-product
    // form of the regions is off by 1e-6 to 1 here: it cancels on thin
    // triangles.)
    const testCases::TrapFloatingPointErrors trap;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1), symmetric(-1, 1);
    const double r = 0.05;
    for (const Frame& frame : frames)
    {
        for (const double width : {1e-3, 1e-6, 1e-9, 1e-12, 1e-14})
        {
            for (int i = 0; i < 10000; ++i)
            {
                const Vector3 a{symmetric(rng), symmetric(rng), 0};
                const Vector3 c{symmetric(rng), symmetric(rng), 0};
                const double dx = symmetric(rng), dy = symmetric(rng);
                const Vector3 offset{width*dx, width*dy, 0};
                const Vector3 b =
                    i % 2 == 0 ? a + offset : a + unit(rng)*(c - a) + offset;
                const Triangle t = frame(Triangle{a, b, c});

                double s = unit(rng), q = unit(rng);
                if (s + q > 1)
                {
                    s = 1 - s;
                    q = 1 - q;
                }
                const Vector3 inside = a + s*(b - a) + q*(c - a);
                const double h = (0.1 + 0.9*unit(rng))*(i % 4 < 2 ? 1 : -1);
                const Vector3 p = frame(inside + Vector3{0, 0, h});
                const Vector3 below = frame(inside - Vector3{0, 0, h});

                ASSERT_NEAR(mag(p - closestPoint(t, p)), std::abs(h), 1e-14)
                    << "width " << width << ", " << i;

                const auto lambda = firstContact(t, p, below, r);
                ASSERT_TRUE(lambda) << "width " << width << ", " << i;
                ASSERT_NEAR
                (
                    *lambda, (std::abs(h) - r)/(2*std::abs(h)), 1e-14
                ) << "width " << width << ", " << i;
            }
        }
    }
}


// * * * * * * * * * * * * One triangle, closed forms * * * * * * * * * * * //

TEST(SphereContact, NormalApproachOnLargeTriangle)
{
    // lambda = (h - r)/|B - A|, from above and from below
    const double r = 0.5, h = 3, travel = 5;
    for (const Frame& frame : frames)
    {
        for (const double side : {1.0, -1.0})
        {
            const Vector3 A{1, 2, side*h}, B{1, 2, side*(h - travel)};
            const auto lambda =
                firstContact(frame(floorTriangle), frame(A), frame(B), r);
            ASSERT_TRUE(lambda);
            EXPECT_NEAR(*lambda, (h - r)/travel, lambdaTol);

            const auto contact = firstContact
            (
                std::vector<Triangle>{frame(floorTriangle)},
                frame(A),
                frame(B),
                r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, (h - r)/travel, lambdaTol);
            EXPECT_POINT_NEAR(contact->point, frame({1, 2, 0}), pointTol);
        }

        // Oblique onto the face: height 3 - 4 lambda = r
        const auto lambda = firstContact
        (
            frame(floorTriangle), frame({0, 0, 3}), frame({4, 1, -1}), r
        );
        ASSERT_TRUE(lambda);
        EXPECT_NEAR(*lambda, (3 - r)/4, lambdaTol);

        // Stops short of the face: 0.51 above it at B, r = 0.5
        EXPECT_FALSE
        (
            firstContact
            (
                frame(floorTriangle), frame({1, 2, 3}), frame({1, 2, 0.51}), r
            )
        );
    }
}


TEST(SphereContact, ParallelToTriangle)
{
    // The triangle lies in z = 0 on the side x >= 0 of its edge on the y
    // axis; the centre crosses that edge at height y from x = -3 to x = 3.
    // The sphere reaches the edge when x^2 + y^2 = r^2, if y <= r.
    const Triangle t{{0, -100, 0}, {0, 100, 0}, {200, 0, 0}};
    const double r = 1;
    for (const Frame& frame : frames)
    {
        const double y = 0.98*r;
        const Vector3 A{-3, 0.5, y}, B{3, 0.5, y};
        const double lambda = (3 - std::sqrt(r*r - y*y))/6;

        const auto one = firstContact(frame(t), frame(A), frame(B), r);
        ASSERT_TRUE(one);
        EXPECT_NEAR(*one, lambda, lambdaTol);

        const std::vector<Triangle> wall{frame(t)};
        const auto contact = firstContact(wall, frame(A), frame(B), r);
        ASSERT_TRUE(contact);
        EXPECT_NEAR(contact->fraction, lambda, lambdaTol);
        EXPECT_POINT_NEAR(contact->point, frame({0, 0.5, 0}), pointTol);

        const double above = 1.02*r;
        EXPECT_FALSE
        (
            firstContact
            (
                frame(t), frame({-3, 0.5, above}), frame({3, 0.5, above}), r
            )
        );
        EXPECT_FALSE
        (
            firstContact
            (
                std::vector<Triangle>{frame(t)},
                frame({-3, 0.5, above}),
                frame({3, 0.5, above}),
                r
            )
        );
    }
}


TEST(SphereContact, EdgeHit)
{
    // Edge on the x axis from x = -2 to 3, the triangle on its side y <= 0
    // in z = 0, r = 1. The centre stays on the side y > 0: the sphere
    // touches the edge when y^2 + z^2 = r^2 (the cylinder around the edge).
    const Triangle t{{-2, 0, 0}, {3, 0, 0}, {0, -4, 0}};
    const double r = 1;
    for (const Frame& frame : frames)
    {
        // Straight down at y = 0.6: z = 0.8 at lambda = (3 - 0.8)/6
        {
            const Vector3 A{0.5, 0.6, 3}, B{0.5, 0.6, -3};
            const auto contact = firstContact
            (
                std::vector<Triangle>{frame(t)}, frame(A), frame(B), r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, 2.2/6, lambdaTol);
            EXPECT_POINT_NEAR(contact->point, frame({0.5, 0, 0}), pointTol);
        }

        // Obliquely: y = 2 - 2.4 lambda, z = 1 - 0.4 lambda, x = 0.5 + lambda
        {
            const Vector3 A{0.5, 2, 1}, B{1.5, -0.4, 0.6};
            const double lambda = smallerRoot
            (
                2.4*2.4 + 0.4*0.4, -2*(2*2.4 + 1*0.4), 2*2 + 1*1 - r*r
            );
            ASSERT_GT(2 - 2.4*lambda, 0);
            const auto one = firstContact(frame(t), frame(A), frame(B), r);
            ASSERT_TRUE(one);
            EXPECT_NEAR(*one, lambda, lambdaTol);

            const auto contact = firstContact
            (
                std::vector<Triangle>{frame(t)}, frame(A), frame(B), r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, lambda, lambdaTol);
            EXPECT_POINT_NEAR
            (
                contact->point, frame({0.5 + lambda, 0, 0}), pointTol
            );
        }

        // Passing the edge at 1.01 r
        EXPECT_FALSE
        (
            firstContact
            (
                frame(t), frame({0.5, 1.01, 3}), frame({0.5, 1.01, -3}), r
            )
        );
    }
}


TEST(SphereContact, VertexHit)
{
    // The vertex at the origin; the triangle's other vertices make the
    // region x, y >= 0 its Voronoi region. r = 1: |A + lambda d| = r.
    const Triangle t{{0, 0, 0}, {-4, -1, 0}, {-1, -4, 0}};
    const double r = 1;
    for (const Frame& frame : frames)
    {
        // Straight down at (0.3, 0.4): z^2 + 0.25 = 1
        {
            const auto contact = firstContact
            (
                std::vector<Triangle>{frame(t)},
                frame({0.3, 0.4, 5}),
                frame({0.3, 0.4, -5}),
                r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR
            (
                contact->fraction, (5 - std::sqrt(0.75))/10, lambdaTol
            );
            EXPECT_POINT_NEAR(contact->point, frame(t.a), pointTol);
        }

        // Obliquely: A = (3, 2, 1), d = (-4, -1.5, -0.8)
        {
            const Vector3 A{3, 2, 1}, d{-4, -1.5, -0.8};
            const double lambda =
                smallerRoot(dot(d, d), 2*dot(A, d), dot(A, A) - r*r);
            const Vector3 centre = A + lambda*d;
            ASSERT_GT(centre.x, 0);
            ASSERT_GT(centre.y, 0);

            const auto one =
                firstContact(frame(t), frame(A), frame(A + d), r);
            ASSERT_TRUE(one);
            EXPECT_NEAR(*one, lambda, lambdaTol);

            const auto contact = firstContact
            (
                std::vector<Triangle>{frame(t)}, frame(A), frame(A + d), r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, lambda, lambdaTol);
            EXPECT_POINT_NEAR(contact->point, frame(t.a), pointTol);
        }
    }
}


TEST(SphereContact, InContactAtStart)
{
    // Touching (at exactly r) and sliding along (moving exactly parallel)
    // are only exact in the identity frame: elsewhere rounding decides
    const double r = 0.5;
    for (const Frame& frame : frames)
    {
        const std::vector<Triangle> wall{frame(floorTriangle)};
        const struct { Vector3 A, B; bool approaching, exact; } cases[] =
        {
            // Touching, overlapping and sliding along, leaving
            {{1, 2, r}, {1.5, 2, 2}, false, true},
            {{1, 2, 0.5*r}, {1, 2.5, 0.7}, false, false},
            {{1, 2, 0.5*r}, {3, 2, 0.5*r}, false, true},
            // Touching and overlapping, approaching
            {{1, 2, r}, {1.5, 2, -1}, true, true},
            {{1, 2, 0.5*r}, {1, 2.5, 0.1}, true, false}
        };
        for (const auto& c : cases)
        {
            if (c.exact && !frame.identity)
            {
                continue;
            }

            // One triangle: in contact at 0, whichever way it moves
            const auto one =
                firstContact(frame(floorTriangle), frame(c.A), frame(c.B), r);
            ASSERT_TRUE(one);
            EXPECT_EQ(*one, 0);

            // Among triangles: only when approaching
            const auto contact = firstContact(wall, frame(c.A), frame(c.B), r);
            EXPECT_EQ(bool(contact), c.approaching) << c.A.z << " " << c.B.z;
            if (contact)
            {
                EXPECT_EQ(contact->fraction, 0);
                EXPECT_POINT_NEAR(contact->point, frame({1, 2, 0}), pointTol);
            }
        }
    }
}


TEST(SphereContact, StationarySphere)
{
    const double r = 0.5;
    for (const Frame& frame : frames)
    {
        const std::vector<Triangle> wall{frame(floorTriangle)};
        const Triangle floor = frame(floorTriangle);
        const Vector3 touching = frame({1, 2, 0.4});
        const Vector3 apart = frame({1, 2, 0.6});

        EXPECT_EQ(firstContact(floor, touching, touching, r), 0);
        EXPECT_FALSE(firstContact(floor, apart, apart, r));

        // Not approaching: ignored among triangles
        EXPECT_FALSE(firstContact(wall, touching, touching, r));
        EXPECT_FALSE(firstContact(wall, apart, apart, r));
    }
}


TEST(SphereContact, DegenerateTriangles)
{
    const testCases::TrapFloatingPointErrors trap;
    const double r = 1;

    // Collinear on the x axis from 0 to 3, and two vertices the same: the
    // segment. Straight down at y = 0.6: z = 0.8 at lambda = 2.2/6.
    for (const Triangle& t :
         {Triangle{{0, 0, 0}, {3, 0, 0}, {1, 0, 0}},
          Triangle{{0, 0, 0}, {3, 0, 0}, {3, 0, 0}}})
    {
        const auto contact = firstContact
        (
            std::vector<Triangle>{t}, {1.5, 0.6, 3}, {1.5, 0.6, -3}, r
        );
        ASSERT_TRUE(contact);
        EXPECT_NEAR(contact->fraction, 2.2/6, lambdaTol);
        EXPECT_POINT_NEAR(contact->point, Vector3({1.5, 0, 0}), pointTol);

        // Past its end at x = 3: the end's sphere, (x - 3)^2 + z^2 = 1
        const auto end = firstContact(t, {3.6, 0, 3}, {3.6, 0, -3}, r);
        ASSERT_TRUE(end);
        EXPECT_NEAR(*end, 2.2/6, lambdaTol);
    }

    // All three the same: a point, |A + lambda d - v| = r
    const Triangle point{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const auto hit = firstContact(point, {0.3, 0.4, 5}, {0.3, 0.4, -5}, r);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(*hit, (5 - std::sqrt(0.75))/10, lambdaTol);

    // A needle 1e-9 wide at its base: onto its face, h - r = 2 over 4
    const Triangle needle{{0, 0, 0}, {0, 1e-9, 0}, {1, 0, 0}};
    const auto onNeedle = firstContact
    (
        std::vector<Triangle>{needle}, {0.5, 2e-10, 3}, {0.5, 2e-10, -1}, r
    );
    ASSERT_TRUE(onNeedle);
    EXPECT_NEAR(onNeedle->fraction, 0.5, lambdaTol);
    EXPECT_POINT_NEAR(onNeedle->point, Vector3({0.5, 2e-10, 0}), 1e-15);

    // A sliver 1e-13 high: as its longest edge, down at y = 0.6
    const Triangle sliver{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-13, 0}};
    const auto onSliver =
        firstContact(sliver, {0.3, 0.6, 3}, {0.3, 0.6, -3}, r);
    ASSERT_TRUE(onSliver);
    EXPECT_NEAR(*onSliver, 2.2/6, 1e-12);
}


// * * * * * * * * * * * * * * Several triangles  * * * * * * * * * * * * * //

TEST(SphereContact, SeveralTriangles)
{
    const double r = 0.5;
    // A floor at z = 0, a parallel one below at z = -1, a wall at x = 2
    const Triangle below{{-100, -100, -1}, {100, -100, -1}, {0, 100, -1}};
    const Triangle wall{{2, -100, -100}, {2, 100, -100}, {2, 0, 100}};

    for (const Frame& frame : frames)
    {
        // Down onto the floor, the floor below behind it: (3 - r)/5
        std::vector<Triangle> floors{frame(below), frame(floorTriangle)};
        for (int order = 0; order < 2; ++order)
        {
            const auto contact =
                firstContact(floors, frame({1, 2, 3}), frame({1, 2, -2}), r);
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, (3 - r)/5, lambdaTol);
            EXPECT_POINT_NEAR(contact->point, frame({1, 2, 0}), pointTol);
            std::reverse(floors.begin(), floors.end());
        }

        // Towards the wall and the floor: the wall first at x = 2 - r,
        // lambda = 1/2 (the floor at z = r: lambda = 2.5/4)
        std::vector<Triangle> corner{frame(floorTriangle), frame(wall)};
        for (int order = 0; order < 2; ++order)
        {
            const auto contact = firstContact
            (
                corner, frame({0.5, 0, 3}), frame({2.5, 0, -1}), r
            );
            ASSERT_TRUE(contact);
            EXPECT_NEAR(contact->fraction, 0.5, lambdaTol);
            EXPECT_POINT_NEAR(contact->point, frame({2, 0, 1}), pointTol);
            std::reverse(corner.begin(), corner.end());
        }

        // Leaving the floor (overlapping it) towards the wall: the wall at
        // x = 2 - r, lambda = 1/2, while the floor is still nearer (z = 0.3)
        const auto contact = firstContact
        (
            corner, frame({0.5, 0, 0.2}), frame({2.5, 0, 0.4}), r
        );
        ASSERT_TRUE(contact);
        EXPECT_NEAR(contact->fraction, 0.5, lambdaTol);
        EXPECT_POINT_NEAR(contact->point, frame({2, 0, 0.3}), pointTol);

        // A square of two triangles hit on their common edge x + y = 2:
        // the same lambda from both, and the point on the edge
        const std::vector<Triangle> square
        {
            frame(Triangle{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}),
            frame(Triangle{{2, 0, 0}, {2, 2, 0}, {0, 2, 0}})
        };
        const auto onEdge =
            firstContact(square, frame({1, 1, 3}), frame({1, 1, -1}), r);
        ASSERT_TRUE(onEdge);
        EXPECT_NEAR(onEdge->fraction, (3 - r)/4, lambdaTol);
        EXPECT_POINT_NEAR(onEdge->point, frame({1, 1, 0}), pointTol);

        // No triangles: no contact
        EXPECT_FALSE
        (
            firstContact
            (
                std::vector<Triangle>(), frame({0, 0, 0}), frame({1, 1, 1}), r
            )
        );
    }
}


// * * * * * * * * * * * * * Against dense sampling * * * * * * * * * * * * //

TEST(SphereContact, RandomAgainstSampling)
{
    // The first sample k/n at which the reference distance is <= r brackets
    // the contact: (k - 1)/n < lambda <= k/n; no sample within r and no
    // contact, unless the sphere only grazes (the distance stays within
    // a sampling step's worth of r)
    constexpr int n = 100000;
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto random = [&](double size)
    {
        const double x = unit(rng), y = unit(rng), z = unit(rng);
        return size*Vector3{2*x - 1, 2*y - 1, 2*z - 1};
    };

    int contacts = 0, misses = 0, atStart = 0;
    for (int i = 0; i < 200; ++i)
    {
        Triangle t{random(1), random(1), random(1)};
        if (i % 10 == 3)
        {
            t.c = t.a + 1.7*(t.b - t.a);    // collinear
        }
        else if (i % 10 == 5 || i % 10 == 7)
        {
            // A sliver with a plane, and one without (edges only)
            const double height = i % 10 == 5 ? 1e-6 : 1e-12;
            t.c = t.a + 0.4*(t.b - t.a) + height*random(1);
        }
        const Vector3 A = random(1.5), B = random(0.8);
        const double r = 0.05 + 0.95*unit(rng);

        const auto distance = [&](double lambda)
        {
            return referenceDistance(t, A + lambda*(B - A));
        };
        int first = -1;
        double nearest = distance(0);
        for (int k = 0; k <= n && first < 0; ++k)
        {
            const double dk = distance(double(k)/n);
            nearest = std::min(nearest, dk);
            if (dk <= r)
            {
                first = k;
            }
        }

        const auto lambda = firstContact(t, A, B, r);
        if (first == 0)
        {
            ++atStart;
            ASSERT_TRUE(lambda) << i;
            EXPECT_EQ(*lambda, 0) << i;
        }
        else if (first > 0)
        {
            ++contacts;
            ASSERT_TRUE(lambda) << i;
            EXPECT_GT(*lambda, (first - 1.0)/n - 1e-12) << i;
            EXPECT_LE(*lambda, double(first)/n + 1e-12) << i;
            EXPECT_NEAR(distance(*lambda), r, 1e-12) << i;
        }
        else
        {
            ++misses;
            if (lambda)
            {
                // A graze between two samples
                EXPECT_NEAR(distance(*lambda), r, 1e-12) << i;
                EXPECT_LT(nearest - r, 1e-8) << i;
            }
        }
    }
    // Each kind well represented
    EXPECT_GT(contacts, 60);
    EXPECT_GT(misses, 60);
    EXPECT_GT(atStart, 15);
    std::cout << "    " << contacts << " contacts, " << misses << " misses, "
        << atStart << " in contact at the start" << std::endl;
}


TEST(SphereContact, SeveralAgainstEachAlone)
{
    // With no triangle touched at the start, the earliest contact among
    // several is the earliest of each alone, at a point r from the centre
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(-1, 1);
    const auto random = [&] {
        return Vector3{unit(rng), unit(rng), unit(rng)};
    };
    int contacts = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const double r = 0.1;
        const Vector3 A = 2*random(), B = 2*random();
        std::vector<Triangle> triangles;
        std::optional<double> earliest;
        int earliestIndex = -1;
        while (triangles.size() < 6)
        {
            const Triangle t{random(), random(), random()};
            if (referenceDistance(t, A) <= r)
            {
                continue;
            }
            triangles.push_back(t);
            const auto lambda = firstContact(t, A, B, r);
            if (lambda && (!earliest || *lambda < *earliest))
            {
                earliest = lambda;
                earliestIndex = int(triangles.size()) - 1;
            }
        }
        const auto contact = firstContact(triangles, A, B, r);
        ASSERT_EQ(bool(contact), bool(earliest)) << i;
        if (contact)
        {
            ++contacts;
            EXPECT_EQ(contact->fraction, *earliest) << i;
            EXPECT_EQ(contact->triangle, earliestIndex) << i;
            const Vector3 centre = A + contact->fraction*(B - A);
            EXPECT_NEAR(mag(centre - contact->point), r, 1e-12) << i;
        }

        // Over the candidates 1, 3, 5 only: the earliest of those alone
        std::vector<PreparedTriangle> prepared;
        for (const Triangle& t : triangles)
        {
            prepared.push_back(prepare(t));
        }
        const std::vector<int> odd{1, 3, 5};
        std::optional<double> earliestOdd;
        int earliestOddIndex = -1;
        for (const int index : odd)
        {
            const auto lambda = firstContact(triangles[index], A, B, r);
            if (lambda && (!earliestOdd || *lambda < *earliestOdd))
            {
                earliestOdd = lambda;
                earliestOddIndex = index;
            }
        }
        const auto contactOdd =
            firstContact(prepared, odd.data(), odd.data() + 3, A, B, r);
        ASSERT_EQ(bool(contactOdd), bool(earliestOdd)) << i;
        if (contactOdd)
        {
            EXPECT_EQ(contactOdd->fraction, *earliestOdd) << i;
            EXPECT_EQ(contactOdd->triangle, earliestOddIndex) << i;
        }
    }
    EXPECT_GT(contacts, 5000);
}


TEST(SphereContact, AlongAPlaneOfSeveralTriangles)
{
    // The plane z = 0 as two squares of two triangles each, split at x = 1
    const std::vector<Triangle> plane
    {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
        {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}}, {{1, 0, 0}, {2, 1, 0}, {1, 1, 0}}
    };
    const double r = 0.1;
    for (const double height : {0.98*r, r})
    {
        // Overlapping (0.98 r) or touching (r) the plane, moving along it
        // across the edges: no contact at any triangle's edge
        const auto along =
            firstContact(plane, {0.3, 0.5, height}, {1.7, 0.4, height}, r);
        EXPECT_FALSE(along) << "height " << height << ": contact at "
            << (along ? along->fraction : -1);

        // ...and leaving it
        EXPECT_FALSE
        (
            firstContact(plane, {0.3, 0.5, height}, {1.7, 0.4, 2*r}, r)
        ) << height;
    }

    // Overlapping and approaching: a contact at A
    const auto approaching =
        firstContact(plane, {0.3, 0.5, 0.98*r}, {1.7, 0.4, 0.5*r}, r);
    ASSERT_TRUE(approaching);
    EXPECT_EQ(approaching->fraction, 0);

    // The plane's second half alone, approached along it at 0.98 r from
    // beyond its edge x = 1: the edge is touched where
    // (1 - x)^2 + (0.98 r)^2 = r^2
    const std::vector<Triangle> half(plane.begin() + 2, plane.end());
    const auto edge =
        firstContact(half, {0.5, 0.5, 0.98*r}, {1.5, 0.5, 0.98*r}, r);
    ASSERT_TRUE(edge);
    EXPECT_NEAR
    (
        edge->fraction, (0.5 - r*std::sqrt(1 - 0.98*0.98))/1.0, lambdaTol
    );
    EXPECT_NEAR(edge->point.x, 1, 1e-15);
    EXPECT_NEAR(edge->point.z, 0, 1e-15);
    EXPECT_FALSE
    (
        firstContact(half, {0.5, 0.5, 1.02*r}, {1.5, 0.5, 1.02*r}, r)
    );
}


TEST(SphereContact, SlidingWithinTheContactTolerance)
{
    // The rule of the contact tolerance tol (about 1e-9 r here), not exact
    // geometry: a parcel that moves along a wall at contact (a rebound
    // without normal velocity) starts at r from the plane to rounding,
    // above or below it, and rounding tilts its segment into the plane or
    // out of it. Starting within tol of r and ending no deeper than r - tol
    // it slides, and no triangle of the plane is touched, in any frame
    const std::vector<Triangle> plane
    {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
        {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}}, {{1, 0, 0}, {2, 1, 0}, {1, 1, 0}}
    };
    const std::vector<Triangle> half(plane.begin() + 2, plane.end());
    const double r = 0.1;
    for (const Frame& frame : frames)
    {
        std::vector<Triangle> wall, halfWall;
        for (const Triangle& t : plane)
        {
            wall.push_back(frame(t));
        }
        for (const Triangle& t : half)
        {
            halfWall.push_back(frame(t));
        }
        const auto along = [&](const std::vector<Triangle>& w, double h,
                               double sink)
        {
            return firstContact
            (
                w, frame({0.3, 0.5, h}), frame({1.7, 0.4, h - sink}), r
            );
        };
        for (const double h : {r*(1 - 0.5e-9), r*(1 - 1e-12), r,
                               r*(1 + 1e-12), r*(1 + 0.5e-9)})
        {
            for (const double sink : {0.0, 1e-12*r, 0.5e-9*r, -1e-12*r})
            {
                const auto c = along(wall, h, sink);
                EXPECT_FALSE(c) << "identity " << frame.identity << ", height "
                    << h/r << " r, sinking " << sink/r << " r: contact at "
                    << (c ? c->fraction : -1);
                // ...nor the plate's edge, reached from beyond it
                EXPECT_FALSE(along(halfWall, h, sink)) << h/r << " " << sink/r;
            }
        }

        // Approaching by 1e-6 r from contact (to the tolerance): a contact
        // at once (the rotated frame may put the start 1e-16 beyond r and
        // find it at that rounding over the approach, below 1e-8; from
        // r (1 + 1e-12) the exact contact lies 1e-6 of the segment on, 1e-12
        // r nearer the plane: the tolerance takes it as touching)
        for (const double h : {r*(1 - 1e-12), r, r*(1 + 1e-12)})
        {
            const auto c = along(wall, h, 1e-6*r);
            ASSERT_TRUE(c) << h/r;
            EXPECT_LE(c->fraction, 1e-8) << h/r;
        }
        // From 1e-6 r beyond contact, approaching by 1e-3 r: where it is
        // 1e-6 r nearer, lambda = 1e-3 (to the rounding of the heights)
        const auto beyond = along(wall, r*(1 + 1e-6), 1e-3*r);
        ASSERT_TRUE(beyond);
        EXPECT_NEAR(beyond->fraction, 1e-3, 1e-12);

        // A slow approach is caught once it ends deeper than r - tol:
        // from r (1 - 0.8e-9), sinking 0.4e-9 r
        const auto slow = along(wall, r*(1 - 0.8e-9), 0.4e-9*r);
        ASSERT_TRUE(slow);
        EXPECT_EQ(slow->fraction, 0);

        // Overlapping deeply (0.5 r), beyond the contact band: any approach
        // is a contact at once; moving exactly along (identity frame only:
        // elsewhere rounding decides) or away is none
        const auto deep = along(wall, 0.5*r, 1e-12*r);
        ASSERT_TRUE(deep);
        EXPECT_EQ(deep->fraction, 0);
        if (frame.identity)
        {
            EXPECT_FALSE(along(wall, 0.5*r, 0));
        }
        EXPECT_FALSE(along(wall, 0.5*r, -1e-6*r));
    }

    // A point (r = 0) within the tolerance of the plane, moving through it
    // slowly: a contact at once (no sliding for a radius within tol)
    const auto point = firstContact
    (
        plane, {0.3, 0.5, 4e-15}, {0.4, 0.5, -4e-15}, 0
    );
    ASSERT_TRUE(point);
    EXPECT_EQ(point->fraction, 0);

    // Far from the origin (rotated, then shifted by millions of radii: a
    // sub-micron particle in a domain of centimetres), where rounding of
    // the coordinates alone (about 1e-8 r here) exceeds 1e-9 r: the
    // tolerance grows with the coordinates, and sliding stays sliding
    const Frame rotated{false};
    const auto far = [&](const Vector3& v)
    {
        return rotated(v) + Vector3{1e6, 2e6, -3e6};
    };
    std::vector<Triangle> farWall;
    for (const Triangle& t : plane)
    {
        farWall.push_back({far(t.a), far(t.b), far(t.c)});
    }
    int slid = 0;
    for (int i = 0; i <= 100; ++i)
    {
        // Starts along the plane, each rounded its own way
        const double x = 0.3 + 0.004*i;
        if (!firstContact(farWall, far({x, 0.5, r}), far({x + 1, 0.4, r}), r))
        {
            ++slid;
        }
    }
    EXPECT_EQ(slid, 101);
    const auto farApproach =
        firstContact(farWall, far({0.3, 0.5, r}), far({1.3, 0.4, 0.999*r}), r);
    ASSERT_TRUE(farApproach);
    EXPECT_LE(farApproach->fraction, 1e-4);
}


TEST(SphereContact, FromBesideThePlaneOverTheTriangle)
{
    // A starts within r of the triangle's plane but beside the triangle
    // and rises over it: the edge x = 0 is touched first, before the
    // centre leaves the slab |z| < r over the triangle. Expected: the first
    // lambda where the reference distance is r, sampled and bisected.
    const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const double r = 0.1;
    const Vector3 A{-0.15, 0.2, 0.02}, B{0.35, 0.2, 0.17};
    double below = 0, above = 1;
    for (int i = 1; i <= 100000; ++i)
    {
        if (referenceDistance(t, A + (i/100000.0)*(B - A)) <= r)
        {
            below = (i - 1)/100000.0;
            above = i/100000.0;
            break;
        }
    }
    // (by hand: (-0.15 + 0.5 l)^2 + (0.02 + 0.15 l)^2 = r^2, l = 0.114;
    // the slab is left at l = 0.533)
    ASSERT_GT(above, 0.1);
    ASSERT_LT(above, 0.12);
    for (int i = 0; i < 60; ++i)
    {
        const double mid = 0.5*(below + above);
        (referenceDistance(t, A + mid*(B - A)) <= r ? above : below) = mid;
    }
    const auto lambda = firstContact(t, A, B, r);
    ASSERT_TRUE(lambda);
    EXPECT_NEAR(*lambda, above, 1e-12);
    const auto several = firstContact(std::vector<Triangle>{t}, A, B, r);
    ASSERT_TRUE(several);
    EXPECT_NEAR(several->fraction, above, 1e-12);
}


TEST(SphereContact, LeavingWallsOnTheCallersVerdict)
{
    // A floor of two triangles flat only to 1e-7 r (its far edge x = 1
    // raised by delta: faces a mesh's grouping into planes takes as one
    // plane), and beyond that edge a slope down at 45 degrees. A sphere
    // slides along the floor's plane z = 0 at z = r over the edge: the
    // caller's verdict on the floor is "slides" (slidesOrLeaves of its
    // plane), though each floor triangle's own plane lies up to delta
    // nearer, far beyond the tolerance (1e-9 r). Handed as leaving, the
    // floor is never touched, and the slope, met first at the edge it
    // shares with the floor (a point of a wall the sphere slides along), is
    // not touched either: no contact. As plain candidates, the core finds
    // the raised floor at once.
    const double r = 0.1, delta = 1e-7*r;
    const std::vector<Triangle> walls
    {
        {{0, 0, 0}, {1, 0, delta}, {1, 1, delta}},
        {{0, 0, 0}, {1, 1, delta}, {0, 1, 0}},
        {{1, 0, delta}, {2, 0, delta - 1}, {2, 1, delta - 1}},
        {{1, 0, delta}, {2, 1, delta - 1}, {1, 1, delta}}
    };
    for (const Frame& frame : frames)
    {
        std::vector<PreparedTriangle> prepared;
        for (const Triangle& t : walls)
        {
            prepared.push_back(prepare(frame(t)));
        }
        const int floor[] = {0, 1}, slope[] = {2, 3}, all[] = {0, 1, 2, 3};
        const Vector3 A = frame({0.5, 0.5, r}), B = frame({1.2, 0.5, r});

        const auto c = firstContact(prepared, slope, slope + 2, A, B, r,
                                    floor, floor + 2);
        EXPECT_FALSE(c) << frame.identity << ": contact at "
            << (c ? c->fraction : -1) << " with " << (c ? c->triangle : -1);

        const auto plain = firstContact(prepared, all, all + 4, A, B, r);
        ASSERT_TRUE(plain) << frame.identity;
        EXPECT_EQ(plain->fraction, 0) << frame.identity;
        EXPECT_LT(plain->triangle, 2) << frame.identity;
    }
}


TEST(SphereContact, AsManyOverlappedWallsAsThereAre)
{
    // The geometry of LeavingWallsOnTheCallersVerdict, with 100 small
    // triangles of the floor's plane along the path handed as leaving
    // before the floor's own two: however many walls the sphere overlaps,
    // the slope met at the floor's edge is still a point of one of them,
    // and there is no contact (the same answer as with the floor alone).
    // A search that held only the first 64 overlapped walls lost the
    // floor's and touched the slope at the edge
    const double r = 0.1, delta = 1e-7*r;
    std::vector<Triangle> walls
    {
        {{0, 0, 0}, {1, 0, delta}, {1, 1, delta}},
        {{0, 0, 0}, {1, 1, delta}, {0, 1, 0}},
        {{1, 0, delta}, {2, 0, delta - 1}, {2, 1, delta - 1}},
        {{1, 0, delta}, {2, 1, delta - 1}, {1, 1, delta}}
    };
    std::vector<int> leaving;
    for (int i = 0; i < 100; ++i)
    {
        const double x = 0.5 + 0.005*i;
        walls.push_back({{x, 0.45, 0}, {x + 0.004, 0.45, 0}, {x, 0.55, 0}});
        leaving.push_back(int(walls.size()) - 1);
    }
    leaving.push_back(0);
    leaving.push_back(1);
    for (const Frame& frame : frames)
    {
        std::vector<PreparedTriangle> prepared;
        for (const Triangle& t : walls)
        {
            prepared.push_back(prepare(frame(t)));
        }
        const int slope[] = {2, 3};
        const Vector3 A = frame({0.5, 0.5, r}), B = frame({1.2, 0.5, r});
        const auto c = firstContact
        (
            prepared, slope, slope + 2, A, B, r,
            leaving.data(), leaving.data() + leaving.size()
        );
        EXPECT_FALSE(c) << frame.identity << ": contact at "
            << (c ? c->fraction : -1) << " with " << (c ? c->triangle : -1);
    }
}


TEST(SphereContact, InputChecks)
{
    const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<Triangle> ts{t};
    const double nan = std::nan("");
    EXPECT_THROW(firstContact(t, {0, 0, 1}, {0, 0, 0}, -1), InputError);
    EXPECT_THROW(firstContact(ts, {0, 0, 1}, {0, 0, 0}, nan), InputError);
    EXPECT_THROW(firstContact(t, {nan, 0, 1}, {0, 0, 0}, 1), InputError);
    EXPECT_THROW(firstContact(ts, {0, 0, 1}, {0, 0, INFINITY}, 1), InputError);

    // r = 0: a point meeting the triangle
    const auto lambda = firstContact(t, {0.2, 0.2, 1}, {0.2, 0.2, -1}, 0);
    ASSERT_TRUE(lambda);
    EXPECT_NEAR(*lambda, 0.5, lambdaTol);
}
