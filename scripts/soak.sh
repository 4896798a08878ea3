#!/usr/bin/env bash
# Runs the README's test command (scripts/test.sh, what CI runs) from fresh clones of HEAD,
# several at once, and prints one line per run: commit, start, end, minutes, result.
# Each run is the others' busy machine; --stress adds `stress-ng --cpu 2` beside them,
# --nice runs the last clone under `nice -n 19`, and --ccache compiles through a ccache shared
# by the clones (so that, once warm, the machine's time goes to the tests rather than to
# compiling the same objects again). docs/reliability.md records what it gave.
#   scripts/soak.sh [--runs N] [--stress] [--nice] [--ccache]     (default: 3 runs at once)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3 stress=0 nice_last=0 cache=0
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --stress) stress=1; shift ;;
    --nice) nice_last=1; shift ;;
    --ccache) cache=1; shift ;;
    *) echo "usage: scripts/soak.sh [--runs N] [--stress] [--nice] [--ccache]" >&2; exit 2 ;;
  esac
done
commit=$(git rev-parse --short HEAD)
root=$(mktemp -d /tmp/elastic-lab-soak.XXXXXX)
if [ "$cache" = 1 ]; then
  # CMake takes the launcher from the environment; paths below $root hash alike in every clone.
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
  export CCACHE_DIR=/tmp/elastic-lab-ccache CCACHE_BASEDIR=/tmp CCACHE_NOHASHDIR=1 CCACHE_MAXSIZE=20G
fi
stress_pid=""
if [ "$stress" = 1 ]; then
  stress-ng --cpu 2 --timeout 4h >/dev/null 2>&1 &
  stress_pid=$!
fi
pids=()
for i in $(seq 1 "$runs"); do
  git clone -q . "$root/run$i"
  prefix=()
  if [ "$nice_last" = 1 ] && [ "$i" = "$runs" ]; then prefix=(nice -n 19); fi
  (
    start=$(date -u +%H:%M:%S); t0=$(date +%s)
    if (cd "$root/run$i" && "${prefix[@]}" bash .ci/run) >"$root/run$i.log" 2>&1; then result=pass; else result=FAIL; fi
    t1=$(date +%s)
    printf '%s run%s%s %s-%s UTC %.1f min %s (%s)\n' "$commit" "$i" "${prefix[*]:+ (${prefix[*]})}" "$start" \
      "$(date -u +%H:%M:%S)" "$(echo "($t1 - $t0) / 60" | bc -l)" "$result" \
      "$(grep -E 'tests passed|tests failed' "$root/run$i.log" | tr '\n' ' ')"
  ) &
  pids+=($!)
done
status=0
for p in "${pids[@]}"; do wait "$p" || status=1; done
[ -n "$stress_pid" ] && kill "$stress_pid" 2>/dev/null || true
echo "logs: $root"
exit $status
