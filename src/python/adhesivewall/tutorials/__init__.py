# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The post-processing of each tutorial (its Allrun.post calls it)."""
