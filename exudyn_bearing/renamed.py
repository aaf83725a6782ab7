"""Inputs renamed in session 17 so that every function uses the builder's words
(``axialForce`` / ``axial_force``, ``radialForce`` / ``radial_force``, ``ballDrag`` /
``ball_drag``): the old keyword still works for now, with a FutureWarning."""
from __future__ import annotations

import functools
import warnings

__all__ = ["RENAMED_INPUTS", "accepts_old_names"]

#: old keyword -> its name since session 17
RENAMED_INPUTS = {"axial": "axial_force", "radial": "radial_force", "drag": "ball_drag"}


def accepts_old_names(func):
    """Let ``func`` take the keywords of :data:`RENAMED_INPUTS` under their old names, with a
    FutureWarning naming the new one; both names at once is a TypeError."""
    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        for old, new in RENAMED_INPUTS.items():
            if old in kwargs:
                if new in kwargs:
                    raise TypeError(f"{func.__name__}() got both {old}= and {new}= (the same input)")
                warnings.warn(f"{func.__name__}({old}=...) is now {func.__name__}({new}=...); the old name will "
                              "be removed", FutureWarning, stacklevel=2)
                kwargs[new] = kwargs.pop(old)
        return func(*args, **kwargs)

    return wrapper
