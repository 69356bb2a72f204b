# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""matplotlib without a display, one look for every tutorial's plots."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend)


def figure(width=9, height=6, rows=1, columns=1):
    """A figure of the size given [inch at 100 dpi] and its axes."""
    fig, axes = plt.subplots(rows, columns, figsize=(width, height),
                             squeeze=(rows * columns == 1))
    if rows * columns > 1:
        axes = axes.ravel()
        for ax in axes:
            ax.grid(True, alpha=0.4)
    else:
        axes.grid(True, alpha=0.4)
    return fig, axes


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def axes(ax, xlabel, ylabel, title, xlim=None, ylim=None, xlog=False):
    """Labels, title, limits and scale of a plot's axes."""
    if xlog:
        ax.set_xscale("log")
    if xlim:
        ax.set_xlim(*xlim)
    if ylim:
        ax.set_ylim(*ylim)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
