"""Runs over a grid of cases, shared by the skid map and the vibration data sets: a journal
of finished cases (one JSON line each, appended as they arrive, so an interrupted grid keeps
what it has), a folder that remembers the inputs its cases came from (a resume with other
inputs is refused), and the cases run in local processes or on a Dask cluster.
"""
from __future__ import annotations

import atexit
import gc
import json
import math
import multiprocessing
import os
import pickle
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

__all__ = ["grid_values", "guard_folder", "read_journal", "check_picklable", "CaseRunner", "run_cases",
           "skip_final_collection"]


def grid_values(name: str, values, low: float | None = 0.0, strict: bool = False, hint: str = "") -> list:
    """The sequence ``values`` as floats, refused by ``name`` unless each is finite and >= ``low``
    (> with ``strict``; ``low`` None: any finite number) and there is one at least; ``hint`` is
    added to the message."""
    values = list(values)
    bad = [v for v in values if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v)
           or (low is not None and (v <= low if strict else v < low))]
    if bad or not values:
        bound = "" if low is None else f" and {'>' if strict else '>='} {low:g}"
        raise ValueError(f"{name}: every value must be finite{bound}, got {bad[0] if bad else 'none'!r}{hint}")
    return [float(v) for v in values]


def guard_folder(folder: Path, record: dict, what: str, journal: str) -> None:
    """Record the inputs ``record`` in ``folder/inputs.json``; refuse a ``folder`` whose
    cases came from other inputs (a resume would serve results of another bearing, oil, law,
    surface or option), or whose ``journal`` has no record of its inputs."""
    path = folder / "inputs.json"
    if path.exists():
        try:
            old = json.loads(path.read_text())
        except json.JSONDecodeError:
            old = None
        if old != record:
            changed = sorted(k for k in set(record) | set(old or {}) if old is None or old.get(k) != record.get(k))
            raise ValueError(f"out: {folder} holds {what} computed from other inputs ({', '.join(changed)} "
                             "differ); use another --out folder or delete it")
    elif (folder / journal).exists():
        raise ValueError(f"out: {folder} holds {what} with no record of its inputs (an older version); "
                         "use another --out folder or delete it")
    else:
        path.write_text(json.dumps(record, indent=1))


def read_journal(path: Path, make) -> dict:
    """{key: case} of the finished cases in the journal ``path``: ``make`` turns a line's dict
    into a case with ``key`` and ``error``; a failed case (``error`` set) is left to run again,
    a line cut by an interruption skipped."""
    done = {}
    if path.exists():
        for line in path.read_text().splitlines():
            if line.strip():
                try:
                    case = make(json.loads(line))
                except (json.JSONDecodeError, TypeError):
                    continue
                if case.error is None:
                    done[case.key] = case
                else:
                    done.pop(case.key, None)
    return done


def check_picklable(registered, workers: int | None, client) -> None:
    """Refuse registered contact terms (``contact.terms.register_term``) that worker processes
    (a Dask ``client``, or more than one of ``workers``, default the CPU count) cannot receive."""
    if registered and (client is not None or (workers or os.cpu_count() or 1) > 1):
        try:
            pickle.dumps(registered)
        except Exception as err:  # noqa: BLE001 - any pickling failure
            raise ValueError(f"registered terms {[n for n, _ in registered]}: the worker processes need "
                             f"them picklable (numba functions at a module's top level): {err}") from None


def skip_final_collection() -> None:
    """Let this process exit without the interpreter's last garbage collection: it walks every
    object numba and Exudyn created (0.2–0.4 s) to free memory the process is about to hand
    back anyway. Objects still alive are frozen (``gc.freeze``), so one kept alive only by a
    reference cycle is not finalized: call it when everything the process wrote is closed
    (the commands write their files in ``with`` blocks; the interpreter still flushes the
    standard streams)."""
    gc.freeze()


def one_thread_per_worker():
    """Pool initializer: the cases already run in parallel processes, so each keeps its
    contact kernels on one thread (more threads than cores slow every process down); a
    worker exits without the last garbage collection (:func:`skip_final_collection`), which
    the pool's shutdown would wait for."""
    import numba

    numba.set_num_threads(1)
    atexit.register(skip_final_collection)


class CaseRunner:
    """Runs batches of cases on a Dask ``client``, else in ``workers`` local processes
    (default: the CPU count; 1: in this process) that stay up for every batch until the
    runner closes (a ``with`` block): a second batch (the skid map's thresholds after its
    points) finds its workers imported and their kernels loaded."""

    def __init__(self, workers: int | None = None, client=None):
        self.client, self.workers = client, workers or os.cpu_count() or 1
        self._pool = None

    def __enter__(self) -> "CaseRunner":
        return self

    def __exit__(self, kind, *exc) -> None:
        self.close(cancel=kind is not None)

    def close(self, cancel: bool = False) -> None:
        """Shut the local worker processes down; ``cancel``: the jobs not yet started with
        them (an error or an interrupt stops the batch without running the rest)."""
        if self._pool is not None:
            pool, self._pool = self._pool, None
            pool.shutdown(cancel_futures=cancel)

    def run(self, worker, jobs: list, record) -> None:
        """``record(worker(job))`` for every job as it finishes. ``worker`` must be importable
        at a module's top level; one that raises stops the batch with its error (the skid map's
        and data set's workers report a failed case instead)."""
        if self.client is not None:
            from dask.distributed import as_completed as dask_completed

            for fut in dask_completed(self.client.map(worker, jobs, pure=False)):
                record(fut.result())
            return
        if not jobs:
            return
        if self.workers == 1:
            for job in jobs:
                record(worker(job))
            return
        if self._pool is None:
            # spawned, not forked: a process that has run the compiled contacts holds GNU OpenMP
            # threads, and forking it aborts the child; started as jobs need them, idle ones reused
            self._pool = ProcessPoolExecutor(max_workers=self.workers,
                                             mp_context=multiprocessing.get_context("spawn"),
                                             initializer=one_thread_per_worker)
        try:
            for fut in as_completed([self._pool.submit(worker, job) for job in jobs]):
                record(fut.result())
        except BrokenProcessPool:  # a worker died: the next batch gets fresh ones
            self.close(cancel=True)
            raise


def run_cases(worker, jobs: list, record, workers: int | None = None, client=None) -> None:
    """``record(worker(job))`` for every job as it finishes, by a :class:`CaseRunner` of
    ``workers`` and ``client`` for this batch alone."""
    with CaseRunner(workers, client) as runner:
        runner.run(worker, jobs, record)
