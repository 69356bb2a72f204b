// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SphereContact.H"
#include "InputError.H"

#include <algorithm>
#include <cmath>

namespace brachDunn
{

namespace
{

inline double magSqr(const Vector3& v)
{
    return dot(v, v);
}


using Face = PreparedTriangle;


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


//- A contact found along the segment, with the distance that breaks ties
struct Hit
{
    double fraction;
    double distSqr;
    Contact contact;
};


//- The search of one segment among candidate triangles. At A: in contact
//  when overlapping and approaching (of several, the nearest). Along the
//  segment: the first contacts of the triangles out of reach at A, the
//  first at a point of no wall the sphere overlaps winning.
//  The triangles the sphere overlaps at A without approaching them (a wall
//  it slides along or leaves), and those it reaches through them: a contact
//  at a point of one of these is no first contact with the wall (the next
//  triangle of the same plane, touched at the edge they share). Rarely more
//  than a few, all of them held (the lists are kept between calls: no
//  allocation once they have grown).
class WallSearch
{
    const std::vector<PreparedTriangle>& triangles_;
    const Vector3& A_;
    const Vector3& B_;
    const Vector3 d_;
    const double r_;
    const double tol_;
    const bool moving_;
    const Box swept_;
    std::vector<int>& overlapped_;
    std::vector<Hit>& hits_;
    std::optional<Contact> atStart_;
    double atStartDistSqr_ = 0;

    void overlap(const int index)
    {
        overlapped_.push_back(index);
    }

    bool onOverlapped(const Vector3& point) const
    {
        const double tolSqr = 1e-12*r_*r_;
        for (const int index : overlapped_)
        {
            const Face& f = triangles_[index];
            if (magSqr(point - closestPoint(f, point)) <= tolSqr)
            {
                return true;
            }
        }
        return false;
    }

    //- A flat triangle against its plane: false when both ends are farther
    //  than r from the plane, on one side, so that the whole swept sphere is
    //  (most triangles near a parcel, cheaply), unless it slides along the
    //  plane or leaves it (to the tolerance, which marks the triangle as
    //  overlapped: sliding); nearAtA false when A is farther than r and the
    //  tolerance from the plane (no contact at A)
    bool nearPlane(const Face& f, bool& nearAtA, bool& sliding) const
    {
        const double hA = dot(f.normal, A_ - f.vertex[0]);
        const double hB = dot(f.normal, B_ - f.vertex[0]);
        const bool beyond = (hA > r_ && hB > r_) || (hA < -r_ && hB < -r_);
        // (sliding needs |hA| within tol of r: most candidates are rejected
        // before it is asked)
        if (beyond && std::abs(hA) > r_ + tol_)
        {
            return false;
        }
        sliding = slidesOrLeaves(hA, hB, r_, tol_);
        if (beyond && !sliding)
        {
            return false;
        }
        nearAtA = std::abs(hA) <= r_ + tol_;
        return true;
    }

    //- Whether the sphere touches f at A (to the tolerance), and then what
    //  it is: moving away or along, or approaching but ending no deeper than
    //  r - tol towards the closest point (rounding, or a slide within the
    //  contact band), is no contact; deeper, any approach is one (the root
    //  only for an approach: rebounds leave)
    bool touchesAtA(const int index, const Face& f)
    {
        const Vector3 point = closestPoint(f, A_);
        const double distSqr = magSqr(A_ - point);
        if (distSqr > (r_ + tol_)*(r_ + tol_))
        {
            return false;
        }
        const double towards = dot(d_, A_ - point);
        if
        (
            towards >= 0
         || (r_ > tol_ && distSqr + towards >= (r_ - tol_)*std::sqrt(distSqr))
        )
        {
            overlap(index);
        }
        else if (!atStart_ || distSqr < atStartDistSqr_)
        {
            atStart_ = Contact{0, point, index};
            atStartDistSqr_ = distSqr;
        }
        return true;
    }

public:

    WallSearch
    (
        const std::vector<PreparedTriangle>& triangles,
        const Vector3& A,
        const Vector3& B,
        const double r,
        std::vector<int>& overlapped,
        std::vector<Hit>& hits
    )
    :
        triangles_(triangles),
        A_(A),
        B_(B),
        d_(B - A),
        r_(r),
        tol_(contactTolerance(A, r)),
        moving_(magSqr(d_) > 0),
        swept_(sweptBox(A, B, r)),
        overlapped_(overlapped),
        hits_(hits)
    {
        overlapped_.clear();
        hits_.clear();
    }

    //- The caller's verdict on the walls the sphere leaves or slides along
    //  (their plane's, not each triangle's: a plane of faces that are flat
    //  only to the caller's grouping)
    void leaving(const int* begin, const int* end)
    {
        for (const int* index = begin; index != end; ++index)
        {
            if (!boxesApart(triangles_[*index], swept_))
            {
                overlap(*index);
            }
        }
    }

    void candidate(const int index)
    {
        const Face& f = triangles_[index];
        bool nearAtA = true;
        bool sliding = false;
        if (f.flat && !nearPlane(f, nearAtA, sliding))
        {
            return;
        }
        if (boxesApart(f, swept_))
        {
            return;
        }
        if (sliding)
        {
            overlap(index);
            return;
        }
        if (nearAtA && touchesAtA(index, f))
        {
            return;
        }
        if (moving_ && !atStart_)
        {
            const std::optional<double> lambda = sweptContact(f, A_, d_, r_);
            if (lambda)
            {
                const Vector3 centre = A_ + *lambda*d_;
                const Vector3 touched = closestPoint(f, centre);
                hits_.push_back
                ({
                    *lambda, magSqr(centre - touched),
                    Contact{*lambda, touched, index}
                });
            }
        }
    }

    std::optional<Contact> result()
    {
        if (atStart_ || hits_.empty())
        {
            return atStart_;
        }
        std::sort
        (
            hits_.begin(), hits_.end(),
            [](const Hit& a, const Hit& b)
            {
                return
                    a.fraction < b.fraction
                 || (a.fraction == b.fraction && a.distSqr < b.distSqr);
            }
        );
        for (const Hit& hit : hits_)
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
};

} // End anonymous namespace


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
    return sweptContact(f, A, d, r);
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
    static thread_local std::vector<int> overlapped;
    static thread_local std::vector<Hit> hits;
    WallSearch search(triangles, A, B, r, overlapped, hits);
    search.leaving(leavingBegin, leavingEnd);
    for (const int* index = candidatesBegin; index != candidatesEnd; ++index)
    {
        search.candidate(*index);
    }
    return search.result();
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
