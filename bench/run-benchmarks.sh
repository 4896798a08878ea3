#!/usr/bin/env bash
# Regenerates the tables of docs/performance.md (run on an otherwise idle machine).
#   bench/run-benchmarks.sh [build-dir]   -> CSV on stdout
set -euo pipefail
B=${1:-build/release}/app/cli/elastic-lab-cli
first=1
row() {
  if [ $first = 1 ]; then "$B" bench "$@" --header; first=0; else "$B" bench "$@"; fi
}
# Each run takes at least ~0.3 s of stepping: steps scale inversely with the body. Gravity is
# off and the start perturbed (the body wobbles in place, every term still evaluated): with 1 kg
# per particle, fine spheres are heavy and soft and would collapse on the floor in long runs.
for level in 1 2 3 4 5 6 7; do
  steps=$(( 400000 / (4 ** level) + 20 ))
  for threads in 1 2; do row --scene sphere3d --set subdivisions=$level --set gravity=0 --set perturb=0.01 --steps $steps --threads $threads; done
done
for n in 10 100 1000 10000 100000; do
  steps=$(( 2000000 / n + 10 ))
  row --scene ring2d --set particles=$n --set gravity=0 --set perturb=0.01 --steps $steps --threads 2
done
for integrator in euler midpoint rk4 symplectic-euler verlet; do
  row --scene sphere3d --set subdivisions=5 --integrator $integrator --set gravity=0 --set perturb=0.01 --steps 200 --threads 2
done
