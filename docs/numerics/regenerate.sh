#!/bin/sh
# Regenerates every table and diagram of docs/numerics.md (about 2-3 minutes on 2 cores).
# usage: docs/numerics/regenerate.sh [path/to/elastic-lab-cli]   (default build/num/app/cli/elastic-lab-cli)
set -e
CLI=${1:-build/num/app/cli/elastic-lab-cli}
OUT=$(dirname "$0")
ALL=euler,midpoint,rk4,symplectic-euler,verlet,rk45,implicit-euler

# Work-precision studies (timings: median of 5, one thread, stepping only).
$CLI study --scene spring1d --integrators $ALL --dts 0.01,0.005,0.0025,0.00125,0.000625 \
    --tols 1e-3,1e-5,1e-7,1e-9 --duration 2 --repeat 5 \
    --csv "$OUT/study-spring1d.csv" --plot "$OUT/study-spring1d.svg" > "$OUT/study-spring1d.txt"
$CLI study --scene ring2d --set gravity=0 --set perturb=0.05 --integrators $ALL \
    --dts 0.004,0.002,0.001,0.0005 --tols 1e-3,1e-5,1e-7,1e-9 --duration 1 --repeat 5 \
    --csv "$OUT/study-ring2d.csv" --plot "$OUT/study-ring2d.svg" > "$OUT/study-ring2d.txt"
# With the floor (thesis defaults), contact as a force (the default) and as the thesis
# program's projection, side by side (docs/numerics.md, "Contact").
FLOOR=euler,midpoint,rk4,verlet,rk45,implicit-euler
for scene in ring2d sphere3d; do
  $CLI study --scene $scene --integrators $FLOOR --dts 0.004,0.002,0.001,0.0005 --tols 1e-3,1e-5,1e-7 \
      --duration 2 --repeat 3 --csv "$OUT/study-$scene-floor.csv" --plot "$OUT/study-$scene-floor.svg" \
      > "$OUT/study-$scene-floor.txt"
  $CLI study --scene $scene --set contact=projection --integrators $FLOOR --dts 0.004,0.002,0.001,0.0005 \
      --tols 1e-3,1e-5,1e-7 --duration 2 --repeat 3 --csv "$OUT/study-$scene-floor-projection.csv" \
      --plot "$OUT/study-$scene-floor-projection.svg" > "$OUT/study-$scene-floor-projection.txt"
done
$CLI study --scene sphere3d --set gravity=0 --set perturb=0.05 --integrators $ALL \
    --dts 0.002,0.001,0.0005 --tols 1e-3,1e-5,1e-7 --duration 0.5 --repeat 3 \
    --csv "$OUT/study-sphere3d.csv" --plot "$OUT/study-sphere3d.svg" > "$OUT/study-sphere3d.txt"

# Refinement: the same physical body at several resolutions against the finest (rk4, the step
# chosen automatically; docs/numerics.md "Refinement study"). Weightless, the body inflates from
# its rest shape to equilibrium; with the floor it falls and hits it (the ring to 0.8 s: at 96
# particles its inner layer collapses at 0.85 s).
$CLI study --scene ring2d --set gravity=0 --refine particles=12,24,48,96 --duration 1 \
    --csv "$OUT/refine-ring2d.csv" --plot "$OUT/refine-ring2d.svg" > "$OUT/refine-ring2d.txt" 2>/dev/null
$CLI study --scene ring2d --refine particles=12,24,48,96 --duration 0.8 \
    --csv "$OUT/refine-ring2d-floor.csv" --plot "$OUT/refine-ring2d-floor.svg" > "$OUT/refine-ring2d-floor.txt" 2>/dev/null
$CLI study --scene sphere3d --set gravity=0 --refine subdivisions=1,2,3,4 --duration 0.5 \
    --csv "$OUT/refine-sphere3d.csv" --plot "$OUT/refine-sphere3d.svg" > "$OUT/refine-sphere3d.txt" 2>/dev/null
$CLI study --scene sphere3d --refine subdivisions=1,2,3,4 --duration 1 \
    --csv "$OUT/refine-sphere3d-floor.csv" --plot "$OUT/refine-sphere3d-floor.svg" > "$OUT/refine-sphere3d-floor.txt" 2>/dev/null

# Stability: measured (bisection) beside the linearised prediction.
$CLI stability --scene spring1d --integrators $ALL --duration 5 > "$OUT/stability-spring1d.txt"
$CLI stability --scene spring1d --set kd=0 --set gravity=0 --set fixed_end=0 --set box=100 --set initial_length=1.01 \
    --integrators $ALL --duration 5 > "$OUT/stability-spring1d-undamped.txt"
$CLI stability --scene ring2d --integrators $ALL --duration 2 > "$OUT/stability-ring2d.txt"
$CLI stability --scene ring2d --set rks=0 --set rkd=0 --set gravity=0 --integrators $ALL --duration 2 \
    > "$OUT/stability-single-rings.txt"
$CLI stability --scene ring2d --set gravity=0 --integrators $ALL --duration 2 > "$OUT/stability-ring2d-weightless.txt"
$CLI stability --scene sphere3d --integrators $ALL --duration 2 > "$OUT/stability-sphere3d.txt"
$CLI stability --scene sphere3d --set gravity=0 --integrators $ALL --duration 2 > "$OUT/stability-sphere3d-weightless.txt"
$CLI stability --scene ring2d --set contact=projection --integrators $ALL --duration 2 > "$OUT/stability-ring2d-projection.txt"
$CLI stability --scene sphere3d --set contact=projection --integrators $ALL --duration 2 > "$OUT/stability-sphere3d-projection.txt"

# Contact: restitution curves, a body at rest on the floor, undamped elastic bounces.
for e in 0.2 0.5 0.8 1; do
  $CLI restitution --scene ring2d --set restitution=$e --speeds 0.3,1,3,10,30 --csv "$OUT/restitution-ring2d-e$e.csv" \
      > "$OUT/restitution-ring2d-e$e.txt"
done
$CLI restitution --scene ring2d --set contact=projection --speeds 0.3,1,3,10,30 > "$OUT/restitution-ring2d-projection.txt"
$CLI restitution --scene sphere3d --speeds 0.3,1,3,10,30 > "$OUT/restitution-sphere3d.txt"
for c in force projection; do for scene in ring2d sphere3d; do for T in 5 20 40 60; do
  echo "$c $scene $T $($CLI run --scene $scene --set contact=$c --duration $T | grep removed)"
done; done; done > "$OUT/resting-drift.txt"
$CLI run --scene ring2d --set kd=0 --set rkd=0 --set restitution=1 --dt 0.0005 --duration 5 > "$OUT/elastic-bounce-force.txt"
$CLI run --scene ring2d --set kd=0 --set rkd=0 --set restitution=1 --dt 0.0005 --duration 5 --set contact=projection \
    > "$OUT/elastic-bounce-projection.txt"

# The thesis's experiment (§7.2.2) and the rest of the gallery.
$CLI gallery --run all > "$OUT/gallery.txt"
python3 "$OUT/plot-restitution.py"
docs/numerics/course-bench.sh "$CLI"
