#!/usr/bin/python3
# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""Analytic checks for the Brownian-force study (numpy only).

1. Exact OU step moments (Var v, Cov, Var x) against numerical quadrature.
2. Design 1 (fresh white-noise force per calc, variance q/dt), constant
   sub-steps: stationary velocity variance 2 tanh(h/2)/h, correlation factor
   coth(h/2), D_eff = D exactly; same for any one-step linear velocity scheme.
3. Design 1 on a periodic pattern of sub-steps: D_eff/D closed form; the
   h -> inf limit  sum(h_{k+1}^2/h_k)/sum(h_k)  (1.5333 for 0.3,0.3,0.3,0.1).
4. OpenFOAM's BrownianMotionForce: pi*S0 = 2 kT/(m tau_LA); per-component
   variance of f*|N|*dir is f^2/3; kurtosis 27/5; Cunningham factors; the
   resulting D relative to Stokes-Einstein with the drag models of v1912.
5. Physical h = DT/tau for typical aerosol particles.
"""
import numpy as np

out = []
def p(*a):
    s = " ".join(str(x) for x in a)
    print(s)
    out.append(s)

# ---------------------------------------------------------------- 1 -----
p("# 1. exact OU step moments (tau = 1, kT/m = 1, q = 2)")
for h in [1e-3, 0.1, 1.0, 10.0]:
    r = np.linspace(0, h, 200001)
    w = np.full_like(r, 1.0); w[0] = w[-1] = 0.5; w *= r[1] - r[0]       # trapezoid
    q = 2.0
    varv = q*np.sum(w*np.exp(-2*r))
    cov = q*np.sum(w*(1 - np.exp(-r))*np.exp(-r))
    varx = q*np.sum(w*(1 - np.exp(-r))**2)
    E = np.exp(-h)
    p("h=%-6g Var v %.10g (closed %.10g)  Cov %.10g (closed %.10g)  Var x %.10g (closed %.10g)"
      % (h, varv, 1 - E*E, cov, (1 - E)**2, varx, 2*h - 3 + 4*E - E*E))
p("stationary-start MSD 2D tau^2 (t/tau - 1 + e^-t/tau) = Var x + (1-e^-h)^2 (v0 ~ N(0,kT/m)):",
  "check at h=1:", 2*1 - 3 + 4*np.exp(-1) - np.exp(-2) + (1 - np.exp(-1))**2, "=", 2*(1 - 1 + np.exp(-1)))

# ---------------------------------------------------------------- 2 -----
p("\n# 2. design 1, constant sub-steps of h = dt/tau")
p("h, sigma_u^2/(kT/m) [=2tanh(h/2)/h], corr factor [coth(h/2)], D_eff/D (analytical), D_eff/D (Euler)")
for h in [0.01, 0.1, 1, 10, 100, 1e4]:
    q = 2.0
    for name, rho in (("an", np.exp(-h)), ("eu", 1/(1 + h))):
        kick = q*(1 - rho)**2/h            # tau = 1: Var of the velocity kick om*tau*a, a ~ N(0, q/dt)
        s2 = kick/(1 - rho*rho)
        corr = (1 + rho)/(1 - rho)
        D = 0.5*h*s2*corr
        if name == "an":
            an = (s2, corr, D)
        else:
            eu = (s2, corr, D)
    p("%-7g %.6g (%.6g)  %.6g (%.6g)  %.12g  %.12g" % (h, an[0], 2*np.tanh(h/2)/h, an[1], 1/np.tanh(h/2), an[2], eu[2]))

# ---------------------------------------------------------------- 3 -----
p("\n# 3. design 1 on a periodic sub-step pattern (fractions of DT), analytical scheme")
def d1_periodic(fracs, h, euler=False):
    hk = np.array(fracs)*h
    rho = 1/(1 + hk) if euler else np.exp(-hk)
    om = 1 - rho
    n = len(hk)
    # S_k = h_k + rho_k S_{k+1}, periodic: solve by iterating many periods
    S = np.zeros(n)
    for _ in range(200000 if h < 1 else 2000):
        Snew = np.empty(n)
        nxt = S[0]
        for k in range(n - 1, -1, -1):
            Snew[k] = hk[k] + rho[k]*nxt
            nxt = Snew[k]
        if np.allclose(Snew, S, rtol=1e-15, atol=0):
            S = Snew
            break
        S = Snew
    Snext = np.roll(S, -1)
    return np.sum(2*om**2*Snext**2/hk)/(2*np.sum(hk))
for fr, name in (([0.3, 0.3, 0.3, 0.1], "maxCo 0.3"), ([0.25]*4, "maxCo 0.25"), ([0.5, 0.5], "maxCo 0.5"),
                 ([0.02]*50, "maxCo 0.02")):
    p(name, " ".join("h=%g:%.5f" % (h, d1_periodic(fr, h)) for h in [0.1, 1, 10, 100, 1e4]))
p("limit h->inf, 0.3,0.3,0.3,0.1: sum h_{k+1}^2/h_k / sum h_k =", (0.3 + 0.3 + 0.1**2/0.3 + 0.3**2/0.1))
p("Euler scheme, maxCo 0.3:", " ".join("h=%g:%.5f" % (h, d1_periodic([0.3, 0.3, 0.3, 0.1], h, True)) for h in [0.1, 1, 10, 100, 1e4]))

# ---------------------------------------------------------------- 4 -----
p("\n# 4. OpenFOAM v1912 BrownianMotionForce coefficients")
kB = 1.380649e-23
T = 293.15
mu = 1.81e-5
lam = 0.0665e-6
rhop = 1000.0
def Cc(d):
    a = 2*lam/d
    return 1 + a*(1.257 + 0.4*np.exp(-1.1/a))
rng = np.random.default_rng(1)
N = 2_000_000
th = rng.random(N)*2*np.pi; u = 2*rng.random(N) - 1; a = np.sqrt(1 - u*u)
g = np.abs(rng.standard_normal(N))
F = np.stack([g*a*np.cos(th), g*a*np.sin(th), g*u], axis=1)
p("per-component variance of |N|*dir (MC, 2e6): %s  (1/3 expected)" % np.round(F.var(axis=0), 4))
p("per-component kurtosis: %s (27/5 = 5.4; Gaussian 3)" % np.round((F**4).mean(axis=0)/F.var(axis=0)**2, 3))
p("E|F|^2 = %.4f (=1; a 3-D Gaussian force with per-component variance 1 would have 3)" % (F**2).sum(axis=1).mean())
p("")
p("d [nm]   Cc      tau_d=rho d^2/18mu [s]  tau_LA=Cc tau_d   pi*S0*m*tau_LA/(2kT)   D_OF/D_SE(sphereDrag)  D_OF/D_SE(drag with Cc)")
for dn in [10, 30, 100, 300, 1000, 3000]:
    d = dn*1e-9
    c = Cc(d)
    m = rhop*np.pi*d**3/6
    S0 = 216*mu*kB*T/(np.pi**2*d**5*rhop**2*c)
    taud = rhop*d*d/(18*mu)
    tauLA = c*taud
    ratio = np.pi*S0*m*tauLA/(2*kB*T)
    # per-component acceleration intensity of OpenFOAM's force: pi*S0/3
    D_SE = kB*T*c/(3*np.pi*mu*d)
    D_OF_sphere = (np.pi*S0/3)*taud**2/2          # drag without Cc (sphereDrag, Stokes limit)
    D_OF_cc = (np.pi*S0/3)*tauLA**2/2             # drag with Cc
    p("%-7g %-7.4g %-23.4g %-17.4g %-22.6f %-22.5g %.5g" % (dn, c, taud, tauLA, ratio, D_OF_sphere/D_SE, D_OF_cc/D_SE))
p("(D_OF = (pi S0/3) tau^2/2 per component in the h->0 limit; times the design-1 factor of the sub-step pattern otherwise)")

p("\nTurbulent branch f = sqrt(2 k^2 T^2/(Dp dt)) with k the TKE [m2/s2]:")
p("  units: (m^2 s^-2)^2 K^2 / (m^2 s^-1 * s) -> m s^-2 K after sqrt: not a force [N]; with k = kB [J/K]:")
p("  sqrt(2 kB^2 T^2/(Dp dt)) [N] = sqrt(2 kB T * (kB T/Dp)/dt) = the laminar force with friction kB T/Dp = m/tau_LA")
for dn in [100, 1000]:
    d = dn*1e-9; c = Cc(d); m = rhop*np.pi*d**3/6
    Dp = kB*T*c/(3*np.pi*mu*d)
    dt = 1e-5
    S0 = 216*mu*kB*T/(np.pi**2*d**5*rhop**2*c)
    f_lam = m*np.sqrt(np.pi*S0/dt)
    f_kB = np.sqrt(2*kB**2*T**2/(Dp*dt))
    for kc in (1e-2, 1.0):
        f_turb = np.sqrt(2*kc**2*T**2/(Dp*dt))
        p("  d=%g nm dt=1e-5: laminar f=%.4g N, with kB: %.4g N, code with k=%g m2/s2: %.4g ('N') = %.3g x laminar"
          % (dn, f_lam, f_kB, kc, f_turb, f_turb/f_lam))

# ---------------------------------------------------------------- 5 -----
p("\n# 5. physical h = DT/tau_LA (rho_p = 1000 kg/m3, air 293 K)")
p("d [nm]  tau [s]     D_SE [m2/s]   v_th=sqrt(kT/m) [m/s]  h at DT = 1e-6, 1e-5, 1e-4, 1e-3 s")
for dn in [10, 30, 100, 300, 1000, 3000]:
    d = dn*1e-9; c = Cc(d); m = rhop*np.pi*d**3/6
    tau = c*rhop*d*d/(18*mu)
    p("%-7g %-11.3g %-13.3g %-22.3g %s" % (dn, tau, kB*T*c/(3*np.pi*mu*d), np.sqrt(kB*T/m),
                                          "  ".join("%.3g" % (dt/tau) for dt in (1e-6, 1e-5, 1e-4, 1e-3))))

open(__file__.replace(".py", ".out"), "w").write("\n".join(out) + "\n")
