# adhesiveWallInteraction | SPDX-License-Identifier: GPL-3.0-or-later
"""The post-processing of each tutorial (its Allrun.post calls it)."""


class NotThisCase(ValueError):
    """A case the tutorial's comparison does not apply to (one made from
    the tutorial, with other physics or outputs)."""


def stop(tutorial, error, needs):
    """The one-line stop of a tutorial's post-processing: the error, and
    for a case the comparison does not apply to, what it needs and what
    to use instead."""
    from ..foam import NotFixedSizes
    text = f"adhesiveWallPost {tutorial}: {error}"
    if isinstance(error, (NotThisCase, NotFixedSizes)):
        text += (f"\nThis comparison needs {needs}; in a case of your own, "
                 "leave it out of Allrun.post and use adhesiveWallPost "
                 "gradeEfficiency or sizeClasses")
    return SystemExit(text)
