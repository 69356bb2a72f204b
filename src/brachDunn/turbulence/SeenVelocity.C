// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
#include "SeenVelocity.H"
#include "InputError.H"

#include <cmath>

namespace brachDunn
{

WallFrame WallFrame::of(const Vector3& normal, const Vector3& U)
{
    requirePositive("wall normal length", mag(normal));
    WallFrame f;
    f.n = (1/mag(normal))*normal;
    Vector3 along = U - dot(U, f.n)*f.n;
    if (!(mag(along) > 1e-12*mag(U)) || !(mag(along) > 0))
    {
        // No mean flow along the wall: the axis least aligned with n
        const double ax = std::abs(f.n.x), ay = std::abs(f.n.y),
            az = std::abs(f.n.z);
        const Vector3 axis =
            ax <= ay && ax <= az ? Vector3{1, 0, 0}
          : ay <= az ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
        along = axis - dot(axis, f.n)*f.n;
    }
    f.s = (1/mag(along))*along;
    f.z = cross(f.s, f.n);
    return f;
}


Vector3 seenVelocityStep
(
    const Vector3& w,
    const SeenStatistics& stats,
    const double tauP,
    const double dt,
    const Vector3& xi
)
{
    requireNonNegative("dt", dt);
    requirePositive("TL", stats.TL);
    requirePositive("T", stats.T.x);
    requirePositive("T", stats.T.y);
    requirePositive("T", stats.T.z);
    requireNonNegative("tauP", tauP);

    // The drift scaled by 1/(1 + St) for an inertial particle
    const double scale = 1/(1 + tauP/stats.TL);
    const auto one = [&](double w0, double a, double T, double x)
    {
        const double h = dt/T;
        // the stationary mean, and sqrt(1 - e^-2h) without cancellation
        // at small h
        const double mean = a*T*scale;
        return mean + (w0 - mean)*std::exp(-h) + std::sqrt(-std::expm1(-2*h))*x;
    };
    return
    {
        one(w.x, stats.drift.x, stats.T.x, xi.x),
        one(w.y, stats.drift.y, stats.T.y, xi.y),
        one(w.z, stats.drift.z, stats.T.z, xi.z)
    };
}

} // End namespace brachDunn

// ************************************************************************* //
