#!/usr/bin/env python3
"""A work-precision diagram of the 1D spring from Python (docs/python.md).

The study is the CLI's `study` (simlab/study.h): every integrator at several steps (rk45 at
several tolerances) against the closed-form solution, its error against the run time (the
median of 5 timed runs, with a band from the first to the third quartile) and against the force
evaluations it cost (machine-independent). The same rows could be written as the CLI's CSV and
SVG (csv=, plot=); here matplotlib draws them.

    PYTHONPATH=build/release/python python3 docs/examples/work_precision.py [out.png]

Writes docs/images/python-work-precision.png by default.
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt

import elasticlab as el

HERE = os.path.dirname(os.path.abspath(__file__))
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "images", "python-work-precision.png")

# kd = 1: lightly damped, so the error does not die out before T; box = 1000: no wall is ever
# reached, so the closed form holds. Velocity Verlet is first order with damping (docs/numerics.md).
# A run that fails (a step too large for its method) is a row with status "failed@t", not drawn.
result = el.study("spring1d", kd=1.0, box=1000.0, duration=2.0, repeat=5,
                  integrators=["euler", "midpoint", "rk4", "verlet", "yoshida4", "rk45"],
                  dts=[0.004, 0.002, 0.001, 0.0005, 0.00025, 0.000125],
                  tolerances=[1e-4, 1e-6, 1e-8, 1e-10])
print("reference:", result["reference"])
print("fitted orders (error_max):", {name: round(order, 2) for name, order in result["orders"].items()})

fig, (wall, work) = plt.subplots(1, 2, figsize=(10, 4.2))
for name in dict.fromkeys(r["integrator"] for r in result["rows"]):
    rows = sorted((r for r in result["rows"] if r["integrator"] == name and r["status"] == "ok"),
                  key=lambda r: r["dt"])
    order = result["orders"].get(name, float("nan"))
    label = f"{name} (order {order:.2f})" if order == order else name
    errors = [r["error_max"] for r in rows]
    (line,) = wall.loglog([r["wall_median"] for r in rows], errors, "o-", ms=3, label=label)
    # The spread of the repeats: from the first to the third quartile of the wall times.
    wall.fill_betweenx(errors, [r["wall_q1"] for r in rows], [r["wall_q3"] for r in rows],
                       color=line.get_color(), alpha=0.2, linewidth=0)
    work.loglog([r["force_evals"] for r in rows], errors, "o-", ms=3, color=line.get_color(), label=name)
wall.set_xlabel("wall time [s] (median of 5, band: q1 to q3)")
wall.set_ylabel("largest position error over the run [m]")
wall.set_title("work-precision, spring1d, T = 2 s")
work.set_xlabel("force evaluations")
work.set_title("the same against force evaluations")
wall.legend(fontsize=8)
for ax in (wall, work):
    ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(out, dpi=80)
print("wrote", os.path.relpath(out))
