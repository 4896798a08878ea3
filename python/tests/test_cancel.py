"""Ctrl+C at many instants (issue 31): study, refinement, conservation, stability scan and sweep.

Each call is interrupted (KeyboardInterrupt through _thread.interrupt_main, which is how Python
delivers Ctrl+C to the main thread) after a delay from 0 to 0.4 s; each call is sized to take a
few tenths of a second here, so that the interrupt lands before, inside (the module looks at
pending signals every 50 ms of work) and after the computation. Whatever instant it lands
on: no crash, the outputs all or none (the old files byte-identical, or - when the interrupt
came after the commit - the complete new files, equal to an uninterrupted call's), no temporary
file left in the folder, and the next call gives the uninterrupted result again. The sweep is
interrupted deterministically too: from its progress callback after every number of runs.
"""
import _thread
import os
import threading

import pytest

import elasticlab as el

DELAYS = [0.0, 0.005, 0.02, 0.05, 0.1, 0.15, 0.25, 0.4]


def interrupted_after(delay, call):
    """Runs call() while another thread interrupts the main thread after `delay` seconds.
    Returns (result or None, interrupted). A late interrupt (after call returned) is absorbed
    here and counted as not interrupted: the call had finished."""
    done = threading.Event()
    fired = threading.Event()

    def fire():
        if not done.wait(delay):
            fired.set()
            _thread.interrupt_main()

    t = threading.Thread(target=fire, daemon=True)
    result, interrupted = None, False
    try:
        try:
            t.start()  # the interrupt may come at once: inside the try
            result = call()
        finally:
            done.set()
            t.join()
        # An interrupt fired just as the call returned arrives at the next bytecodes: wait for it.
        if fired.is_set():
            for _ in range(1000):
                threading.Event().wait(0.001)
    except KeyboardInterrupt:
        interrupted = result is None
    return result, interrupted


def folder(path):
    return sorted(os.listdir(path))


def without_wall_columns(text):
    lines = text.splitlines()
    if not lines:
        return lines
    header = lines[0].split(",")
    keep = [i for i, name in enumerate(header) if "wall" not in name]
    return [",".join(f for i, f in enumerate(line.split(",")) if i in keep) for line in lines]


CALLS = {
    "study": lambda csv: el.study("ring2d", integrators=["euler", "rk4"], dts=[0.0005, 0.00025], duration=0.4,
                                  csv=csv),
    "refinement": lambda csv: el.refinement("ring2d", levels=[24, 48, 96], duration=0.4, gravity=0.0, csv=csv),
    "conservation": lambda csv: el.conservation("spring1d", integrators=["verlet", "rk4"], periods=5000, dt=0.01,
                                                csv=csv),
    "stability": lambda csv: el.stability("ring2d", integrators=["euler", "rk4"], duration=1.5, particles=64,
                                          ks=20000, csv=csv),
}


@pytest.mark.parametrize("what", sorted(CALLS))
def test_ctrl_c_anywhere_leaves_all_or_none(tmp_path, what):
    call = CALLS[what]
    clean = tmp_path / "clean.csv"
    call(clean)
    expected = without_wall_columns(clean.read_text())
    work = tmp_path / "work"
    work.mkdir()
    target = work / "out.csv"
    interrupts = 0
    for delay in DELAYS:
        target.write_text("the last table\n")
        result, interrupted = interrupted_after(delay, lambda: call(target))
        assert folder(work) == ["out.csv"], (delay, folder(work))  # no temporary left behind
        text = target.read_text()
        if interrupted:
            interrupts += 1
            # All or none: the old bytes, or (interrupted after the commit) the whole new table.
            assert text == "the last table\n" or without_wall_columns(text) == expected, (delay, text)
        else:
            assert result is not None
            assert without_wall_columns(text) == expected, delay
    assert interrupts >= 1  # at 0 s the interrupt lands inside the call
    # The call after all those interrupts gives the uninterrupted table again.
    call(target)
    assert without_wall_columns(target.read_text()) == expected


SWEEP = dict(grid={"ks": [400, 800, 1600], "pressure": [10, 20]}, duration=0.3, particles=8)


def test_ctrl_c_from_the_sweeps_progress_after_every_run():
    full = el.sweep("ring2d", progress=False, **SWEEP)
    assert len(full) == 6 and (full["status"] == "ok").all()

    for k in range(0, len(full)):
        calls = []

        def progress(done, total):
            calls.append(done)
            if len(calls) == k:
                raise KeyboardInterrupt

        if k == 0:
            df = el.sweep("ring2d", progress=progress, **SWEEP)  # never raises
            assert len(calls) == len(full)
        else:
            with pytest.raises(KeyboardInterrupt):
                el.sweep("ring2d", progress=progress, **SWEEP)
            assert len(calls) == k
        # The next sweep is whole and equal to the first (wall times aside).
        df = el.sweep("ring2d", progress=False, **SWEEP)
        cols = [c for c in full.columns if c != "wall_seconds"]
        assert df[cols].equals(full[cols])


def test_ctrl_c_inside_a_sweep_run():
    long_runs = dict(SWEEP, duration=3.0)  # a few tenths of a second: the interrupt lands inside runs
    full = el.sweep("ring2d", progress=False, **long_runs)
    cols = [c for c in full.columns if c != "wall_seconds"]
    interrupts = 0
    for delay in DELAYS:
        df, interrupted = interrupted_after(delay, lambda: el.sweep("ring2d", progress=False, **long_runs))
        if interrupted:
            interrupts += 1
        else:
            assert df[cols].equals(full[cols])
    assert interrupts >= 1
    assert el.sweep("ring2d", progress=False, **long_runs)[cols].equals(full[cols])
