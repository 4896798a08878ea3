#!/bin/sh
# The numerics course bench (docs/numerics.md, "The numerics course bench"): honest run time,
# several error measures, the symplectic family, long-time energy and the round-off floor.
# About a minute on 2 cores.
# usage: docs/numerics/course-bench.sh [path/to/elastic-lab-cli]   (default build/num/app/cli/elastic-lab-cli)
set -e
CLI=${1:-build/num/app/cli/elastic-lab-cli}
OUT=$(dirname "$0")

# Work-precision on the undamped closed form, every raw timing kept (9 repeats), a budget of
# 5 ms per run: the symplectic family beside the explicit Runge-Kutta methods.
$CLI study --scene spring1d --set kd=0 --integrators euler,midpoint,rk4,symplectic-euler,verlet,yoshida4,yoshida8,rk45 \
    --dts 0.02,0.01,0.005,0.0025,0.00125,0.000625,0.0003125,0.00015625,7.8125e-05 --tols 1e-4,1e-6,1e-8,1e-10,1e-12 \
    --duration 2 --repeat 9 --time-budget 0.005 --csv "$OUT/course-spring1d.csv" --timings "$OUT/course-spring1d-timings.csv" \
    --plot "$OUT/course-spring1d.svg" > "$OUT/course-spring1d.txt"

# The round-off floor: rk4 and yoshida4 in double (the simulation) and in float (the float
# build of spring1d), and float with the compensated (Kahan) state update.
DTS=0.02,0.01,0.005,0.0025,0.00125,0.000625,0.0003125,0.00015625,7.8125e-05,3.90625e-05
$CLI study --scene spring1d --set kd=0 --integrators rk4,yoshida4 --dts $DTS --duration 2 --precision double,float --repeat 3 \
    --csv "$OUT/course-roundoff.csv" --plot "$OUT/course-roundoff.svg" > "$OUT/course-roundoff.txt"
$CLI study --scene spring1d --set kd=0 --integrators rk4,yoshida4 --dts $DTS --duration 2 --precision float --repeat 3 \
    --compensated --csv "$OUT/course-roundoff-kahan.csv" --plot "$OUT/course-roundoff-kahan.svg" \
    > "$OUT/course-roundoff-kahan.txt"

# Long-time energy: ten thousand periods of spring1d's mode (the guided experiment), and the
# round-off walk, in double (yoshida8 at h omega = 0.057) and in float.
$CLI conservation --scene spring1d --dt 0.01 --periods 10000 \
    --integrators symplectic-euler,verlet,yoshida4,yoshida8,euler,midpoint,rk4 \
    --csv "$OUT/conservation-spring1d.csv" --curves "$OUT/conservation-spring1d-curves.csv" \
    --plot "$OUT/conservation-spring1d.svg" > "$OUT/conservation-spring1d.txt" 2>/dev/null
$CLI conservation --scene spring1d --dt 0.002 --periods 3000 --integrators verlet,yoshida8 \
    --csv "$OUT/conservation-roundoff.csv" --plot "$OUT/conservation-roundoff.svg" \
    > "$OUT/conservation-roundoff.txt" 2>/dev/null
$CLI conservation --scene spring1d --dt 0.0005 --periods 10000 --integrators verlet,yoshida8,rk4 --precision float \
    --csv "$OUT/conservation-float.csv" --plot "$OUT/conservation-float.svg" > "$OUT/conservation-float.txt" 2>/dev/null
# A 2D body: the weightless ring, undamped.
$CLI conservation --scene ring2d --set gravity=0 --dt 0.001 --periods 2000 --integrators verlet,yoshida4,rk4 \
    --csv "$OUT/conservation-ring2d.csv" --plot "$OUT/conservation-ring2d.svg" > "$OUT/conservation-ring2d.txt" 2>/dev/null
