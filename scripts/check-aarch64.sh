#!/usr/bin/env bash
# Builds the force code for AArch64 and checks that it gives the same bits as on x86-64.
#
# tests/cross/force_hash.cpp prints the force code's results (hashes and values in hex, one line
# each; see there). It is compiled with the simcore sources it needs (no Qt, no SUNDIALS) and
# simcore's own flags (simcore/CMakeLists.txt, Release), three times:
#   x86-64            every kernel set, run with portable, AVX2 and AVX-512 (where the CPU has them);
#   x86-64 portable   -DELASTIC_LAB_PORTABLE_KERNELS (the CMake option of that name): no x86 intrinsics;
#   AArch64           the portable kernels (the only ones there), run under qemu-aarch64.
# Every output is compared with the x86-64 portable one, line by line; exit 0 only if all are
# identical. Then the AArch64 kernels' object code is searched for NEON vector arithmetic on
# pairs of doubles (v<n>.2d) and the counts printed.
# Needs the optional packages: scripts/install-deps.sh --cross. Not part of CTest (a CI machine
# has no cross compiler). Build products go to build/aarch64-check.
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in aarch64-linux-gnu-g++ aarch64-linux-gnu-objdump qemu-aarch64; do
  command -v "$tool" >/dev/null || { echo "check-aarch64: $tool not found (scripts/install-deps.sh --cross)" >&2; exit 2; }
done
out=build/aarch64-check
mkdir -p "$out"

# What simcore's target compiles these sources with (CMakeLists.txt, simcore/CMakeLists.txt):
# Release -O3 -DNDEBUG, C++20 without GNU extensions, position-independent with
# -fno-semantic-interposition, no errno from sqrt, no trapping assumed, no contraction into
# fused multiply-adds; -Wno-psabi on force_kernels.cpp; the project's warnings.
flags=(-std=c++20 -O3 -DNDEBUG -fPIC -fno-semantic-interposition
       -fno-math-errno -fno-trapping-math -ffp-contract=off -pthread
       -Isimcore -Itests -isystem /usr/include/eigen3
       -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
       -Woverloaded-virtual -Wconversion -Wno-sign-conversion -Wno-restrict)
# The simcore sources the force evaluation needs.
sources=(params body scaling forces contact force_kernels parallel scenes)

# build NAME COMPILER [FLAGS...]: objects and the driver into $out/NAME, two compilations at once.
build() {
  local name=$1 compiler=$2
  shift 2
  mkdir -p "$out/$name"
  local objects=() pids=() src extra
  for src in "${sources[@]/#/simcore/}" tests/cross/force_hash; do
    extra=()
    [ "$src" = simcore/force_kernels ] && extra=(-Wno-psabi)
    "$compiler" "${flags[@]}" "$@" "${extra[@]}" -c "$src.cpp" -o "$out/$name/$(basename "$src").o" &
    pids+=($!)
    objects+=("$out/$name/$(basename "$src").o")
    if [ ${#pids[@]} -ge 2 ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  done
  for pid in "${pids[@]}"; do wait "$pid"; done
  "$compiler" -pthread "${objects[@]}" -o "$out/$name/force_hash"
  echo "built $out/$name/force_hash ($compiler $*)"
}

# What GCC on x86-64 builds by default (simcore/CMakeLists.txt defines ELASTIC_LAB_MULTIVERSION there).
build x86-64 g++ -DELASTIC_LAB_MULTIVERSION
build x86-64-portable g++ -DELASTIC_LAB_PORTABLE_KERNELS
build aarch64 aarch64-linux-gnu-g++

# run NAME OUTPUT [COMMAND...]: the driver of build NAME (under COMMAND), with $kernel_set when
# set, its results into $out/OUTPUT.txt. Returns 3 when the build or CPU lacks that set (the
# driver's exit code for it); any other failure stops the check with the driver's message.
run() {
  local name=$1 output=$2 status=0
  shift 2
  "$@" "$out/$name/force_hash" ${kernel_set:+"$kernel_set"} >"$out/$output.txt" 2>"$out/$output.err" || status=$?
  if [ $status -ne 0 ] && [ $status -ne 3 ]; then
    echo "FAILED: $output: the driver exited with $status: $(cat "$out/$output.err")" >&2
    exit 1
  fi
  return $status
}

kernel_set=portable run x86-64 x86-64-portable
reference=$out/x86-64-portable.txt
cases=$(grep -c ' rest-shape ' "$reference")
blocks=$(grep -c '^kernel-' "$reference")
echo "reference: x86-64, portable kernels: $(wc -l <"$reference") lines ($cases cases, $blocks kernel blocks)"

failed=0
compare() {
  local label=$1 output=$2
  if cmp -s "$reference" "$out/$output.txt"; then
    echo "identical: $label ($(wc -l <"$out/$output.txt") lines)"
  else
    echo "DIFFERENT: $label against x86-64 portable:" >&2
    diff "$reference" "$out/$output.txt" | head -40 >&2 || true
    echo "  (lines differing: $(diff "$reference" "$out/$output.txt" | grep -c '^>' || true))" >&2
    failed=1
  fi
}
for s in avx2 avx512; do
  if kernel_set=$s run x86-64 "x86-64-$s"; then
    compare "x86-64, $s kernels" "x86-64-$s"
  else
    echo "not compared: x86-64 $s kernels (not on this CPU)"
  fi
done
kernel_set="" run x86-64-portable x86-64-portable-only
compare "x86-64 built with ELASTIC_LAB_PORTABLE_KERNELS" x86-64-portable-only
kernel_set="" run aarch64 aarch64 qemu-aarch64 -L /usr/aarch64-linux-gnu
echo "aarch64 run: $(cat "$out/aarch64.err")"
compare "AArch64 (qemu-aarch64), portable kernels" aarch64

# NEON arithmetic on two doubles per register in the AArch64 kernels, and no fused
# multiply-add anywhere in the AArch64 objects (-ffp-contract=off; an fmadd or fmla would round
# once where x86-64 rounds twice).
aarch64-linux-gnu-objdump -d --no-show-raw-insn "$out/aarch64/force_kernels.o" >"$out/aarch64-force_kernels.s"
echo "AArch64 force_kernels.o, arithmetic on doubles: NEON (v<n>.2d, two per register) and scalar (d<n>):"
for op in fadd fsub fmul fdiv fsqrt; do
  printf '  %-6s NEON %4d  scalar %4d\n' "$op" "$(grep -cE "\s$op\s+v[0-9]+\.2d" "$out/aarch64-force_kernels.s" || true)" \
    "$(grep -cE "\s$op\s+d[0-9]+" "$out/aarch64-force_kernels.s" || true)"
done
fused=$(for o in "$out"/aarch64/*.o; do aarch64-linux-gnu-objdump -d --no-show-raw-insn "$o"; done |
        grep -cE '\s(fmadd|fmsub|fnmadd|fnmsub|fmla|fmls)\s' || true)
echo "fused multiply-adds in the AArch64 objects: $fused"
[ "$fused" -eq 0 ] || { echo "FAILED: fused multiply-adds in the AArch64 build" >&2; failed=1; }

if [ $failed -ne 0 ]; then
  echo "check-aarch64: FAILED" >&2
  exit 1
fi
echo "check-aarch64: all identical"
