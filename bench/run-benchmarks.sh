#!/usr/bin/env bash
# Regenerates the tables of docs/performance.md (run on an otherwise idle machine).
#   bench/run-benchmarks.sh [build-dir]   -> CSV on stdout
set -euo pipefail
B=${1:-build/release}/app/cli/elastic-lab-cli
first=1
row() {
  if [ $first = 1 ]; then "$B" bench "$@" --header; first=0; else "$B" bench "$@"; fi
}
# Each run takes at least ~0.3 s of stepping: steps scale inversely with the body.
for level in 1 2 3 4 5 6 7; do
  steps=$(( 400000 / (4 ** level) + 20 ))
  for threads in 1 2; do row --scene sphere3d --set subdivisions=$level --steps $steps --threads $threads; done
done
for n in 10 100 1000 10000 100000; do
  steps=$(( 2000000 / n + 10 ))
  row --scene ring2d --set particles=$n --steps $steps --threads 2
done
for integrator in euler midpoint rk4 symplectic-euler verlet; do
  row --scene sphere3d --set subdivisions=5 --integrator $integrator --steps 200 --threads 2
done
