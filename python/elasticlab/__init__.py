"""Elastic Lab from Python: two-layer elastic bodies (particles, springs, gas pressure).

The physics is C++ (the compiled module ``elasticlab._core``, pybind11); this package gives it
the shape of numpy and scipy: real signatures, keywords for every option (``None`` for "off"),
results with named columns, pickling, and parameter sweeps returning a pandas DataFrame.

Units are SI throughout: seconds, metres, kilograms, newtons, joules. In 2D a "volume" is an
area [m^2] and a pressure a force per length [N/m]; in 3D they are [m^3] and [N/m^2].

>>> import elasticlab as el
>>> sim = el.Simulation("ring2d", integrator="rk45", rtol=1e-6, ks=900)
>>> r = sim.run(1.0, every=0.01)          # rows every 0.01 s of simulated time
>>> r["t"], r["volume_inner"]             # numpy arrays, one value per row

See docs/python.md and docs/sweeps.md.
"""

from __future__ import annotations

import functools
import os
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import SimulationFailed, WorldBody, __version__
from ._sweep import decades, integers, linear, log, loguniform, sweep, uniform

__all__ = [
    "Simulation", "World", "WorldBody", "SimulationFailed", "scenes", "world_scenes", "integrators", "parameters", "study", "refinement",
    "stability", "conservation", "sweep", "linear", "log", "decades", "uniform", "loguniform", "integers", "__version__",
]

PathLike = Union[str, "os.PathLike[str]"]


def _inert(text: str, limit: int = 1000) -> str:
    """A message as inert text: control characters as \\xNN, at most `limit` characters."""
    out = "".join(c if c.isprintable() or c == "\n" else f"\\x{ord(c):02x}" for c in text)
    return out if len(out) <= limit else out[:limit] + f"... ({len(text)} characters)"


def _door(function):
    """pybind11's TypeError for arguments of the wrong type echoes every argument whole and raw
    (a 5,000-character name, an escape sequence that retitles the terminal): that message is
    escaped and cut like every other message of the front door (issue 31)."""
    @functools.wraps(function)
    def checked(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            text = str(e)
            if _inert(text) == text:
                raise
            raise TypeError(_inert(text)) from None
    return checked

# The integrator options, as keywords of Simulation, set_integrator and sweep: name -> meaning.
# None (the default) leaves the method's own default.
INTEGRATOR_OPTIONS = {
    "rtol": "relative error tolerance of the adaptive methods (rk45, cvode-*)",
    "atol": "absolute error tolerance of the adaptive methods [m, m/s]",
    "min_step": "below this step the run fails instead of stalling (adaptive methods) [s]",
    "max_step": "the largest step an adaptive method may take [s]; None: no cap",
    "fixed_step": "run rk45 at the fixed step dt (order studies)",
    "error_estimate": "step doubling for fixed-step methods: fills error_estimate (costs about 3x)",
    "newton": "Newton iterations per step of implicit-euler (1: linearised once)",
    "cg_tolerance": "implicit-euler: relative residual of its conjugate-gradient solve",
    "cg_max_iterations": "implicit-euler: a solve needing more iterations fails the step",
}


def integrator_options(options: Optional[Mapping[str, Any]] = None, **keywords: Any) -> Optional[dict]:
    """The options dict the C++ side takes: `options` (a dict, as before) updated with every
    keyword that is not None; None when nothing is set."""
    merged = dict(options or {})
    for name, value in keywords.items():
        if value is not None:
            merged[name] = value
    return merged or None


def scenes() -> list[str]:
    """The built-in scene names (spring1d, ring2d, sphere3d, ...)."""
    return _core.scenes()


def world_scenes() -> list[str]:
    """The built-in scenes of several bodies (collide2d, collide3d, stack3d): ``World(name)``."""
    return _core.world_scenes()


def integrators() -> list[dict]:
    """The integrators: a dict per method with its name, order and description."""
    return _core.integrators()


def parameters(scene: str) -> list[dict]:
    """The parameter table of a built-in scene: a dict per key with unit, default, range,
    choices and meaning (the CLI's ``params``)."""
    return _core.parameters(scene)


class Simulation(_core.Simulation):
    """One body, its parameters, its integrator and its diagnostics.

    Parameters
    ----------
    scene : str or path
        A built-in scene (``scenes()``) or a scene file (.json), which resumes with its saved state.
    integrator : str, optional
        The method (``integrators()``); default the scene file's, else ``"rk4"``.
    rtol, atol, min_step, max_step, fixed_step, error_estimate, newton, cg_tolerance, cg_max_iterations
        Integrator options (see ``INTEGRATOR_OPTIONS``); None keeps the method's default.
    options : dict, optional
        The same options as a dict (the keywords win).
    threads : int, optional
        Threads for the force evaluation of large bodies (results do not depend on it).
    **parameters
        The scene's parameters by key, in its units (``ks=900`` [N/m], ``dt=0.002`` [s],
        ``contact="projection"``); checked by the table: ValueError with the CLI's message.

    A Simulation pickles (through the scene file format, state included): a copy goes on bit for
    bit. ``time`` and ``step_count`` may be read from another thread while one runs it.
    """

    __slots__ = ()

    @_door
    def __init__(self, scene: PathLike = "ring2d", *, integrator: Optional[str] = None,
                 rtol: Optional[float] = None, atol: Optional[float] = None, min_step: Optional[float] = None,
                 max_step: Optional[float] = None, fixed_step: Optional[bool] = None,
                 error_estimate: Optional[bool] = None, newton: Optional[int] = None,
                 cg_tolerance: Optional[float] = None, cg_max_iterations: Optional[int] = None,
                 options: Optional[Mapping[str, Any]] = None, threads: Optional[int] = None,
                 **parameters: Any) -> None:
        opts = integrator_options(options, rtol=rtol, atol=atol, min_step=min_step, max_step=max_step,
                                  fixed_step=fixed_step, error_estimate=error_estimate, newton=newton,
                                  cg_tolerance=cg_tolerance, cg_max_iterations=cg_max_iterations)
        super().__init__(scene, integrator=integrator, options=opts, threads=threads, **parameters)

    def __repr__(self) -> str:
        return super().__repr__()

    # --- running ---

    @_door
    def run(self, duration: float, *, every: Optional[float] = None, t_eval: Optional[Sequence[float]] = None,
            every_steps: Optional[int] = None,
            progress: Union[None, bool, Callable[[float], Any]] = None,
            csv: Optional[PathLike] = None, xlsx: Optional[PathLike] = None,
            csv_dialect: str = "plain", precision: str = "double") -> np.ndarray:
        """Runs for `duration` seconds of simulated time and returns the rows it sampled.

        Parameters
        ----------
        duration : float
            Simulated time to run [s] (whole steps: a fixed-step run ends at the first step at
            or past the end).
        every : float, optional
            Sample every so many seconds of simulated time [s]: rows at the start time t0,
            t0 + every, t0 + 2 every, ... and the end.
        t_eval : sequence of float, optional
            The simulated times to sample [s], ascending, within [time, time + duration].
        every_steps : int, optional
            A row every N steps instead (and the start and the end).
        progress : callable or bool, optional
            ``progress(t)`` is called with the simulated time [s] a few times a second while it
            runs; True shows a tqdm bar where tqdm is installed.
        csv, xlsx : path, optional
            Also write the sampled rows as the CLI's ``run --csv`` / ``run --xlsx`` files (its
            columns; the workbook with units in the header and charts of energy, volume and
            pressure against t). Without a sampling option a row is written every step, as the
            CLI's ``--every 1``, and the returned array holds the same rows. The files hold the
            run so far also when it fails.
        csv_dialect : str
            ``"plain"`` (comma, decimal point) or ``"excel-semicolon"`` (semicolon, decimal
            comma, CRLF, UTF-8 byte-order mark: spreadsheets in decimal-comma locales).
        precision : str
            ``"double"``, or ``"float"``: the float32 path steps the run (state and forces in
            float, the diagnostics measured in double; euler, midpoint, rk4, symplectic-euler and
            verlet; no contact: a run fails where a particle reaches a wall), with this
            simulation's threads (the same bits with any count), as the CLI's ``run --precision
            float``. Afterwards the simulation holds the float run's end state in double (a
            failed float run leaves it where it started). Other integrators: ValueError with the
            CLI's message.

        Returns
        -------
        numpy.ndarray
            A structured array, one row per sample (without any sampling option: the start and
            the end), a field per column of ``diagnostics_columns``: ``t`` [s], ``step``,
            ``dt`` [s], energies [J], volumes and pressures (scenes with gas), ...;
            ``error_estimate`` is NaN where the step had none. A row is the first step at or past
            its sample time; an adaptive method shortens its step to land on it exactly.

        Raises
        ------
        SimulationFailed
            When a step fails; its ``rows`` hold the samples up to the last good step.
        """
        if sum(x is not None for x in (every, t_eval, every_steps)) > 1:
            raise ValueError("give one of every (seconds), t_eval (times) and every_steps (steps)")
        start = self.time
        times: Optional[list] = None
        if every_steps is None:
            if every is not None:
                if isinstance(every, bool) or not np.isfinite(every) or not 0 < every <= 1e7:
                    raise ValueError(f"every = {every!r} is out of range; allowed (0, 1e+07] s")
                times = None  # built by the core after the front door has bounded the rows
            elif t_eval is not None:
                times = [float(t) for t in np.asarray(t_eval, dtype=float).ravel()]
                end = start + float(duration)
                if any(not np.isfinite(t) for t in times) or any(b <= a for a, b in zip(times, times[1:])):
                    raise ValueError("t_eval: expected finite times in ascending order [s]")
                if times and (times[0] < start - 1e-12 * max(1.0, abs(start)) or times[-1] > end * (1 + 1e-12) + 1e-12):
                    raise ValueError(f"t_eval: times must lie within [{start:g}, {end:g}] s, the run's span")
            elif csv is None and xlsx is None:
                times = [start]
            else:
                every_steps = 1  # files without a sampling option: every step, as the CLI's
        callback = _progress_callback(progress, start, float(duration) if np.isfinite(duration) else 0.0)
        try:
            table = super().run(duration, every=every_steps, times=times, progress=callback, csv=csv, xlsx=xlsx,
                                csv_dialect=csv_dialect, every_seconds=every, precision=precision)
        except SimulationFailed as e:
            if getattr(e, "rows", None) is not None:
                e.rows = self._named(e.rows)
            raise
        finally:
            if callback is not None and hasattr(callback, "close"):
                callback.close()
        return self._named(table)

    def _named(self, table: np.ndarray) -> np.ndarray:
        columns = self.diagnostics_columns
        dtype = [(c, np.int64 if c == "step" else np.float64) for c in columns]
        out = np.empty(table.shape[0], dtype=dtype)
        for i, c in enumerate(columns):
            out[c] = table[:, i]
        if "error_estimate" in columns:
            out["error_estimate"][out["error_estimate"] < 0] = np.nan  # none: NaN, not -1
        return out

    @_door
    def step(self, n: int = 1) -> None:
        """Takes `n` steps (SimulationFailed when one fails)."""
        super().step(n)

    def reset(self) -> None:
        """Back to the start state, same parameters and integrator."""
        super().reset()

    @_door
    def set_integrator(self, name: str, *, rtol: Optional[float] = None, atol: Optional[float] = None,
                       min_step: Optional[float] = None, max_step: Optional[float] = None,
                       fixed_step: Optional[bool] = None, error_estimate: Optional[bool] = None,
                       newton: Optional[int] = None, cg_tolerance: Optional[float] = None,
                       cg_max_iterations: Optional[int] = None,
                       options: Optional[Mapping[str, Any]] = None) -> None:
        """Changes the integrator between steps; options as in the constructor (added to the
        current ones)."""
        opts = integrator_options(options, rtol=rtol, atol=atol, min_step=min_step, max_step=max_step,
                                  fixed_step=fixed_step, error_estimate=error_estimate, newton=newton,
                                  cg_tolerance=cg_tolerance, cg_max_iterations=cg_max_iterations)
        super().set_integrator(name, opts)

    def exact(self) -> tuple[np.ndarray, np.ndarray]:
        """spring1d: the closed-form (positions [m], velocities [m/s]) at the current time, N x 3."""
        return super().exact()

    @_door
    def save_scene(self, path: PathLike) -> None:
        """Writes the scene, its parameters, integrator and exact state as a scene file (atomically)."""
        super().save_scene(path)

    @property
    def diagnostics(self) -> dict:
        """The diagnostics row as a dict (the CSV's names, SI units); error_estimate [m] is None
        when the last step had no estimate."""
        d = dict(super().diagnostics)
        if d.get("error_estimate", 0) < 0:
            d["error_estimate"] = None
        return d

    @property
    def diagnostics_row(self) -> np.ndarray:
        """The diagnostics row as an array (columns as diagnostics_columns); NaN for no error estimate."""
        row = np.array(super().diagnostics_row)
        columns = self.diagnostics_columns
        if "error_estimate" in columns and row[columns.index("error_estimate")] < 0:
            row[columns.index("error_estimate")] = np.nan
        return row

    @property
    def integrator_options(self) -> dict:
        """The integrator's options; max_step None when there is no cap."""
        o = dict(super().integrator_options)
        if o.get("max_step") == 0:
            o["max_step"] = None
        return o


class World(_core.World):
    """Several two-layer bodies in one box, stepped as one ODE by any integrator; they meet
    through a contact force between their outer layers (docs/model.md "Several bodies").

    Parameters
    ----------
    scene : str or path, optional
        A built-in scene of several bodies (``world_scenes()``: collide2d, collide3d, stack3d) or
        a scene file of several bodies (.json), which resumes with its saved state.
    bodies : list of dict, optional
        Instead of a scene: one dict per body, ``{"kind": "sphere3d", "position": (x, y, z) [m],
        "velocity": (vx, vy, vz) [m/s], "mass": 4, ...}`` (kind: ring2d, sphere3d or
        sphere3d-latlong; any body parameter by key). ValueError names the body: ``body2.mass``.
    set : list of str, optional
        ``["body2.mass=4", "offset=0.5"]``: the CLI's ``--set``, one body with a ``bodyN.`` prefix
        (bodies counted from 1).
    integrator, rtol, atol, ..., options
        As for Simulation.
    **parameters
        Set every body (``gravity=0``, ``ks=900``) or the scene (``offset=0.5``).

    ``bodies`` are views of each body (positions, velocities, parameters, diagnostics) that follow
    the world as it steps. A World pickles (scene file with state): a copy goes on bit for bit.
    """

    __slots__ = ()

    def __init__(self, scene: Optional[PathLike] = None, *, bodies: Optional[Sequence[Mapping[str, Any]]] = None,
                 set: Optional[Sequence[str]] = None, integrator: Optional[str] = None,
                 rtol: Optional[float] = None, atol: Optional[float] = None, min_step: Optional[float] = None,
                 max_step: Optional[float] = None, fixed_step: Optional[bool] = None,
                 error_estimate: Optional[bool] = None, newton: Optional[int] = None,
                 cg_tolerance: Optional[float] = None, cg_max_iterations: Optional[int] = None,
                 options: Optional[Mapping[str, Any]] = None, **parameters: Any) -> None:
        opts = integrator_options(options, rtol=rtol, atol=atol, min_step=min_step, max_step=max_step,
                                  fixed_step=fixed_step, error_estimate=error_estimate, newton=newton,
                                  cg_tolerance=cg_tolerance, cg_max_iterations=cg_max_iterations)
        if scene is None and bodies is None:
            raise ValueError("World needs a scene (" + ", ".join(_core.world_scenes()) + ", a .json file) or bodies=[...]")
        super().__init__(scene, bodies=None if bodies is None else [dict(b) for b in bodies],
                         set=None if set is None else list(set), integrator=integrator, options=opts, **parameters)

    def run(self, duration: float, *, every: Optional[float] = None, t_eval: Optional[Sequence[float]] = None,
            every_steps: Optional[int] = None,
            progress: Union[None, bool, Callable[[float], Any]] = None) -> np.ndarray:
        """As Simulation.run: a structured array of the sampled rows, a field per column of
        ``diagnostics_columns`` (the world's energies and ledger, per-body columns with the body
        number as suffix: ``com_x_2`` [m], ``volume_outer_1``, ...; ``momentum_x`` [kg m/s],
        ``min_gap`` [m])."""
        return _sampled_run(self, super().run, duration, every, t_eval, every_steps, progress)

    def _named(self, table: np.ndarray) -> np.ndarray:
        return Simulation._named(self, table)

    @property
    def diagnostics(self) -> dict:
        """The CSV row as a dict; error_estimate [m] is None when the last step had none."""
        d = dict(super().diagnostics)
        if d.get("error_estimate", 0) < 0:
            d["error_estimate"] = None
        return d


def _sampled_run(sim, run, duration, every, t_eval, every_steps, progress) -> np.ndarray:
    """World.run: the sample times from `t_eval` (or `every` seconds, turned into times by the
    core once the front door has bounded the rows), then the C++ run."""
    if sum(x is not None for x in (every, t_eval, every_steps)) > 1:
        raise ValueError("give one of every (seconds), t_eval (times) and every_steps (steps)")
    start = sim.time
    times: Optional[list] = None
    if every_steps is None:
        if every is not None:
            if isinstance(every, bool) or not np.isfinite(every) or not 0 < every <= 1e7:
                raise ValueError(f"every = {every!r} is out of range; allowed (0, 1e+07] s")
            times = None  # built by the core after the front door has bounded the rows
        elif t_eval is not None:
            times = [float(t) for t in np.asarray(t_eval, dtype=float).ravel()]
            end = start + float(duration)
            if any(not np.isfinite(t) for t in times) or any(b <= a for a, b in zip(times, times[1:])):
                raise ValueError("t_eval: expected finite times in ascending order [s]")
            if times and (times[0] < start - 1e-12 * max(1.0, abs(start)) or times[-1] > end * (1 + 1e-12) + 1e-12):
                raise ValueError(f"t_eval: times must lie within [{start:g}, {end:g}] s, the run's span")
        else:
            times = [start]
    callback = _progress_callback(progress, start, float(duration) if np.isfinite(duration) else 0.0)
    try:
        table = run(duration, every=every_steps, times=times, progress=callback, every_seconds=every)
    except SimulationFailed as e:
        if getattr(e, "rows", None) is not None:
            e.rows = sim._named(e.rows)
        raise
    finally:
        if callback is not None and hasattr(callback, "close"):
            callback.close()
    return sim._named(table)


def _progress_callback(progress, start: float, duration: float):
    if progress is None or progress is False:
        return None
    if callable(progress):
        return progress
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    bar = tqdm(total=duration, unit="s", desc="simulated", bar_format="{l_bar}{bar}| {n:.3g}/{total:.3g} s")

    class Bar:
        def __call__(self, t: float) -> None:
            bar.update(min(t - start, duration) - bar.n)

        def close(self) -> None:
            bar.close()

    return Bar()


@_door
def study(scene: PathLike, *, integrators: Sequence[str] = ("euler", "midpoint", "rk4"),
          dts: Optional[Sequence[float]] = None, tolerances: Optional[Sequence[float]] = None,
          duration: float = 2.0, repeat: int = 1, reference: str = "auto", samples: int = 20,
          fixed_step: bool = False, time_budget: float = 0.0, precision: Union[str, Sequence[str]] = ("double",),
          compensated: bool = False, csv: Optional[PathLike] = None, timings: Optional[PathLike] = None,
          plot: Optional[PathLike] = None, title: Optional[str] = None, **parameters: Any) -> dict:
    """Work-precision study (the CLI's ``study``): every integrator at every step `dts` [s] (or
    tolerance) over `duration` [s] against a reference, each point timed `repeat` times;
    returns ``{'rows': [dict per point: walls, wall_min/q1/median/q3 [s], error_final,
    error_max, error_rms, ...], 'orders', ...}``. ``time_budget`` [s]: a slower point is "not
    reached"; ``precision="float"`` runs the float32 path (euler, midpoint, rk4,
    symplectic-euler, verlet; for the 1D spring its float build, also the Yoshida methods),
    ``precision=("double", "float")`` both: the float curve flattens at the round-off floor;
    ``compensated`` Kahan-sums the 1D spring's float update. ``csv=``, ``timings=`` and
    ``plot=`` write the CLI's files. A scene of several bodies (``"collide2d"``, a world's scene
    file) is studied as one world: the errors over every particle of every body (double only);
    keywords set every body."""
    return _core.study(scene, integrators=list(integrators), dts=None if dts is None else list(dts),
                       tolerances=None if tolerances is None else list(tolerances), duration=duration,
                       repeat=repeat, reference=reference, samples=samples, fixed_step=fixed_step,
                       time_budget=time_budget,
                       precision=[precision] if isinstance(precision, str) else list(precision), compensated=compensated, csv=csv,
                       timings=timings, plot=plot, title=title, **parameters)


@_door
def refinement(scene: PathLike, *, levels: Sequence[int], key: Optional[str] = None, integrator: str = "rk4",
               tolerance: Optional[float] = None, duration: float = 1.0, interval: float = 0.01,
               temporal_runs: int = 4, fixed_step: bool = False, csv: Optional[PathLike] = None,
               plot: Optional[PathLike] = None, title: Optional[str] = None, **parameters: Any) -> dict:
    """Refinement study (the CLI's ``study --refine``): the same body at several resolutions
    (`levels` of `key`, the scene's own by default) against the finest, compared every
    `interval` [s] over `duration` [s]; ``dt=`` (a parameter, [s]) fixes the step. A scene of
    several bodies raises every body's resolution together (bodies of one kind)."""
    return _core.refinement(scene, levels=list(levels), key=key, integrator=integrator, tolerance=tolerance,
                            duration=duration, interval=interval, temporal_runs=temporal_runs,
                            fixed_step=fixed_step, csv=csv, plot=plot, title=title, **parameters)


@_door
def conservation(scene: PathLike, *, integrators: Sequence[str] = ("verlet", "yoshida4", "rk4"),
                 periods: float = 1000.0, dt: Optional[float] = None, samples: int = 120,
                 precision: str = "double", csv: Optional[PathLike] = None, plot: Optional[PathLike] = None,
                 title: Optional[str] = None) -> dict:
    """Long-time energy (the CLI's ``conservation``): the undamped scene for `periods` periods of
    its fastest mode at `dt` [s] (default: the scene's); per integrator the growth exponent alpha
    of |energy error| [J] against t [s] with its 95 % interval and its class (bounded,
    random-walk, drift). ``precision="float"`` runs the float build of the 1D spring."""
    return _core.conservation(scene, integrators=list(integrators), periods=periods, dt=dt, samples=samples,
                              precision=precision, csv=csv, plot=plot, title=title)


@_door
def stability(scene: PathLike, *, integrators: Sequence[str] = ("euler", "midpoint", "rk4", "symplectic-euler",
                                                               "verlet", "rk45", "implicit-euler"),
              duration: float = 2.0, perturb: float = 0.01, hmin: float = 1e-5, hmax: float = 1.0,
              csv: Optional[PathLike] = None, **parameters: Any) -> dict:
    """Stability scan (the CLI's ``stability``): the largest stable step [s] of each integrator,
    measured between `hmin` and `hmax` [s] over `duration` [s] from a start perturbed by
    `perturb` [m], beside the linear prediction. A scene of several bodies is scanned as one
    world: the prediction from the whole system's eigenvalues, the trials run every body;
    the result then has ``'bodies'``."""
    return _core.stability(scene, integrators=list(integrators), duration=duration, perturb=perturb, hmin=hmin,
                           hmax=hmax, csv=csv, **parameters)
