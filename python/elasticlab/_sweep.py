"""Parameter sweeps: a grid of runs as one call, returning a pandas DataFrame.

The grid's points, each point's run and its metrics are simlab's (the CLI's ``sweep`` runs the
same code): a point is a pure function of the plan and its index, so the table is the same
whichever executor runs it (wall times aside), in grid order. docs/sweeps.md has the recipes.
"""

from __future__ import annotations

import numbers
import os
from dataclasses import dataclass
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core

__all__ = ["sweep", "SweepItem", "run_item", "run_items", "linear", "log", "decades", "uniform", "loguniform", "integers"]


# --- values --------------------------------------------------------------------------------------

def linear(start: float, stop: float, num: int) -> np.ndarray:
    """`num` values from `start` to `stop`, evenly spaced, both ends included (like numpy.linspace)."""
    return np.array(_core._sweep_range("linear", start, stop, num))


def log(start: float, stop: float, num: int) -> np.ndarray:
    """`num` values from `start` to `stop` (both > 0) evenly spaced in log, both ends exact
    (like numpy.geomspace)."""
    return np.array(_core._sweep_range("log", start, stop, num))


def decades(start: float, stop: float, per_decade: int) -> np.ndarray:
    """`per_decade` values per decade from `start` up to `stop` (both > 0): start * 10**(i/per_decade);
    the decades themselves exact (decades(100, 1e4, 2) is 100, 316.2..., 1000, 3162.2..., 10000)."""
    return np.array(_core._sweep_range("decades", start, stop, per_decade))


@dataclass(frozen=True)
class _Distribution:
    kind: str
    low: float
    high: float

    def draw(self, rng: np.random.Generator, n: int) -> list:
        if self.kind == "uniform":
            return list(rng.uniform(self.low, self.high, n))
        if self.kind == "loguniform":
            return list(np.exp(rng.uniform(np.log(self.low), np.log(self.high), n)))
        return [float(v) for v in rng.integers(int(self.low), int(self.high), n, endpoint=True)]


def uniform(low: float, high: float) -> _Distribution:
    """For random samples (``sweep(..., samples=N, seed=S)``): uniform in [low, high)."""
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        raise ValueError(f"uniform({low!r}, {high!r}): expected finite low < high")
    return _Distribution("uniform", float(low), float(high))


def loguniform(low: float, high: float) -> _Distribution:
    """For random samples: log-uniform in [low, high), both > 0 (a stiffness over decades)."""
    if not (np.isfinite(low) and np.isfinite(high) and 0 < low < high):
        raise ValueError(f"loguniform({low!r}, {high!r}): expected finite 0 < low < high")
    return _Distribution("loguniform", float(low), float(high))


def integers(low: int, high: int) -> _Distribution:
    """For random samples: whole numbers from low to high, both included (particles, subdivisions)."""
    if int(low) != low or int(high) != high or not low <= high:
        raise ValueError(f"integers({low!r}, {high!r}): expected whole numbers low <= high")
    return _Distribution("integers", float(low), float(high))


# --- the items a worker runs -------------------------------------------------------------------------

@dataclass(frozen=True)
class SweepItem:
    """One point of a sweep: the checked plan (its text, which embeds the scene file) and the
    point's index. Pickles, so process pools and Dask workers take it."""
    plan: str
    index: int


def run_item(item: SweepItem) -> tuple:
    """Runs one point (in whichever process gets it): its row, in the plan's column order."""
    return _core._sweep_run(item.plan, item.index)


def run_items(items: Sequence[SweepItem]) -> list:
    """Runs several points, one after the other: a task that packs many short runs."""
    return [run_item(item) for item in items]


def _workers(executor: Any) -> int:
    """How many points the executor runs at once, as far as can be told."""
    if _is_dask_client(executor):
        return max(1, sum(executor.nthreads().values()))
    for attribute in ("_max_workers", "_processes"):  # concurrent.futures, multiprocessing.Pool
        if isinstance(getattr(executor, attribute, None), int):
            return max(1, getattr(executor, attribute))
    return os.cpu_count() or 1


# --- the sweep ---------------------------------------------------------------------------------------

def _grid(grid: Optional[Mapping[str, Any]], samples: Optional[int], seed: Optional[int]):
    grid = dict(grid or {})
    keys = [str(k) for k in grid]
    if samples is None:
        axes = []
        for key, values in grid.items():
            if isinstance(values, _Distribution):
                raise ValueError(f"grid: {key} is a distribution; give samples= (and seed=) for random samples, "
                                 "or a list of values")
            if isinstance(values, (str, numbers.Number)):
                values = [values]
            axes.append([v.item() if isinstance(v, np.generic) else v for v in values])
        return keys, axes, None, None
    if isinstance(samples, bool) or int(samples) != samples or not 1 <= samples <= 10_000_000:
        raise ValueError(f"samples = {samples!r} is out of range; allowed whole numbers in [1, 10000000]")
    if seed is None:
        seed = int(np.random.SeedSequence().entropy % (2**63))
    rng = np.random.default_rng(seed)
    columns = []
    for key, values in grid.items():
        if isinstance(values, _Distribution):
            columns.append(values.draw(rng, int(samples)))
        else:  # a list: each point picks one of its values
            values = [values] if isinstance(values, (str, numbers.Number)) else list(values)
            if not values:
                raise ValueError(f"grid: {key} has no values")
            columns.append([values[i] for i in rng.integers(0, len(values), int(samples))])
    points = [list(p) for p in zip(*columns)] if columns else [[] for _ in range(int(samples))]
    return keys, None, [[v.item() if isinstance(v, np.generic) else v for v in p] for p in points], seed


def _is_dask_client(executor: Any) -> bool:
    return type(executor).__module__.split(".")[0] == "distributed" and hasattr(executor, "gather")


def _progress_bar(total: int, progress):
    if progress is False or progress is None:
        return None
    if callable(progress):
        class Call:
            done = 0

            def update(self, n: int = 1) -> None:
                self.done += n
                progress(self.done, total)

            def close(self) -> None:
                pass
        return Call()
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="run", desc="sweep")


def _execute(items: list, executor: Any, progress, chunk: Optional[int]) -> list:
    bar = _progress_bar(len(items), progress)
    tick = bar.update if bar is not None else (lambda n=1: None)
    try:
        if executor is None:
            rows = []
            for item in items:
                rows.append(run_item(item))
                tick()
            return rows
        if not _is_dask_client(executor) and not hasattr(executor, "map"):
            raise TypeError("executor: expected None, something with a map method (concurrent.futures, "
                            "multiprocessing, joblib's loky) or a dask.distributed.Client")
        # Tasks of `chunk` points each: by default about four tasks per worker, so that a task's
        # overhead (scheduling, pickling, a round trip) is paid per chunk, not per short run,
        # while the workers still share the load evenly.
        if chunk is None:
            chunk = max(1, len(items) // (4 * _workers(executor)))
        chunks = [items[i:i + chunk] for i in range(0, len(items), chunk)]
        rows = []
        if _is_dask_client(executor):
            from distributed import as_completed
            futures = executor.map(run_items, chunks, pure=False)
            sizes = {future.key: len(part) for future, part in zip(futures, chunks)}
            for future in as_completed(futures):
                tick(sizes[future.key])
            for part in executor.gather(futures):
                rows.extend(part)
            return rows
        for part in executor.map(run_items, chunks):
            rows.extend(part)
            tick(len(part))
        return rows
    finally:
        if bar is not None:
            bar.close()


def sweep(scene: Union[str, Any], grid: Optional[Mapping[str, Any]] = None, *, duration: float,
          integrator: Optional[str] = None, metrics: Optional[Sequence[str]] = None, executor: Any = None,
          samples: Optional[int] = None, seed: Optional[int] = None, max_steps: Optional[float] = None,
          rtol: Optional[float] = None, atol: Optional[float] = None, min_step: Optional[float] = None,
          max_step: Optional[float] = None, fixed_step: Optional[bool] = None,
          error_estimate: Optional[bool] = None, newton: Optional[int] = None,
          cg_tolerance: Optional[float] = None, cg_max_iterations: Optional[int] = None,
          options: Optional[Mapping[str, Any]] = None, chunk: Optional[int] = None,
          progress: Union[bool, Callable[[int, int], Any], None] = True, **fixed: Any):
    """Runs a grid of simulations and returns a pandas DataFrame, one row per run.

    Parameters
    ----------
    scene : str or path
        A built-in scene or a scene file (.json; every run starts from its state).
    grid : dict
        Parameter key -> values: a list (the runs are the Cartesian product, the first key varying
        slowest), ``linear(a, b, n)``, ``log(a, b, n)``, ``decades(a, b, k)``; a choice by name
        (``contact=["force", "projection"]``). With ``samples``: ``uniform(a, b)``,
        ``loguniform(a, b)``, ``integers(a, b)`` or a list to pick from.
    duration : float
        Simulated time of each run [s].
    integrator : str, optional
        The method (default: the scene file's, else rk4).
    metrics : list of str, optional
        The metric columns (default: every one the scene has; docs/sweeps.md lists them with units).
    executor : optional
        None (this process), anything with a ``map`` (concurrent.futures, multiprocessing,
        joblib's loky executor) or a ``dask.distributed.Client``. The table is the same.
    samples, seed : int, optional
        Random samples instead of the product: `samples` points drawn with numpy's generator from
        `seed` (None: a fresh seed, kept in ``df.attrs["seed"]``).
    max_steps : float, optional
        A run needing more steps is "over budget" (not run, or stopped there). Default 1e8.
    rtol, atol, min_step, max_step, fixed_step, error_estimate, newton, cg_tolerance, cg_max_iterations, options
        Integrator options, as for Simulation.
    chunk : int, optional
        Points per task sent to the executor (default: about four tasks per worker); the table
        does not depend on it.
    progress : bool or callable
        True: a tqdm bar where tqdm is installed (a widget in a notebook); a callable gets
        ``(done, total)`` after each run; False: nothing.
    **fixed
        Parameters held fixed for every run (``subdivisions=2``, ``dt=0.002`` [s]).

    Returns
    -------
    pandas.DataFrame
        Columns: ``index`` (the point's place in the grid), the grid's keys, ``integrator``,
        ``status`` ("ok", "failed", "over budget"), ``reason`` (why not ok; "" when ok), the
        metrics, ``version``. ``df.attrs`` holds the scene, duration, grid and seed.

    Raises
    ------
    ValueError
        For any bad key, value, metric or option, with the CLI's message, before anything runs.
    """
    import pandas as pd

    keys, axes, points, used_seed = _grid(grid, samples, seed)
    opts = _options(options, rtol=rtol, atol=atol, min_step=min_step, max_step=max_step, fixed_step=fixed_step,
                    error_estimate=error_estimate, newton=newton, cg_tolerance=cg_tolerance,
                    cg_max_iterations=cg_max_iterations)
    plan, columns, count = _core._sweep_plan(scene, keys, axes, points, duration, integrator, opts,
                                             None if metrics is None else list(metrics), max_steps, **fixed)
    if chunk is not None and (isinstance(chunk, bool) or int(chunk) != chunk or chunk < 1):
        raise ValueError(f"chunk = {chunk!r} is out of range; allowed whole numbers >= 1")
    rows = _execute([SweepItem(plan, i) for i in range(count)], executor, progress, chunk)
    df = pd.DataFrame.from_records(list(rows), columns=columns)
    for name in ("steps", "force_evals"):
        if name in df and df[name].notna().all():
            df[name] = df[name].astype("int64")
    df.attrs.update(scene=str(scene), duration=float(duration), grid={k: list(v) for k, v in zip(keys, axes)}
                    if axes is not None else {}, samples=samples, seed=used_seed)
    return df


def _options(options, **keywords):
    from . import integrator_options
    return integrator_options(options, **keywords)
