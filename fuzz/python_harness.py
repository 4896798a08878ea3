"""The Python entry under a fuzzer (issue 31): fuzz/fuzz_python.cpp embeds the interpreter with the
module compiled in and calls fuzz_one(data) for every input.

The bytes choose a call of the package (its public functions and classes, through their Python
wrappers and the front door behind them) and its arguments: a scene, then keyword arguments whose
names come from the package's own vocabulary (every parameter key, every keyword of the API) or
from the bytes, and whose values are hostile ones (0, -1, nan, inf, 1e308, 2**63, '', 300 bytes,
escape sequences, None, lists, dicts, the scratch folder's special files) or numbers and text
taken from the bytes. A call that is accepted runs for at most ~0.2 s: a watchdog thread then
delivers Ctrl+C (the module looks at pending signals every 50 ms of work).

A finding (AssertionError, which the driver turns into a crash) is: an exception other than
ValueError, TypeError, RuntimeError, KeyboardInterrupt or SimulationFailed; a message with a
control byte or longer than 2,000 characters; a temporary file left in the scratch folder.
Files are only ever written in the scratch folder (the current directory; a name with '/' is
replaced), never elsewhere.
"""
import _thread
import math
import os
import signal
import struct
import tempfile
import threading

import elasticlab as el
import pandas  # noqa: F401  (imported here: a Ctrl+C from the watchdog must not land in its first import)

# Python's own Ctrl+C handler: the program that embeds the interpreter (libFuzzer) installed its
# own before Python started, and Python then leaves SIGINT without a Python handler, so that an
# interrupt_main() would only print "Signal 2 ignored due to race condition".
signal.signal(signal.SIGINT, signal.default_int_handler)

SCRATCH = tempfile.mkdtemp(prefix="elastic-lab-fuzz-py-")
os.chdir(SCRATCH)
os.mkdir("dir.json")
os.mkfifo("fifo.json")
with open("scene.json", "w") as f:
    f.write('{"format": "elastic-lab-scene", "version": 3, "scene": "ring2d", "integrator": "rk4", '
            '"parameters": {"ks": 100, "dt": 0.001}}')
BASELINE = sorted(os.listdir("."))

SCENES = el.scenes() + ["scene.json", "dir.json", "fifo.json", "nope", "", "two-balloons"]
KEYS = sorted({p["key"] for s in el.scenes() for p in el.parameters(s)} | {
    "integrators", "integrator", "dts", "tolerances", "duration", "repeat", "reference", "samples", "fixed_step",
    "time_budget", "precision", "compensated", "csv", "timings", "plot", "title", "levels", "key", "tolerance",
    "interval", "temporal_runs", "periods", "dt", "perturb", "hmin", "hmax", "grid", "metrics", "max_steps",
    "seed", "options", "rtol", "atol", "min_step", "max_step", "error_estimate", "newton", "cg_tolerance",
    "cg_max_iterations", "every", "t_eval", "every_steps", "progress", "xlsx", "executor", "chunk", "bodies"})
VALUES = [0, 1, -1, 2, 3, 0.5, 1e-3, 1e-300, 1e308, -1e308, math.nan, math.inf, -math.inf, 2 ** 63, 2 ** 31, True, False,
          None, "", "x" * 300, "\x1b]0;title\x07\x1b[2J", "rk4", "euler", "rk45", "cvode-bdf", "particles", "ks",
          "out.csv", "scene.json", "dir.json", "fifo.json", "exact", "float", [], [0.01], [0.01, 0.005], [1e-300],
          ["rk4"], ["rk4", "rk4"], ["euler", "rk4"], [12, 24], [12], [True], {"ks": [100, 200]}, {"ks": []},
          {"": 1}, {"atol": -1}, b"\x00", object()]
FUNCTIONS = ["Simulation", "run", "step", "study", "refinement", "conservation", "stability", "sweep", "World",
             "parameters", "integrator_options", "save"]
ALLOWED = (ValueError, TypeError, RuntimeError, KeyboardInterrupt, el.SimulationFailed)


class Bytes:
    def __init__(self, data):
        self.data, self.at = data, 0

    def byte(self):
        if self.at >= len(self.data):
            return 0
        self.at += 1
        return self.data[self.at - 1]

    def pick(self, seq):
        return seq[self.byte() % len(seq)]

    def value(self):
        kind = self.byte() % 8
        if kind == 0 and self.at + 8 <= len(self.data):
            self.at += 8
            return struct.unpack("<d", self.data[self.at - 8:self.at])[0]
        if kind == 1:
            n = self.byte() % 24
            self.at += n
            text = self.data[self.at - n:self.at].decode("utf-8", "replace")
            return text.replace("/", "_")  # never a path outside the scratch folder
        if kind == 2:
            return [self.value() for _ in range(self.byte() % 4)]
        if kind == 3:
            return int.from_bytes(bytes([self.byte(), self.byte()]), "little", signed=True)
        return self.pick(VALUES)

    def keywords(self):
        out = {}
        for _ in range(self.byte() % 7):
            key = self.pick(KEYS) if self.byte() % 8 else str(self.value())
            out[key] = self.value()
        return out


def inert(message):
    assert len(message) <= 2000, f"a message of {len(message)} characters"
    bad = [c for c in message if ord(c) < 0x20 and c != "\n" or ord(c) == 0x7f]
    assert not bad, f"control characters {bad!r} in {message[:300]!r}"


def guarded(call):
    """call() with Ctrl+C after 0.2 s; a late interrupt is absorbed here."""
    done, fired = threading.Event(), threading.Event()

    def fire():
        if not done.wait(0.2):
            fired.set()
            _thread.interrupt_main()

    t = threading.Thread(target=fire, daemon=True)
    try:
        try:
            t.start()
            return call()
        finally:
            done.set()
            t.join()
            if fired.is_set():
                for _ in range(100):
                    threading.Event().wait(0.001)
    except KeyboardInterrupt:
        return None


def one_call(b):
    what = b.pick(FUNCTIONS)
    scene = b.pick(SCENES) if b.byte() % 4 else b.value()
    kw = b.keywords()
    if what == "Simulation":
        return el.Simulation(scene, **kw)
    if what in ("run", "step", "save"):
        sim = el.Simulation(b.pick(el.scenes()), **({} if b.byte() % 2 else kw))
        if what == "run":
            return sim.run(b.value(), **b.keywords())
        if what == "step":
            return sim.step(b.value())
        return sim.save_scene(b.pick(["saved.json", "dir.json", "fifo.json", "", "scene.json"]))
    if what == "World":
        return el.World(scene, **kw)
    if what == "parameters":
        return el.parameters(scene)
    if what == "integrator_options":
        return el.integrator_options(kw.pop("options", None), **kw)
    function = getattr(el, what)
    if what == "sweep":
        kw.setdefault("duration", b.value())
        kw["progress"] = False
        kw.pop("executor", None)  # this process only
        return function(scene, kw.pop("grid", b.value()), **kw)
    return function(scene, **kw)


def fuzz_one(data: bytes) -> None:
    b = Bytes(data)
    try:
        guarded(lambda: one_call(b))
    except ALLOWED as e:
        inert(str(e))
    leftovers = [n for n in os.listdir(".") if n.startswith(".elastic-lab-") or ".tmp" in n]
    assert not leftovers, f"temporary files left: {leftovers}"
    # Outputs written by accepted calls are removed; the scratch folder's fixtures stay.
    for name in os.listdir("."):
        if name not in BASELINE:
            try:
                os.remove(name)
            except IsADirectoryError:
                os.rmdir(name)
