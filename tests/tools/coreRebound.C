// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The core's prediction of one impact, for the case tests to compare the
// solver with: velocity after impact in the global frame.
//
//     coreRebound d rho Ep nup Ew nuw R|k,p gamma|c,n Ux Uy Uz nx ny nz Wx Wy Wz
//
// Restitution and adhesion: 'k,p' and 'c,n' give the power laws of Eqs. 15
// and 24; a single number R or gamma gives the constant laws; friction is
// sticking. n is the wall normal into the fluid, W the wall velocity.
// Prints "Ux Uy Uz captured wx wy wz R gamma WA energyLoss" (velocity, 0
// or 1, angular velocity after impact, the particle not spinning before,
// then the impact's R, gamma, W_A and kinetic energy lost) with 17
// significant digits.

#include "ImpactModel.H"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace brachDunn;

namespace
{

//- "a,b" as two numbers, "a" as one (second is then NaN)
std::pair<double, double> pairOf(const char* text)
{
    const std::string s(text);
    const auto comma = s.find(',');
    if (comma == std::string::npos) return {std::stod(s), std::nan("")};
    return {std::stod(s.substr(0, comma)), std::stod(s.substr(comma + 1))};
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    if (argc != 18)
    {
        std::fprintf(stderr, "usage: coreRebound d rho Ep nup Ew nuw R|k,p"
            " gamma|c,n Ux Uy Uz nx ny nz Wx Wy Wz\n");
        return 1;
    }
    double a[18];
    for (int i = 1; i < 18; ++i)
    {
        if (i != 7 && i != 8) a[i] = std::atof(argv[i]);
    }
    const auto [r1, r2] = pairOf(argv[7]);
    const auto [a1, a2] = pairOf(argv[8]);

    try
    {
        const ImpactModel model
        (
            ElasticMaterial{a[3], a[4]},
            ElasticMaterial{a[5], a[6]},
            std::isnan(r2)
          ? RestitutionLaw::constant(r1) : RestitutionLaw::powerLaw(r1, r2),
            std::isnan(a2)
          ? (a1 > 0 ? AdhesionLaw::constant(a1) : AdhesionLaw::none())
          : AdhesionLaw::powerLaw(a1, a2),
            FrictionLaw::sticking()
        );
        const Vector3 wall{a[15], a[16], a[17]};
        const Vector3 U{a[9], a[10], a[11]};
        const Impact3D out = model.impact
        (
            Particle{a[1], a[2]}, U - wall, Vector3{a[12], a[13], a[14]}
        );
        const Vector3 Uout =
            out.result.captured() ? Vector3{} : out.U + wall;
        std::printf
        (
            "%.17g %.17g %.17g %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
            Uout.x, Uout.y, Uout.z, out.result.captured() ? 1 : 0,
            out.omega.x, out.omega.y, out.omega.z,
            out.result.R, out.result.gamma, out.result.WA,
            out.result.energyLoss
        );
    }
    catch (const InputError& err)
    {
        std::fprintf(stderr, "coreRebound: %s\n", err.what());
        return 1;
    }
    return 0;
}
