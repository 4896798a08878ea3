#!/usr/bin/env bash
# Are the two CPUs two cores right now? (issue 27; docs/performance.md, "Issue 27 at stop 38").
# On a virtual machine the host may place the two virtual CPUs on two cores or on the two
# hardware threads of one core, and may move them. Each round measures, back to back:
#   pair  - floating-point work per CPU second on both CPUs at once (stress-ng --cpu 2, one
#           worker pinned to each CPU) over the same on one CPU alone: ~1.0 when the CPUs are
#           separate cores, well below 1 when they share one core's units (or its caches);
#   2/1   - the level-6 sphere's steps/s with 2 threads over 1 thread (RK4, DT 0.003, gravity
#           off, `--kernels avx2` unless --kernels is given).
# If the 2-thread scaling follows `pair` round by round, a slow round is the machine's, not
# the pool's. Run it with nothing else running.
#
#   bench/vcpu-pair-probe.sh [--rounds N] [--steps N] [--kernels K] CLI
set -euo pipefail

rounds=6 steps=150 kernels=avx2
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds) rounds=$2; shift 2 ;;
        --steps) steps=$2; shift 2 ;;
        --kernels) kernels=$2; shift 2 ;;
        -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
        -*) echo "unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
[ $# -eq 1 ] && [ -x "$1" ] || { echo "usage: $0 [--rounds N] [--steps N] [--kernels K] CLI" >&2; exit 2; }
cli=$1
command -v stress-ng >/dev/null || { echo "stress-ng is not installed (scripts/install-deps.sh)" >&2; exit 2; }
[ "$(nproc)" -ge 2 ] || { echo "needs two CPUs (nproc: $(nproc))" >&2; exit 2; }

# Bogo operations per CPU second (user + system) of stress-ng's double-precision method.
perCpuSecond() {  # taskset-list workers
    stress-ng --cpu "$2" --cpu-method double --taskset "$1" --timeout 2s --metrics-brief 2>&1 |
        awk '$4 == "cpu" { print $NF }'
}

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) CPUs; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "round,one_cpu_ops_per_cpu_s,two_cpus_ops_per_cpu_s,pair,steps_per_s_1,steps_per_s_2,two_over_one"
for r in $(seq 1 "$rounds"); do
    one=$(perCpuSecond 0 1)
    two=$(perCpuSecond 0,1 2)
    rates=$("$cli" bench --scene sphere3d --set subdivisions=6 --set gravity=0 --set perturb=0.01 --integrator rk4 \
        --dt 0.003 --steps "$steps" --warmup 10 --threads 1,2 --kernels "$kernels" | awk -F, '{ print $11 }' | paste -sd,)
    python3 - "$r" "$one" "$two" "$rates" <<'EOF'
import sys
r, one, two, rates = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), [float(x) for x in sys.argv[4].split(',')]
print(f"{r},{one:.0f},{two:.0f},{two / one:.3f},{rates[0]:.1f},{rates[1]:.1f},{rates[1] / rates[0]:.3f}")
EOF
done
