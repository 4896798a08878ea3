#!/usr/bin/env bash
# The long-function gate (docs/conventions.md, "Functions"): lists every function outside the
# tests that is longer than a limit (default 80 lines, from the line of its name to its closing
# brace), each with the reason written above it, and exits 1 when one has none. CTest runs it
# (test long_functions, Release only).
#   scripts/long-functions.sh [LIMIT]
# The reason: a line "// Kept whole: <reason>" in the run of // comment lines (and template<...>
# lines) directly above the function's first line; the reason may go on over the next comment
# lines. A function listed in scripts/long-functions.owned-elsewhere ("path function  # why") is
# printed as such and does not fail the gate: its file is being rewritten by other work.
# Reads the files git tracks or would add (every source when not in a checkout) with Universal
# Ctags (Debian: universal-ctags); exits 77 (CTest: skipped) when ctags is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
limit=${1:-80}
command -v ctags >/dev/null || { echo "long-functions: skipped, needs ctags (universal-ctags; scripts/install-deps.sh)" >&2; exit 77; }
dirs=(simcore simlab ui app python bench)
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files --cached --others --exclude-standard "${dirs[@]/%//*.cpp}" "${dirs[@]/%//*.h}" | while read -r f; do [ -f "$f" ] && echo "$f"; done)
else
    files=$(find "${dirs[@]}" -name '*.cpp' -o -name '*.h' | sort)
fi
# shellcheck disable=SC2086
ctags --sort=no --output-format=json --language-force=C++ --kinds-C++=f --fields=+ne --extras=-q -f - $files |
python3 -c '
import json, sys
limit = int(sys.argv[1])
elsewhere = {}
try:
    for line in open("scripts/long-functions.owned-elsewhere", encoding="utf-8"):
        entry, _, why = line.partition("#")
        if entry.split(): elsewhere[tuple(entry.split()[:2])] = why.strip()
except FileNotFoundError:
    pass
bad = 0
rows = []
for line in sys.stdin:
    t = json.loads(line)
    if t.get("_type") != "tag" or "end" not in t: continue
    n = t["end"] - t["line"] + 1
    if n <= limit: continue
    src = open(t["path"], encoding="utf-8").read().split("\n")
    # The comment lines right above the definition (and its template line), no blank between.
    i = t["line"] - 2
    comment = []
    while i >= 0 and (src[i].lstrip().startswith("//") or src[i].lstrip().startswith("template")):
        comment.append(src[i].strip()); i -= 1
    block = [c.lstrip("/").strip() for c in reversed(comment) if c.startswith("//")]
    text = " ".join(block)
    reason = text.split("Kept whole:", 1)[1].strip() if "Kept whole:" in text else ""
    scope = ".".join(p if not p.startswith("__anon") else "(anonymous)" for p in t.get("scope", "").split("::"))
    name = (scope + "::" if scope else "") + t["name"]
    if not reason:
        why = elsewhere.get((t["path"], t["name"])) or elsewhere.get((t["path"], name))
        if why is not None: reason = "OWNED ELSEWHERE: " + why
        else: bad += 1
    rows.append((t["path"], t["line"], n, name, reason))
for path, line, n, name, reason in sorted(rows):
    print(f"{path}:{line}: {name}: {n} lines: " + (reason or "NO REASON (split it, or write \"// Kept whole: <reason>\" right above it)"))
print(f"{len(rows)} functions over {limit} lines, {bad} without a reason")
sys.exit(1 if bad else 0)
' "$limit"
