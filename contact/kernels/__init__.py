"""The contact physics compiled with numba: a whole bearing's contact forces in one pass.

The numpy functions of :mod:`contact` compute the same equations on arrays; these kernels
compute them contact by contact, without per-call array overhead (a 16-ball bearing's
right-hand side spent ~1 ms of its ~1.7 ms in numpy bookkeeping on arrays of 32 rows).
Laws that exist once for both paths (the per-contact terms of :mod:`contact.terms`) are
called from here; the others are checked against the numpy path by ``tests/test_compiled.py``.

* :mod:`.records` — the typed records the kernels take (geometry, law, tables, states);
* :mod:`.float32` — vectorizable float32 exp, log and tanh;
* :mod:`.crook` — the Crook traction by the fast rule (MODEL.md §6, §6a, §6b);
* :mod:`.race` — ball–race contacts of B states (MODEL.md §2–§6);
* :mod:`.cage` — cage, ball drag, pocket friction, guiding land (MODEL.md §1, §8, §11d).

Everything is in one global frame and SI units.
"""
from __future__ import annotations

import os
from pathlib import Path

# GNU OpenMP threads (numba's parallel layer) spin ~300 000 times while they wait for work;
# when other processes share the cores (a skid map, a second run) the spinning threads take
# their CPU. Two runs side by side on 2 cores, 0.02 s simulated each: 10.5-11.7 s with that
# default, 1.9-2.0 s with a spin count of 3000 (alone: 1.30 vs 1.2 s). Must be set before the
# OpenMP runtime loads; a user's own OMP_WAIT_POLICY or GOMP_SPINCOUNT wins.
if "OMP_WAIT_POLICY" not in os.environ:
    os.environ.setdefault("GOMP_SPINCOUNT", "3000")

from ..kernel_cache import drop_stale  # noqa: E402

# the kernels call and inline functions of other modules (contact/*.py, this package): numba's
# cache is per file, so drop a module's cache when any contact source changed
SOURCES = sorted([*Path(__file__).parent.parent.glob("*.py"), *Path(__file__).parent.glob("*.py")])
drop_stale(Path(__file__).parent.glob("*.py"), SOURCES)

from .cage import cage_and_drag, land_forces, pocket_friction  # noqa: E402
from .crook import crook_fast, crook_one, crook_tables  # noqa: E402
from .race import race_contacts, race_contacts_parallel, rotation_matrices  # noqa: E402
from .records import (BallStates, BodyStates, CageRecord, ContactOutputs, CrookTables, LawRecord,  # noqa: E402
                      RaceFrames, RaceGeometry, law_record, traction_record)

__all__ = ["crook_fast", "crook_one", "crook_tables", "race_contacts", "race_contacts_parallel", "cage_and_drag",
           "land_forces", "pocket_friction", "rotation_matrices", "BallStates", "BodyStates", "CageRecord",
           "ContactOutputs", "CrookTables", "LawRecord", "RaceFrames", "RaceGeometry", "law_record",
           "traction_record"]
