#!/usr/bin/env python3
"""The rooms of the code, checked from its includes (docs/conventions.md, "Rooms"):
- every include of a library header names its library ("simcore/body.h", not "body.h");
- no include runs up a layer (simcore < simlab < ui, app, python; nothing includes app/ but app
  and the tests);
- nothing outside simcore (and its tests) includes simcore/internal/;
- within a library no two files include each other in a circle, a header and its source counted
  as one file (Tarjan's strongly connected components over the file graph);
- no source, doc or lesson points a reader at a file outside the repository (the physics is
  docs/model.md, the conventions docs/conventions.md: the repository stands on its own).
Prints each violation and exits 1 when there is one. Usage: check-structure.py [ROOT]."""
import os, re, sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
os.chdir(root)
LAYER = {"simcore": 0, "simlab": 1, "ui": 2, "app": 3, "python": 3, "bench": 3, "fuzz": 3, "tests": 4}
INC = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
problems = []

def sources():
    for top in LAYER:
        for dirpath, _, names in os.walk(top):
            if "/build" in dirpath or dirpath.startswith("build"): continue
            for n in names:
                if n.endswith((".h", ".cpp")):
                    yield os.path.join(dirpath, n)

files = sorted(sources())
headers = {f for f in files if f.endswith(".h")}
basenames = {}
for h in headers:
    if h.split("/")[0] in ("simcore", "simlab", "ui", "app"):
        basenames.setdefault(os.path.basename(h), []).append(h)

def unit(path):  # a header and its source are one file
    return path[:-2] if path.endswith(".h") else path[:-4]

graph = {}
for f in files:
    top = f.split("/")[0]
    text = open(f, encoding="utf-8").read()
    for inc in INC.findall(text):
        if inc.endswith(".moc") or inc == "elastic_lab_version.h": continue
        if "/" not in inc:
            if inc in basenames and not os.path.exists(os.path.join(os.path.dirname(f), inc)):
                problems.append(f"{f}: includes \"{inc}\" without its library (\"{basenames[inc][0]}\")")
            elif inc in basenames and top != "tests":
                problems.append(f"{f}: includes \"{inc}\" without its library (\"{basenames[inc][0]}\")")
            continue
        target_top = inc.split("/")[0]
        if target_top not in LAYER or not os.path.exists(inc): continue
        if LAYER[target_top] > LAYER[top] and not (top == "tests"):
            problems.append(f"{f}: includes {inc}, a layer above it")
        if target_top == "app" and top not in ("app", "tests", "fuzz"):
            problems.append(f"{f}: includes {inc} (the app is on top; nothing but it and the tests include it)")
        if inc.startswith("simcore/internal/") and top not in ("simcore", "tests"):
            problems.append(f"{f}: includes {inc}, internal to simcore")
        if target_top == top and top in ("simcore", "simlab", "ui"):
            a, b = unit(f), unit(inc)
            if a != b: graph.setdefault(a, set()).add(b)

# Tarjan's strongly connected components: a component of two or more files is a circle.
index, low, stack, on, counter, comps = {}, {}, [], set(), [0], []
def connect(v):
    index[v] = low[v] = counter[0]; counter[0] += 1; stack.append(v); on.add(v)
    for w in sorted(graph.get(v, ())):
        if w not in index:
            connect(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v: break
        if len(comp) > 1: comps.append(sorted(comp))
sys.setrecursionlimit(10000)
for v in sorted(graph):
    if v not in index: connect(v)
for c in comps:
    problems.append("files that include each other in a circle: " + ", ".join(c))

# The repository stands on its own: the physics and the conventions it cites are its own docs.
OUTSIDE = re.compile(r"\.\./shared|\bMODEL\.md|\bSTYLE\.md")
for top in list(LAYER) + ["docs", "resources", "scripts", "README.md"]:
    paths = [top] if os.path.isfile(top) else [os.path.join(d, n) for d, _, ns in os.walk(top) for n in ns]
    for path in sorted(paths):
        if "/build" in path or path.startswith("build") or path.endswith("check-structure.py"): continue
        if not path.endswith((".h", ".cpp", ".py", ".md", ".html", ".sh", ".txt")): continue
        for number, line in enumerate(open(path, encoding="utf-8", errors="replace"), 1):
            if OUTSIDE.search(line):
                problems.append(f"{path}:{number}: names a file outside the repository ({OUTSIDE.search(line).group(0)}); cite docs/model.md or docs/conventions.md")

for p in problems: print(p)
print(f"check-structure: {len(files)} files, {len(problems)} problems")
sys.exit(1 if problems else 0)
