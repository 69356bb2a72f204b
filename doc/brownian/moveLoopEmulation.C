// adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
// bsim.cpp -- 1-D emulation of OpenFOAM v1912 KinematicParcel::move with a
// Brownian force (or the exact Ornstein-Uhlenbeck step), to measure the
// effective diffusivity and the MSD as functions of h = DT/tau and of the
// sub-step pattern.
//
// Units: tau = 1, kT/m = 1, so D = kT tau/m = 1 and the white-noise intensity
// (per unit mass) is q = 2 kT/(m tau) = 2: a force held over dt has variance
// m^2 q/dt.
//
// Emulated move loop (KinematicParcel.C:300-367), per cloud step DT:
//     sf = 0
//     while sf < 1:
//         f = min(1 - sf, maxCo)                 (l.318-319; maxCo*l/|s| optional, mesh mode)
//         cut: with prob pcut the track stops at a face at a uniform fraction
//              lambda of f (l.324, trackToFace); mesh mode: at real faces
//         sf += f (a completing, uncut track ends at 1-2^-53 with prob pshort,
//              rounding of the stepFraction sums, particle.C:776; one more
//              sub-step of ~1e-16 DT follows)
//         dt = (sf_new - sf_old)*DT                (l.336)
//         x += U_old*dt                            (the track uses s = trackTime*U, l.307)
//         U  = U e^-h + tau(1-e^-h) a              (analytical, or Euler U=(U+h tau a)/(1+h))
//              a = force/m from the design, evaluated with this dt (l.351, calc)
//
// Designs (a = force per unit mass):
//   0  OpenFOAM's BrownianMotionForce, one Cartesian component of
//      f*|N|*dir, dir uniform on the sphere: a = sqrt(q/dt)*|N|*U(-1,1)
//   1  Li & Ahmadi white noise, a = sqrt(q/dt)*N, fresh every calc
//   2  a = A_n = sqrt(q/DT)*N(key n), one draw per cloud step (counter based)
//   3  as 2, but the calc that completes the step (sf reaches 1) uses A_{n+1}
//   4  exact OU outside the force framework: per sub-step (dx, v) bivariate
//      normal, dx added to x
//   5  "setter": U_B held at W_n = tau*A_n during step n (a = W_n/tau, i.e.
//      design 2), and the completing calc sets U_B to W_{n+1} exactly:
//      a = (W_{n+1} - rho W_n)/(tau(1-rho)), any dt
//   6  as 5, but W_n = dx_n/DT with (dx_n, v_{n+1}) the exact OU step of a
//      hidden velocity v_n (needs per-parcel state, or regeneration)
//
// Modes:
//   mc    long stationary trajectory, overlapping-window MSD at step ends
//   rest  ensemble from rest (U = 0, v = 0) at t = 0, MSD at step ends
//   resp  exact-in-noise D_eff for designs 0-3 (response recursion)
//
// Build: g++ -O2 -std=c++17 -o bsim bsim.cpp

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>
#include <algorithm>

// ---------------------------------------------------------------- RNG ----

static inline uint64_t splitmix64(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

static inline double u01(uint64_t r)   // (0,1)
{
    return ((r >> 11) + 0.5) * (1.0/9007199254740992.0);
}

struct Xoshiro
{
    uint64_t s[4];
    bool has = false;
    double cache = 0;
    explicit Xoshiro(uint64_t seed)
    {
        uint64_t z = seed;
        for (int i = 0; i < 4; ++i) { z = splitmix64(z); s[i] = z; }
    }
    static inline uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    inline uint64_t next()
    {
        const uint64_t result = rotl(s[1]*5, 7)*9;
        const uint64_t t = s[1] << 17;
        s[2] ^= s[0]; s[3] ^= s[1]; s[1] ^= s[2]; s[0] ^= s[3];
        s[2] ^= t; s[3] = rotl(s[3], 45);
        return result;
    }
    inline double uniform() { return u01(next()); }
    inline double normal()
    {
        if (has) { has = false; return cache; }
        const double u1 = uniform(), u2 = uniform();
        const double r = std::sqrt(-2*std::log(u1));
        cache = r*std::sin(2*M_PI*u2); has = true;
        return r*std::cos(2*M_PI*u2);
    }
};

// Counter-based normal keyed on (seed, parcel, time index, stream): what a
// force would use to regenerate the same number at every sub-step of a step.
static inline double keyedNormal(uint64_t seed, uint64_t parcel, uint64_t n, uint64_t stream)
{
    uint64_t k = splitmix64(seed ^ splitmix64(parcel*0x632BE59BD9B4E019ULL ^ splitmix64(n + (stream << 56))));
    const double a = u01(splitmix64(k)), b = u01(splitmix64(k ^ 0xD1B54A32D192ED03ULL));
    return std::sqrt(-2*std::log(a))*std::cos(2*M_PI*b);
}

// ------------------------------------------------------------ params -----

struct Params
{
    std::string mode = "mc";
    int design = 1;
    double h = 1;          // DT/tau
    double maxCo = 0.3;
    double pcut = 0;       // probability that a sub-step is cut at a face
    double pshort = 0;     // probability that an uncut completion falls 1 ulp short
    int euler = 0;         // 0 analytical, 1 Euler
    double mesh = 0;       // >0: 1-D mesh with cell size mesh*sqrt(2 D DT), faces cut
    double Co = 0;         // >0: carrier flow crosses a face every 1/Co steps (cuts), limiter f<=maxCo/Co
    long long nsteps = 1000000;
    long long burn = -1;
    int nrep = 8;
    uint64_t seed = 12345;
    long long nparcels = 100000;  // rest mode
    long long lmax = 0;           // rest mode: steps
};

// -------------------------------------------------------- sub-stepper ----

struct SubStep { double dt; bool last; };

// OU exact step coefficients
struct OUStep
{
    double rho, a, sv, c, s;   // v1 = rho v0 + sv z1; dx = a v0 + c z1 + s z2  (tau=1, kT/m=1)
};

static inline double phiSmall(double h)   // h - 2 tanh(h/2)
{
    if (h < 1e-2) { const double h2 = h*h; return h*h2*(1.0/12 - h2/120 + h2*h2*17.0/20160); }
    return h - 2*std::tanh(0.5*h);
}

static inline OUStep ouStep(double h)
{
    OUStep o;
    const double a = -std::expm1(-h);      // 1 - e^-h
    o.rho = 1 - a;
    o.a = a;
    const double varv = a*(2 - a);          // 1 - e^-2h
    o.sv = std::sqrt(varv);
    const double cov = a*a;                 // (1-e^-h)^2
    o.c = varv > 0 ? cov/o.sv : 0;
    const double condVar = 2*phiSmall(h);   // Var dx - cov^2/varv
    o.s = std::sqrt(std::max(0.0, condVar));
    return o;
}

// ------------------------------------------------------------ parcel -----

struct Parcel
{
    double x = 0, u = 0;
    double v = 0;            // design 4: Brownian velocity state; design 6: hidden velocity
    double Wcur = 0, Wnext = 0;  // designs 6: step-mean velocities
    bool haveNext = false;
    long long n = 0;         // time index
    uint64_t id = 0;
    // mesh mode
    long long cell = 0; double xi = 0;
    double toFace = 0;       // Co mode: time to the next face crossing, in steps
};

struct Sim
{
    Params P;
    double DT, q = 2.0, tau = 1.0;
    uint64_t seed;
    Xoshiro rng;
    double cellL = 0;
    long long nsub = 0;

    Sim(const Params& p, uint64_t s) : P(p), DT(p.h), seed(s), rng(s)
    {
        if (P.mesh > 0) cellL = P.mesh*std::sqrt(2*1.0*DT);
    }

    double A(const Parcel& p, long long n) { return std::sqrt(q/DT)*keyedNormal(seed, p.id, (uint64_t)n, 0); }

    // design 6: draw W for step n (from hidden v_n), update hidden to v_{n+1}
    double drawW6(Parcel& p)
    {
        const OUStep o = ouStep(DT/tau);
        const double z1 = rng.normal(), z2 = rng.normal();
        const double dx = o.a*tau*p.v + tau*(o.c*z1 + o.s*z2);
        p.v = o.rho*p.v + o.sv*z1;
        return dx/DT;
    }

    void init(Parcel& p, bool fromRest)
    {
        if (fromRest) { p.u = 0; p.v = 0; }
        else { p.u = rng.normal(); p.v = rng.normal(); }
        if (P.design == 5)
        {
            if (!fromRest) p.u = tau*A(p, p.n);
        }
        if (P.design == 6)
        {
            p.Wcur = drawW6(p);
            if (!fromRest) p.u = p.Wcur;
        }
        if (P.mesh > 0) { p.cell = 0; p.xi = rng.uniform()*cellL; }
        if (P.Co > 0) p.toFace = rng.uniform()/P.Co;
    }

    // one cloud time step of the move loop
    void step(Parcel& p)
    {
        double sf = 0;
        const long long n = p.n;
        while (sf < 1)
        {
            double f = std::min(1 - sf, P.maxCo);
            bool cut = false;
            double lam = 1;
            if (P.mesh > 0)
            {
                // maxCo*l/|s| limiter (l.320)
                const double s = std::fabs(DT*p.u);
                f = std::min(f, P.maxCo*cellL/std::max(1e-15*cellL, s));
                const double disp = p.u*f*DT;
                double dist = p.u > 0 ? cellL - p.xi : p.xi;   // to the face ahead
                if (dist <= 0) dist = cellL;                    // sitting on that face: the next one
                if (std::fabs(disp) > dist)
                {
                    cut = true; lam = dist/std::fabs(disp);
                }
            }
            else if (P.Co > 0)
            {
                f = std::min(f, P.maxCo/P.Co);
                if (p.toFace < f) { cut = true; lam = p.toFace/f; }
            }
            else if (P.pcut > 0 && rng.uniform() < P.pcut)
            {
                cut = true; lam = rng.uniform();
            }
            double df = cut ? lam*f : f;
            if (P.Co > 0) { if (cut) { df = p.toFace; p.toFace = 1/P.Co; } else p.toFace -= df; }
            double sfNew = sf + df;
            // a completing track that falls one ulp short of 1 (rounding in the
            // stepFraction sums of particle.C:776): an extra sub-step of ~1e-16
            if (!cut && !(sfNew < 1) && P.pshort > 0 && rng.uniform() < P.pshort) sfNew = std::nextafter(1.0, 0.0);
            const double dt = (sfNew - sf)*DT;
            const bool last = !(sfNew < 1);
            sf = sfNew;
            ++nsub;
            if (!(dt > 1e-150)) continue;   // ROOTVSMALL guard (l.339)

            const double h = dt/tau;
            if (P.design == 4)
            {
                const OUStep o = ouStep(h);
                const double z1 = rng.normal(), z2 = rng.normal();
                p.x += o.a*tau*p.v + tau*(o.c*z1 + o.s*z2);
                p.v = o.rho*p.v + o.sv*z1;
                continue;
            }

            // position with the start velocity
            const double dx = p.u*dt;
            p.x += dx;
            if (P.mesh > 0)
            {
                if (cut)
                {
                    if (p.u > 0) { p.cell += 1; p.xi = 0; } else { p.cell -= 1; p.xi = cellL; }
                }
                else
                {
                    p.xi += dx;
                    if (p.xi < 0) p.xi = 0;
                    if (p.xi > cellL) p.xi = cellL;
                }
            }

            double rho, om;   // u1 = rho u0 + om*tau*a
            if (!P.euler) { om = -std::expm1(-h); rho = 1 - om; }
            else { rho = 1/(1 + h); om = h/(1 + h); }

            double a = 0;
            switch (P.design)
            {
                case 0:
                    a = std::sqrt(q/dt)*std::fabs(rng.normal())*(2*rng.uniform() - 1);
                    break;
                case 1:
                    a = std::sqrt(q/dt)*rng.normal();
                    break;
                case 2:
                    a = A(p, n);
                    break;
                case 3:
                    a = last ? A(p, n + 1) : A(p, n);
                    break;
                case 5:
                {
                    const double W0 = tau*A(p, n);
                    if (last)
                    {
                        const double W1 = tau*A(p, n + 1);
                        a = (W1 - rho*W0)/(om*tau);
                    }
                    else a = W0/tau;
                    break;
                }
                case 6:
                {
                    if (last)
                    {
                        if (!p.haveNext) { p.Wnext = drawW6(p); p.haveNext = true; }
                        a = (p.Wnext - rho*p.Wcur)/(om*tau);
                    }
                    else a = p.Wcur/tau;
                    break;
                }
            }
            p.u = rho*p.u + om*tau*a;
        }
        if (P.design == 6) { p.Wcur = p.Wnext; p.haveNext = false; }
        p.n += 1;
    }

    double velocity(const Parcel& p) const
    {
        return P.design == 4 ? p.v : p.u;
    }
};

// ------------------------------------------------------------- modes -----

static std::vector<long long> lagList(double h, long long& L1, long long& L2)
{
    L1 = std::max<long long>(4, (long long)std::ceil(15.0/h));
    L2 = 2*L1;
    std::vector<long long> lags = {1, 2, 3, 5, 10, 20, 30, 50, 100, 200};
    std::vector<long long> out;
    for (long long l : lags) if (l < L2) out.push_back(l);
    out.push_back(L1); out.push_back(L2);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

static void runMC(const Params& P)
{
    long long L1, L2;
    const std::vector<long long> lags = lagList(P.h, L1, L2);
    const size_t nl = lags.size();
    std::vector<std::vector<double>> msdRep(P.nrep, std::vector<double>(nl, 0));
    std::vector<double> DRep(P.nrep), u2Rep(P.nrep), kurtRep(P.nrep), subRep(P.nrep);
    for (int r = 0; r < P.nrep; ++r)
    {
        Sim S(P, P.seed + 1000003ULL*r);
        Parcel p; p.id = 7 + r;
        S.init(p, false);
        const long long burn = P.burn >= 0 ? P.burn : std::max<long long>(200, (long long)std::ceil(40.0/P.h));
        for (long long i = 0; i < burn; ++i) S.step(p);
        const long long R = L2 + 1;
        std::vector<double> ring(R);
        ring[0] = p.x;
        std::vector<double> sum(nl, 0);
        std::vector<long long> cnt(nl, 0);
        double u2 = 0, m4 = 0, m2 = 0; long long nu = 0;
        S.nsub = 0;
        for (long long i = 1; i <= P.nsteps; ++i)
        {
            S.step(p);
            ring[i % R] = p.x;
            const double uu = S.velocity(p);
            u2 += uu*uu; ++nu;
            for (size_t j = 0; j < nl; ++j)
            {
                const long long L = lags[j];
                if (i >= L)
                {
                    const double d = p.x - ring[(i - L) % R];
                    sum[j] += d*d; ++cnt[j];
                    if (L == 1) { m2 += d*d; m4 += d*d*d*d; }
                }
            }
        }
        for (size_t j = 0; j < nl; ++j) msdRep[r][j] = sum[j]/cnt[j];
        const size_t j1 = std::find(lags.begin(), lags.end(), L1) - lags.begin();
        const size_t j2 = std::find(lags.begin(), lags.end(), L2) - lags.begin();
        DRep[r] = (msdRep[r][j2] - msdRep[r][j1])/(2*(L2 - L1)*P.h);
        u2Rep[r] = u2/nu;
        const double mm2 = m2/cnt[0], mm4 = m4/cnt[0];
        kurtRep[r] = mm4/(mm2*mm2);
        subRep[r] = double(S.nsub)/P.nsteps;
    }
    auto meanSe = [&](const std::vector<double>& v, double& m, double& se)
    {
        m = 0; for (double x : v) m += x; m /= v.size();
        double s = 0; for (double x : v) s += (x - m)*(x - m);
        se = std::sqrt(s/(v.size() - 1)/v.size());
    };
    double D, Dse, u2, u2se, k, kse, ns, nsse;
    meanSe(DRep, D, Dse); meanSe(u2Rep, u2, u2se); meanSe(kurtRep, k, kse); meanSe(subRep, ns, nsse);
    printf("{\"mode\":\"mc\",\"design\":%d,\"h\":%g,\"maxCo\":%g,\"pcut\":%g,\"pshort\":%g,\"euler\":%d,\"mesh\":%g,\"Co\":%g,"
           "\"nsteps\":%lld,\"nrep\":%d,\"L1\":%lld,\"L2\":%lld,\"D\":%.6f,\"Dse\":%.6f,\"u2\":%.6f,\"u2se\":%.6f,"
           "\"kurt1\":%.4f,\"kurt1se\":%.4f,\"subPerStep\":%.4f,\"lags\":[",
           P.design, P.h, P.maxCo, P.pcut, P.pshort, P.euler, P.mesh, P.Co, P.nsteps, P.nrep, L1, L2, D, Dse, u2, u2se, k, kse, ns);
    for (size_t j = 0; j < nl; ++j) printf("%s%lld", j ? "," : "", lags[j]);
    printf("],\"msd\":[");
    for (size_t j = 0; j < nl; ++j)
    {
        std::vector<double> v(P.nrep); for (int r = 0; r < P.nrep; ++r) v[r] = msdRep[r][j];
        double m, se; meanSe(v, m, se);
        printf("%s[%.6g,%.3g]", j ? "," : "", m, se);
    }
    printf("]}\n");
}

static void runRest(const Params& P)
{
    const long long L = P.lmax;
    std::vector<double> s2(L + 1, 0), s4(L + 1, 0);
    Sim S(P, P.seed);
    for (long long i = 0; i < P.nparcels; ++i)
    {
        Parcel p; p.id = 1000 + i;
        S.init(p, true);
        for (long long n = 1; n <= L; ++n)
        {
            S.step(p);
            s2[n] += p.x*p.x; s4[n] += p.x*p.x*p.x*p.x;
        }
    }
    printf("{\"mode\":\"rest\",\"design\":%d,\"h\":%g,\"maxCo\":%g,\"pcut\":%g,\"pshort\":%g,\"euler\":%d,\"Co\":%g,\"nparcels\":%lld,\"msd\":[",
           P.design, P.h, P.maxCo, P.pcut, P.pshort, P.euler, P.Co, P.nparcels);
    for (long long n = 1; n <= L; ++n)
    {
        const double m = s2[n]/P.nparcels, m4 = s4[n]/P.nparcels;
        const double se = std::sqrt(std::max(0.0, m4 - m*m)/P.nparcels);
        printf("%s[%.6g,%.3g]", n > 1 ? "," : "", m, se);
    }
    printf("]}\n");
}

// Exact-in-noise D_eff for designs 0..3: the displacement is linear in the
// forces; a force a_k in sub-step k changes the velocity by om_k tau a_k,
// which then moves the parcel by om_k tau a_k S_{k+1}, S_k = dt_k + rho_k S_{k+1}.
static void runResp(const Params& P)
{
    Sim S(P, P.seed);
    const double tau = 1, q = 2, DT = P.h;
    // generate the pattern
    std::vector<double> dt, rho, om; std::vector<long long> stepOf; std::vector<char> last;
    Parcel p; S.init(p, false);
    for (long long n = 0; n < P.nsteps; ++n)
    {
        double sf = 0;
        while (sf < 1)
        {
            double f = std::min(1 - sf, P.maxCo);
            bool cut = false; double lam = 1;
            if (P.Co > 0)
            {
                f = std::min(f, P.maxCo/P.Co);
                if (p.toFace < f) { cut = true; lam = p.toFace/f; }
            }
            else if (P.pcut > 0 && S.rng.uniform() < P.pcut) { cut = true; lam = S.rng.uniform(); }
            double df = cut ? lam*f : f;
            if (P.Co > 0) { if (cut) { df = p.toFace; p.toFace = 1/P.Co; } else p.toFace -= df; }
            double sfNew = sf + df;
            if (!cut && !(sfNew < 1) && P.pshort > 0 && S.rng.uniform() < P.pshort) sfNew = std::nextafter(1.0, 0.0);
            const double d = (sfNew - sf)*DT;
            sf = sfNew;
            if (!(d > 1e-150)) continue;
            const double h = d/tau;
            double r, o;
            if (!P.euler) { o = -std::expm1(-h); r = 1 - o; } else { r = 1/(1 + h); o = h/(1 + h); }
            dt.push_back(d); rho.push_back(r); om.push_back(o); stepOf.push_back(n); last.push_back(!(sfNew < 1));
        }
    }
    const size_t K = dt.size();
    std::vector<double> Snext(K);   // S_{k+1}
    double Sk1 = 0;
    for (size_t k = K; k-- > 0;)
    {
        Snext[k] = Sk1;
        Sk1 = dt[k] + rho[k]*Sk1;
    }
    // use kicks in steps [nsteps/20, nsteps*0.8) and divide by that time
    const long long n0 = P.nsteps/20, n1 = (long long)(P.nsteps*0.8);
    const int NB = 20;
    std::vector<double> batch(NB, 0);
    double total = 0;
    if (P.design == 0 || P.design == 1)
    {
        for (size_t k = 0; k < K; ++k)
        {
            if (stepOf[k] < n0 || stepOf[k] >= n1) continue;
            const double c = (q/dt[k])*om[k]*om[k]*tau*tau*Snext[k]*Snext[k]*(P.design == 0 ? 1.0/3.0 : 1.0);
            total += c;
            batch[(stepOf[k] - n0)*NB/(n1 - n0)] += c;
        }
    }
    else
    {
        // accumulate the response of each step's force A_n
        std::vector<double> resp(P.nsteps + 2, 0);
        for (size_t k = 0; k < K; ++k)
        {
            long long idx = stepOf[k];
            if (P.design == 3 && last[k]) idx += 1;
            resp[idx] += om[k]*tau*Snext[k];
        }
        for (long long n = n0; n < n1; ++n)
        {
            const double c = (q/DT)*resp[n]*resp[n];
            total += c;
            batch[(n - n0)*NB/(n1 - n0)] += c;
        }
    }
    const double T = (n1 - n0)*DT;
    const double D = total/(2*T);
    double m = 0, s = 0;
    for (double b : batch) { m += b/(2*T/NB); }
    m /= NB;
    for (double b : batch) { const double x = b/(2*T/NB) - m; s += x*x; }
    const double se = std::sqrt(s/(NB - 1)/NB);
    printf("{\"mode\":\"resp\",\"design\":%d,\"h\":%g,\"maxCo\":%g,\"pcut\":%g,\"pshort\":%g,\"euler\":%d,\"Co\":%g,\"nsteps\":%lld,\"D\":%.7f,\"Dse\":%.7f,\"subPerStep\":%.4f}\n",
           P.design, P.h, P.maxCo, P.pcut, P.pshort, P.euler, P.Co, P.nsteps, D, se, double(K)/P.nsteps);
}

int main(int argc, char** argv)
{
    Params P;
    for (int i = 1; i + 1 < argc; i += 2)
    {
        const std::string k = argv[i]; const char* v = argv[i + 1];
        if (k == "mode") P.mode = v;
        else if (k == "design") P.design = atoi(v);
        else if (k == "h") P.h = atof(v);
        else if (k == "maxCo") P.maxCo = atof(v);
        else if (k == "pcut") P.pcut = atof(v);
        else if (k == "pshort") P.pshort = atof(v);
        else if (k == "euler") P.euler = atoi(v);
        else if (k == "mesh") P.mesh = atof(v);
        else if (k == "Co") P.Co = atof(v);
        else if (k == "nsteps") P.nsteps = atoll(v);
        else if (k == "burn") P.burn = atoll(v);
        else if (k == "nrep") P.nrep = atoi(v);
        else if (k == "seed") P.seed = strtoull(v, nullptr, 10);
        else if (k == "nparcels") P.nparcels = atoll(v);
        else if (k == "lmax") P.lmax = atoll(v);
        else { fprintf(stderr, "unknown %s\n", k.c_str()); return 1; }
    }
    if (P.mode == "mc") runMC(P);
    else if (P.mode == "rest") runRest(P);
    else if (P.mode == "resp") runResp(P);
    return 0;
}
