// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// The deposition velocity of nearWallDispersion's own equations, without
// OpenFOAM: particles in a channel slab of half-height 180 wall units
// (tests/unit/channelSlab.H's flow), their wall-normal position and
// velocity and the normalised fluid velocity seen advanced with the
// statistics of their position held over each step (SeenVelocity.H's exact
// step, the particle's exact response), captured where y+ reaches the
// radius a+, reflected at the centre plane; a captured particle starts
// again uniform in the slab, so that the concentration stays n/H. V+ is
// the captures per time over that concentration (u* = nu = 1).
//
//     slabDeposition tauPlus dtPlus timePlus [aPlus [n]]
//
// Prints "tau+ .. dt+ ..: captures N  V+ v  (SE s)": captures counted
// after the first third of the time, SE = V+/sqrt(N). A documented run
// (tutorials/pipeDeposition/README.md), not a test.

#include "NearWallTurbulence.H"
#include "SeenVelocity.H"
#include "channelSlab.H"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace brachDunn;

int main(int argc, char** argv)
{
    if (argc < 4)
    {
        std::fprintf(stderr, "usage: slabDeposition tauPlus dtPlus timePlus"
                     " [aPlus [n]]\n");
        return 1;
    }
    const double tauP = std::atof(argv[1]);
    const double dt = std::atof(argv[2]);
    const double time = std::atof(argv[3]);
    const double a = argc > 4 ? std::atof(argv[4]) : 0;
    const int n = argc > 5 ? std::atoi(argv[5]) : 5000;
    const double H = testCases::halfHeight;
    const NearWallSettings settings;
    std::mt19937_64 gen(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(a, H);
    std::vector<double> y(n), v(n, 0.0);
    std::vector<Vector3> w(n);
    for (int i = 0; i < n; ++i)
    {
        y[i] = uniform(gen);
        w[i] = {normal(gen), normal(gen), normal(gen)};
    }
    long captures = 0;
    double airborne = 0;
    const long steps = long(time/dt);
    for (long s = 0; s < steps; ++s)
    {
        const bool counted = s*dt > time/3;
        for (int i = 0; i < n; ++i)
        {
            const SeenStatistics st =
                seenStatistics(testCases::channelFlow(y[i]), settings);
            const Vector3 xi{normal(gen), normal(gen), normal(gen)};
            w[i] = seenVelocityStep(w[i], st, tauP, dt, xi);
            const double u = st.sigma.y*w[i].y;
            if (tauP > 0)
            {
                const double decay = std::exp(-dt/tauP);
                y[i] += u*dt + (v[i] - u)*tauP*(1 - decay);
                v[i] = u + (v[i] - u)*decay;
            }
            else
            {
                y[i] += u*dt;
                v[i] = u;
            }
            if (y[i] > H)
            {
                y[i] = 2*H - y[i];
                w[i].y = -w[i].y;
                v[i] = -v[i];
            }
            if (y[i] <= a)
            {
                captures += counted;
                y[i] = uniform(gen);
                v[i] = 0;
                w[i] = {normal(gen), normal(gen), normal(gen)};
            }
            airborne += counted ? dt : 0;
        }
    }
    const double Vplus = captures/airborne*(H - a);
    std::printf("tau+ %g dt+ %g: captures %ld  V+ %.4g  (SE %.2g)\n",
                tauP, dt, captures, Vplus,
                Vplus/std::sqrt(double(captures > 0 ? captures : 1)));
    return 0;
}
