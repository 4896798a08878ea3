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
$CLI study --scene ring2d --integrators rk4,rk45,implicit-euler,verlet \
    --dts 0.002,0.001,0.0005,0.00025 --tols 1e-3,1e-5,1e-7 --duration 1 --repeat 3 \
    --csv "$OUT/study-ring2d-floor.csv" --plot "$OUT/study-ring2d-floor.svg" > "$OUT/study-ring2d-floor.txt"
$CLI study --scene sphere3d --set gravity=0 --set perturb=0.05 --integrators $ALL \
    --dts 0.002,0.001,0.0005 --tols 1e-3,1e-5,1e-7 --duration 0.5 --repeat 3 \
    --csv "$OUT/study-sphere3d.csv" --plot "$OUT/study-sphere3d.svg" > "$OUT/study-sphere3d.txt"

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

# The thesis's experiment (§7.2.2) and the rest of the gallery.
$CLI gallery --run all > "$OUT/gallery.txt"
