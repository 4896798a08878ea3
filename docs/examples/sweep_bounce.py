"""How does the bounce depend on pressure and stiffness? A sweep, as in a notebook cell by cell
(docs/sweeps.md): a 6 x 6 grid of sphere3d runs, the first rebound's height as a heat map.

    PYTHONPATH=build/release/python python3 docs/examples/sweep_bounce.py [OUT.png]
"""

import sys

import matplotlib

matplotlib.use("Agg")  # in a notebook: leave this out, the figure shows inline
import matplotlib.pyplot as plt

import elasticlab as el

# In [1]: the grid: gas constant nRT [J] and membrane stiffness [N/m], both logarithmically.
df = el.sweep("sphere3d", {"pressure": el.log(20, 2000, 6), "ks": el.log(200, 3200, 6)},
              duration=2.5, metrics=["bounce_time", "bounce_height", "volume_inner_min", "steps"],
              subdivisions=2, progress=False)

# In [2]: one row per run; every run ended well?
print(df.groupby("status").size().to_string())
print(df[["pressure", "ks", "bounce_time", "bounce_height", "volume_inner_min"]].head(8).to_string(index=False))

# In [3]: pressure x stiffness -> bounce height, as a heat map.
table = df.pivot(index="pressure", columns="ks", values="bounce_height")
fig, ax = plt.subplots(figsize=(6.4, 4.8))
image = ax.imshow(table.to_numpy(), origin="lower", aspect="auto", cmap="viridis")
ax.set_xticks(range(len(table.columns)), [f"{k:.0f}" for k in table.columns])
ax.set_yticks(range(len(table.index)), [f"{p:.0f}" for p in table.index])
ax.set_xlabel("ks: membrane stiffness [N/m]")
ax.set_ylabel("pressure: nRT per layer [J]")
ax.set_title("sphere3d (level 2), rk4: height of the first rebound")
fig.colorbar(image, label="centre of mass above the floor at the apex [m]")
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "sweep_bounce.png", dpi=100)
