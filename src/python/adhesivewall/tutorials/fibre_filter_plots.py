# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The fibreFilter tutorial's plots: efficiency against the Stokes number,
the spectrum with the most penetrating size, where the fibre captures
(fibre_filter.run makes them)."""

from .fibre_filter import spectrum_velocities


def plot_efficiency(path, results, correlation, fibre):
    """eta against Stk, 1-10 um, per face velocity, with the correlations'
    sum where the impaction fit holds and the sum is at most 1."""
    from .. import plots
    fig, ax = plots.figure(10, 6.5)
    for c, U in enumerate(results.unique("U0")):
        colour = "C%d" % c
        for cloud, style in (("stick", "o-"), ("adhesive", "o--")):
            rows = results.where(U0=U, model=cloud, d=lambda d: float(d)
                                 >= 1e-6)
            ax.errorbar(rows["Stk"], rows["eta"], yerr=rows["etaSE"],
                        fmt=style, color=colour, capsize=3,
                        mfc=colour if cloud == "stick" else "none",
                        label=f"{U} m/s {cloud}")
        curve = correlation.where(
            U0=U, d=lambda d: float(d) >= 0.8e-6,
            etaSum=lambda e: e != "" and 0 <= float(e) <= 1)
        ax.plot(curve["Stk"], curve["etaSum"], ":", color=colour, lw=2,
                label=f"{U} m/s correlations")
    plots.axes(ax, "Stokes number Stk = rho_p Cc d^2 U_0 / (18 mu d_f)",
               "single-fibre efficiency",
               "fibre %g um, solidity %g, 1-10 um; solid: stick, dashed: "
               "adhesive, dotted: Kuwabara-flow sum"
               % (fibre.dFibre * 1e6, fibre.alpha),
               xlim=(0.01, 60), ylim=(0, 1.6), xlog=True)
    ax.legend(loc="center left", bbox_to_anchor=(1, 0.5))
    plots.save(fig, path)


def plot_spectrum(path, results, correlation, mpps, fibre):
    """eta against d (log-log) at each face velocity of the spectrum: the
    simulation, stick and adhesive, +- standard error; each mechanism's
    correlation and their sum; the most penetrating size found and Lee &
    Liu's."""
    from .. import plots
    velocities = spectrum_velocities(results)
    fig, axes = plots.figure(11, 6.5 * len(velocities), rows=len(velocities))
    for ax, U in zip([axes] if len(velocities) == 1 else axes, velocities):
        curve = correlation.where(U0=U)
        d = curve["d"] * 1e6
        for name, style, label in (
                ("etaD", "C0--", "diffusion, Stechkina & Fuchs (1966)"),
                ("etaDLL", "C0:", "diffusion, Lee & Liu (1982)"),
                ("etaR", "C2--", "interception, Lee & Liu (1982)"),
                ("etaDR", "C4--",
                 "diffusion-interception, Stechkina et al. (1969)")):
            ax.plot(d, curve[name], style, lw=1.5, label=label)
        valid = curve.where(etaI=lambda e: e != "" and float(e) > 0)
        ax.plot(valid["d"] * 1e6, valid["etaI"], "C1--", lw=1.5,
                label="impaction, Stechkina et al. (1969), R < 0.4")
        ax.plot(valid["d"] * 1e6, valid["etaSum"], "k-", lw=2,
                label="sum of the four")
        for cloud, style in (("stick", "o"), ("adhesive", "s")):
            rows = results.where(U0=U, model=cloud)
            ax.errorbar(rows["d"] * 1e6, rows["eta"], yerr=rows["etaSE"],
                        fmt=style, color="C3", capsize=3, ms=7 if cloud ==
                        "adhesive" else 5, mfc="C3" if cloud == "stick" else
                        "none", label=f"simulation, {cloud} walls")
        m = mpps.where(U0=U)
        if len(m):
            ax.plot(m["dLeeLiu"] * 1e6, m["etaLeeLiu"], "k*", ms=14,
                    label="MPPS, Lee & Liu (1980)")
            ax.plot(m["d"] * 1e6, m["eta"], "*", color="C3", ms=14, mfc="none",
                    label="MPPS found")
        ax.set_yscale("log")
        plots.axes(ax, "particle diameter [um]", "single-fibre efficiency",
                   "fibre %g um, solidity %g, %s m/s: slip and Brownian "
                   "motion on" % (fibre.dFibre * 1e6, fibre.alpha, U),
                   xlim=(0.01, 12), ylim=(3e-4, 3), xlog=True)
        ax.legend(loc="upper center", fontsize=8, ncol=2)
    plots.save(fig, path)


def plot_angles(path, angles):
    from .. import plots
    subs = angles.unique("case")
    fig, axes = plots.figure(10, 7.5, rows=2, columns=2)
    for ax, sub in zip(axes, subs):
        for shift, cloud in ((-2.5, "stick"), (2.5, "adhesive")):
            rows = angles.where(case=sub, model=cloud)
            ax.bar(rows["angle"] + shift, rows["captured"], width=5,
                   alpha=0.7, edgecolor="k", label=cloud)
        row = angles.where(case=sub)
        ax.set_title("U_0 %s m/s, d %g um, Stk %s" % (
            row.text("U0")[0], row["d"][0] * 1e6, row.text("Stk")[0]))
        ax.set_xlim(0, 180)
        ax.set_xticks(range(0, 181, 30))
        ax.set_xlabel("angle from the upstream stagnation point [deg]")
        ax.set_ylabel("captured parcels per 10 deg")
        ax.legend(loc="upper right")
    for ax in axes[len(subs):]:
        ax.set_visible(False)
    fig.suptitle("Where the fibre captures (parcels per case: results.csv)")
    plots.save(fig, path)
