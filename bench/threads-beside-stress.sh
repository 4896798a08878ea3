#!/usr/bin/env bash
# One and two threads beside a busy process (issue 27; docs/performance.md, "Two threads beside
# a busy process"): the level-6 sphere (RK4, DT 0.003, gravity off, --kernels avx2) with 1 and 2
# threads, alone and beside `stress-ng --cpu 1` and `--cpu 2`, in double and float, for one or
# more builds of elastic-lab-cli measured in alternated rounds (A B, B A, A B, ...). Prints one
# table row per (load, build, precision): steps/s with 1 and 2 threads and the paired ratio
# 2 / 1 (each round's two runs side by side), medians and ranges, every round's ratio (worst
# first), the share of the 2-thread runs' pool runs the caller ran alone and, for a build whose
# pool judges alone against together by trials, its trials and how many one thread won
# (ELASTIC_LAB_POOL_STATS; the pool on main has no trials: 0), the share of the worker's tasks
# begun on the CPU the caller posted the run from and how often a worker moved off it (builds
# from stop 41 on) and joined it (from stop 42 on), the state hashes seen, and the most of all
# CPU time the host took (steal in /proc/stat) during one of the row's runs: a virtual machine's
# host that runs its CPUs on fewer cores makes rounds that say nothing of the pool.
#
#   bench/threads-beside-stress.sh [--rounds N] [--steps N] [--loads "0 1 2"]
#       [--precisions "double float"] [--kernels avx2] [--control] [--interleave N] [--raw FILE]
#       CLI [CLI ...]
#   bench/threads-beside-stress.sh --summary FILE CLI [CLI ...]   (the table again from a raw file)
#
# --control runs one thread twice per round, before and after the two threads (1, 2, 1), and
# pairs the two threads with the mean of both: a load that drifts within a round then counts
# for both sides; the table also shows one thread against itself (the second run over the
# first), the noise any 2 / 1 round carries on this machine.
#
# --interleave N times the thread counts of a round in one process, in turns of N steps each
# (bench --interleave: 1, 2, 1, 2, ... or with --control 1, 2, 1, 1, 2, 1, ...), so that a load
# that drifts within the round (this virtual machine's host, for one) counts for both alike.
#
# e.g. bench/threads-beside-stress.sh build/release/app/cli/elastic-lab-cli
#      bench/threads-beside-stress.sh /tmp/cli-before build/release/app/cli/elastic-lab-cli
# Needs stress-ng (scripts/install-deps.sh) and python3. On a shared machine the caller may
# give its own shell more scheduler weight first (`echo -10 > /proc/$$/autogroup`); stress-ng
# runs in the same scheduler group as the benchmark, as a second program of the same user would.
set -euo pipefail

rounds=5 steps=150 loads="0 1 2" precisions="double float" kernels=avx2 raw="" summary="" control=0 interleave=0
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds) rounds=$2; shift 2 ;;
        --steps) steps=$2; shift 2 ;;
        --loads) loads=$2; shift 2 ;;
        --precisions) precisions=$2; shift 2 ;;
        --kernels) kernels=$2; shift 2 ;;
        --raw) raw=$2; shift 2 ;;
        --control) control=1; shift ;;
        --interleave) interleave=$2; shift 2 ;;
        --summary) summary=$2; shift 2 ;;
        -h|--help) sed -n '2,30p' "$0"; exit 0 ;;
        -*) echo "unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
done
[ $# -ge 1 ] || { echo "usage: $0 [options] CLI [CLI ...]" >&2; exit 2; }
clis=("$@")
if [ -z "$summary" ]; then  # measure (else only the table from the raw file)
command -v stress-ng >/dev/null || { echo "stress-ng is not installed (scripts/install-deps.sh)" >&2; exit 2; }
for c in "${clis[@]}"; do [ -x "$c" ] || { echo "not an executable: $c" >&2; exit 2; }; done

[ -n "$raw" ] || raw=$(mktemp /tmp/threads-beside-stress.XXXXXX.csv)
echo "load,build,precision,round,threads,steps_per_second,state_hash,pool,steal_percent" > "$raw"
args=(bench --scene sphere3d --set subdivisions=6 --set gravity=0 --set perturb=0.01 --integrator rk4
      --dt 0.003 --steps "$steps" --warmup 10 --kernels "$kernels")

echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) CPUs available"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

stress=""
cleanup() { [ -n "$stress" ] && kill "$stress" 2>/dev/null; wait 2>/dev/null || true; }
trap cleanup EXIT

# The host's steal over a run (a virtual machine): the share of all CPU time /proc/stat counts
# as stolen between two readings, in percent.
ticks() { head -1 /proc/stat; }
stolen() {  # ticks-before ticks-after
    awk -v a="$1" -v b="$2" 'BEGIN { n = split(a, x, " "); split(b, y, " "); for (i = 2; i <= n; ++i) all += y[i] - x[i];
        printf "%.0f", (all > 0 ? 100 * (y[9] - x[9]) / all : 0) }'
}

one() {  # load build-index precision round threads (1c: one thread, the control run)
    local out pool before steal
    before=$(ticks)
    out=$(ELASTIC_LAB_POOL_STATS=1 "${clis[$2]}" "${args[@]}" --precision "$3" --threads "${5%c}" 2>/tmp/tbs-err.$$)
    steal=$(stolen "$before" "$(ticks)")
    # the pools' own account (ELASTIC_LAB_POOL_STATS), one field: a float run has two pools
    pool=$(grep '^pool:' /tmp/tbs-err.$$ | sed 's/^pool: //; s/,/;/g' | paste -sd'|' || true)
    # steps_per_second is column 11, state_hash column 15 of bench's CSV
    echo "$out" | tail -1 | awk -F, -v l="$1" -v b="$2" -v p="$3" -v r="$4" -v t="$5" -v pool="$pool" -v s="$steal" \
        '{print l "," b "," p "," r "," t "," $11 "," $15 "," pool "," s}' >> "$raw"
}

interleaved() {  # load build-index precision round: the round's thread counts in one process, in turns
    local out pool threads=1,2 labels="1 2" before steal
    [ "$control" -eq 1 ] && threads=1,2,1 labels="1 2 1c"
    before=$(ticks)
    out=$(ELASTIC_LAB_POOL_STATS=1 "${clis[$2]}" "${args[@]}" --precision "$3" --threads "$threads" \
          --interleave "$interleave" 2>/tmp/tbs-err.$$)
    steal=$(stolen "$before" "$(ticks)")
    pool=$(grep '^pool:' /tmp/tbs-err.$$ | sed 's/^pool: //; s/,/;/g' | paste -sd'|' || true)  # the 2-thread run's
    echo "$out" | awk -F, -v l="$1" -v b="$2" -v p="$3" -v r="$4" -v labels="$labels" -v pool="$pool" -v s="$steal" \
        '{split(labels, t, " "); print l "," b "," p "," r "," t[NR] "," $11 "," $15 "," (t[NR] == "2" ? pool : "") "," s}' >> "$raw"
}

for load in $loads; do
    if [ "$load" -gt 0 ]; then
        stress-ng --cpu "$load" --timeout 3600 --quiet & stress=$!
        sleep 1
    fi
    for r in $(seq 1 "$rounds"); do
        # builds alternated round by round, and within a build the thread counts too
        order=$(seq 0 $((${#clis[@]} - 1)))
        [ $((r % 2)) -eq 0 ] && order=$(echo "$order" | tac)
        for b in $order; do
            for p in $precisions; do
                if [ "$interleave" -gt 0 ]; then interleaved "$load" "$b" "$p" "$r"
                elif [ "$control" -eq 1 ]; then one "$load" "$b" "$p" "$r" 1; one "$load" "$b" "$p" "$r" 2; one "$load" "$b" "$p" "$r" 1c
                elif [ $((r % 2)) -eq 1 ]; then one "$load" "$b" "$p" "$r" 1; one "$load" "$b" "$p" "$r" 2
                else one "$load" "$b" "$p" "$r" 2; one "$load" "$b" "$p" "$r" 1; fi
            done
        done
        echo "load $load round $r done (load average $(cut -d' ' -f1 /proc/loadavg))" >&2
    done
    if [ -n "$stress" ]; then kill "$stress"; wait "$stress" 2>/dev/null || true; stress=""; fi
done
rm -f /tmp/tbs-err.$$
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "raw rows: $raw"

else
    raw=$summary
fi

python3 - "$raw" "${clis[@]}" <<'EOF'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
clis = sys.argv[2:]
def fmt(v): return f"{statistics.median(v):.0f} ({min(v):.0f}-{max(v):.0f})"
def fmtr(v): return f"{statistics.median(v):.2f} ({min(v):.2f}-{max(v):.2f})"
import re
def pool(field):
    # the 2-thread run's pools (ELASTIC_LAB_POOL_STATS): runs, runs alone, trials, won alone,
    # worker tasks, of which begun on the caller's CPU, moves off it, joins onto it (0 where a build
    # has no such count)
    runs = alone = trials = won = tasks = shared = moves = joins = 0
    for m in re.finditer(r"(\d+) runs; (\d+) alone", field): runs += int(m[1]); alone += int(m[2])
    for m in re.finditer(r"(\d+) trials \(alone won (\d+)\)", field): trials += int(m[1]); won += int(m[2])
    # from stop 43 on: the share judge's trials alone and the verdicts that went on alone
    for m in re.finditer(r"tried alone by the CPU share (\d+); alone won (\d+)", field): trials += int(m[1]); won += int(m[2])
    for m in re.finditer(r"worker tasks (\d+)", field): tasks += int(m[1])
    for m in re.finditer(r"worker tasks on the caller's CPU (\d+)", field): shared += int(m[1])
    for m in re.finditer(r"moved off it (\d+)", field): moves += int(m[1])
    for m in re.finditer(r"joined it (\d+)", field): joins += int(m[1])
    return runs, alone, trials, won, tasks, shared, moves, joins
control = any(r["threads"] == "1c" for r in rows)
head = "| beside | build | precision | 1 thread, steps/s | 2 threads, steps/s | 2 / 1, paired | 2 / 1, each round |"
if control: head += " 1 / 1, each round (control) |"
print(head + " 2 threads: runs alone, trials (won alone) | 2 threads: worker tasks on the caller's CPU, moves off it, joins | state hash | host steal, % (most) |")
print("|---" * (12 if control else 11) + "|")
for load in dict.fromkeys(r["load"] for r in rows):
    for b in dict.fromkeys(r["build"] for r in rows):
        for p in dict.fromkeys(r["precision"] for r in rows):
            sel = [r for r in rows if (r["load"], r["build"], r["precision"]) == (load, b, p)]
            if not sel: continue
            by = {}
            for r in sel: by.setdefault(r["round"], {})[r["threads"]] = float(r["steps_per_second"])
            one = [v[k] for v in by.values() for k in ("1", "1c") if k in v]
            two = [v["2"] for v in by.values() if "2" in v]
            # with the control run, two threads against the mean of one thread before and after
            base = lambda v: (v["1"] + v["1c"]) / 2 if "1c" in v else v["1"]
            ratio = [v["2"] / base(v) for v in by.values() if "1" in v and "2" in v]
            selfratio = sorted(v["1c"] / v["1"] for v in by.values() if "1" in v and "1c" in v)
            hashes = ",".join(sorted({r["state_hash"] for r in sel}))
            beside = "nothing" if load == "0" else f"stress-ng --cpu {load}"
            acc = [pool(r.get("pool") or "") for r in sel if r["threads"] == "2"]
            runs, alone, trials, won, tasks, shared, moves, joins = (sum(a[k] for a in acc) for k in range(8))
            share = f"{100 * alone / runs:.0f} %, {trials} ({won})" if runs else "-"
            counted = any("caller's CPU" in (r.get("pool") or "") for r in sel)  # builds before stop 41: no such count
            joined = any("joined it" in (r.get("pool") or "") for r in sel)  # builds before stop 42: no joins
            placed = f"{100 * shared / tasks:.0f} %, {moves}, {joins if joined else '-'}" if tasks and counted else "-"
            rounds = ", ".join(f"{x:.2f}" for x in sorted(ratio))  # worst first
            ctl = (" " + ", ".join(f"{x:.2f}" for x in selfratio) + " |") if control else ""
            steal = [float(r["steal_percent"]) for r in sel if r.get("steal_percent")]  # raw files from stop 43 on
            stolen = f"{max(steal):.0f}" if steal else "-"
            print(f"| {beside} | {clis[int(b)]} | {p} | {fmt(one)} | {fmt(two)} | **{fmtr(ratio)}** | {rounds} |{ctl} {share} | {placed} | {hashes} | {stolen} |")
EOF
