#!/usr/bin/env bash
# Lists the functions outside the tests that are longer than a limit (default 80 lines), each
# with the reason written above it ("Kept whole: ..." in the comment right above the function;
# docs/conventions.md, "Functions"). Exits 1 when a long function has no reason.
#   scripts/long-functions.sh [LIMIT]
# Reads definitions with Universal Ctags (Debian: universal-ctags).
set -euo pipefail
cd "$(dirname "$0")/.."
limit=${1:-80}
command -v ctags >/dev/null || { echo "long-functions: needs ctags (universal-ctags)" >&2; exit 2; }
files=$(git ls-files 'simcore/*.cpp' 'simcore/*.h' 'simlab/*.cpp' 'simlab/*.h' 'ui/*.cpp' 'ui/*.h' \
        'app/*.cpp' 'app/*.h' 'python/*.cpp' 'bench/*.cpp' | while read -r f; do [ -f "$f" ] && echo "$f"; done)
# shellcheck disable=SC2086
ctags --sort=no --output-format=json --language-force=C++ --kinds-C++=f --fields=+ne --extras=-q -f - $files |
python3 -c '
import json, sys
limit = int(sys.argv[1])
bad = 0
rows = []
for line in sys.stdin:
    t = json.loads(line)
    if t.get("_type") != "tag" or "end" not in t: continue
    n = t["end"] - t["line"] + 1
    if n <= limit: continue
    src = open(t["path"], encoding="utf-8").read().split("\n")
    # the comment block right above the definition (template lines and blank-free)
    i = t["line"] - 2
    comment = []
    while i >= 0 and (src[i].lstrip().startswith("//") or src[i].lstrip().startswith("template")):
        comment.append(src[i].strip()); i -= 1
    block = [c.lstrip("/").strip() for c in reversed(comment) if c.startswith("//")]
    text = " ".join(block)
    reason = text.split("Kept whole:", 1)[1].strip() if "Kept whole:" in text else None
    scope = ".".join(p if not p.startswith("__anon") else "(anonymous)" for p in t.get("scope", "").split("::"))
    name = (scope + "::" if scope else "") + t["name"]
    rows.append((t["path"], t["line"], n, name, reason))
    if reason is None: bad += 1
for path, line, n, name, reason in sorted(rows):
    print(f"{path}:{line}: {name}: {n} lines: " + (reason or "NO REASON"))
print(f"{len(rows)} functions over {limit} lines, {bad} without a reason")
sys.exit(1 if bad else 0)
' "$limit"
