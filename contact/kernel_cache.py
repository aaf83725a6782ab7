"""Stale numba caches across modules (no numba import here).

numba's on-disk cache (``@njit(cache=True)``) is keyed on the source file of the function
itself: a cached kernel that calls (or inlines) a function from another file keeps the old
machine code of that callee after the callee's file changed — e.g. the glue's one-state
kernel (exudyn_bearing/model/compiled.py) kept the previous spring-chain cage of
contact/compiled.py and disagreed with the numpy path by 1.5 kN. :func:`drop_stale` removes
a module's cache files when any source it depends on changed since they were written.
"""
from __future__ import annotations

import hashlib
import os
from pathlib import Path

__all__ = ["drop_stale"]


def _cache_dirs(module_file: Path):
    dirs = [module_file.parent / "__pycache__"]
    user = os.environ.get("NUMBA_CACHE_DIR")
    if user:  # numba mirrors the source tree below it
        dirs += [p for p in Path(user).rglob("*") if p.is_dir() and p.name == module_file.parent.name]
    return dirs


def drop_stale(modules, sources) -> bool:
    """Delete the numba cache files (``<stem>.*.nbi``/``.nbc``) of ``modules`` (one module's
    path or several) when the digest of ``sources`` (paths) differs from the one recorded
    next to them; records the new digest. Returns True when caches were dropped. A
    read-only install is left alone."""
    modules = [Path(modules)] if isinstance(modules, (str, os.PathLike)) else [Path(m) for m in modules]
    digest = hashlib.sha256()
    for src in sorted(Path(s) for s in sources):
        digest.update(src.name.encode())
        digest.update(src.read_bytes())
    stamp_text = digest.hexdigest()
    dropped = False
    for module_file in modules:
        dropped |= _drop(module_file, stamp_text)
    return dropped


def _drop(module_file: Path, stamp_text: str) -> bool:
    stamp = module_file.parent / "__pycache__" / f"{module_file.stem}.kernels.sha256"
    try:
        if stamp.is_file() and stamp.read_text() == stamp_text:
            return False
        dropped = False
        for folder in _cache_dirs(module_file):
            for pattern in (f"{module_file.stem}.*.nbi", f"{module_file.stem}.*.nbc"):
                for path in folder.glob(pattern):
                    path.unlink()
                    dropped = True
        stamp.parent.mkdir(exist_ok=True)
        stamp.write_text(stamp_text)
        return dropped
    except OSError:
        return False
