#!/usr/bin/env bash
# test_package: builds the .deb from the build tree with CPack, unpacks it into a scratch root
# and runs the installed binaries from there (both binaries' --version, a short elastic-lab-cli
# run); checks the package's fields, its Depends (from dpkg-shlibdeps), the installed layout,
# the desktop entry, icon, metainfo, man pages, bash completion and docs.
# Everything happens in a temporary directory removed on exit; nothing is written to the source
# tree. Registered by packaging/CMakeLists.txt (Release builds only, see there).
#
# test_package.sh CPACK BUILD_DIR VERSION APP_ID GUI(ON|OFF) MAN_PAGES(ON|OFF) PYTHON(ON|OFF) \
#                 DESKTOP_FILE_VALIDATE|"" APPSTREAMCLI|""
set -euo pipefail
[ $# -eq 9 ] || { echo "usage: $0 CPACK BUILD_DIR VERSION APP_ID GUI MAN_PAGES PYTHON DESKTOP_FILE_VALIDATE APPSTREAMCLI" >&2; exit 2; }
cpack=$1 build=$2 version=$3 app_id=$4 gui=$5 man=$6 python=$7 desktop_validate=$8 appstreamcli=$9

scratch=$(mktemp -d "${TMPDIR:-/tmp}/elastic-lab-package.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# --- build the package ---
if ! "$cpack" --config "$build/CPackConfig.cmake" -G DEB -B "$scratch/out" >"$scratch/cpack.log" 2>&1; then
  cat "$scratch/cpack.log" >&2
  fail "cpack failed"
fi
deb=$scratch/out/elastic-lab_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || { ls -l "$scratch/out" >&2; fail "no $(basename "$deb")"; }
echo "package: $(basename "$deb"), $(stat -c %s "$deb") bytes"

field() { dpkg-deb --field "$deb" "$1"; }
[ "$(field Package)" = elastic-lab ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', the project is $version"
[ "$(field Section)" = science ] || fail "Section is '$(field Section)'"
[ -n "$(field Maintainer)" ] || fail "no Maintainer"
depends=$(field Depends)
echo "Depends: $depends"
# dpkg-shlibdeps found the libraries the binaries link: the C and C++ runtimes always, Qt with the GUI.
expected=(libc6 libstdc++6 libgcc-s1)
[ "$gui" = ON ] && expected+=(libqt6core6 libqt6gui6 libqt6widgets6 libqt6opengl6 libqt6openglwidgets6)
for dep in "${expected[@]}"; do
  [[ ", $depends," == *", $dep "* || ", $depends," == *", $dep,"* ]] || fail "Depends lacks $dep"
done
# ... and no development, debug or sanitizer runtime package.
[[ "$depends" =~ -dev|-dbg|libasan|libtsan|libubsan ]] && fail "Depends names a build-only package"

[ -n "$(field Homepage)" ] || fail "no Homepage"
[[ "$(field Suggests)" == *python3-matplotlib* ]] || fail "Suggests lacks python3-matplotlib (the examples draw with it)"
[[ "$(field Suggests)" == *qt6-translations-l10n* ]] || fail "Suggests lacks qt6-translations-l10n (the standard dialogs' buttons in the GUI's language)"

if [ "$python" = ON ]; then
  recommends=$(field Recommends)
  echo "Recommends: $recommends"
  [[ "$recommends" == *python3-numpy* ]] || fail "Recommends lacks python3-numpy (the Python module imports it)"
fi

# --- install into a scratch root and look at it ---
root=$scratch/root
dpkg-deb --extract "$deb" "$root"
usr=$root/usr
bins=$(cd "$usr/bin" && ls | tr '\n' ' ')
expected_bins="elastic-lab-cli "
[ "$gui" = ON ] && expected_bins="elastic-lab elastic-lab-cli "
[ "$bins" = "$expected_bins" ] || fail "usr/bin holds '$bins', expected '$expected_bins'"
stray=$(cd "$root" && find . \( -name '*.a' -o -name '*.h' -o -name 'test_*' -o -name 'CMakeFiles' \) -print)
[ -z "$stray" ] || fail "build files in the package: $stray"

# Hardened and stripped as Debian's own packages are: immediate binding (bindnow) with full
# RELRO, fortified libc calls (__*_chk), no debug sections, no .comment section.
for bin in "$usr"/bin/* "$usr"/lib/python3/dist-packages/*.so; do
  [ -e "$bin" ] || continue
  name=${bin#"$root"}
  # (Each readelf's output is read whole first: grep -q quitting early would fail the pipe.)
  dynamic=$(readelf -d "$bin") segments=$(readelf -lW "$bin")
  grep -q 'FLAGS.*BIND_NOW\|FLAGS_1.*NOW' <<<"$dynamic" || fail "$name is not linked with -z now (bindnow)"
  grep -q 'GNU_RELRO' <<<"$segments" || fail "$name has no RELRO segment"
  sections=$(readelf -SW "$bin")
  grep -q '\.debug_' <<<"$sections" && fail "$name ships debug sections (not stripped)"
  grep -q ' \.comment ' <<<"$sections" && fail "$name ships a .comment section"
done
symbols=$(readelf --dyn-syms -W "$usr/bin/elastic-lab-cli")
grep -q '__[a-z]*_chk@' <<<"$symbols" || fail "elastic-lab-cli calls no fortified function (not built with _FORTIFY_SOURCE)"

# The installed CLI, from the scratch root, with a clean environment and its own working directory.
mkdir -m 700 "$scratch/runtime"
run_installed() { (cd "$scratch" && env -i PATH=/usr/bin:/bin HOME="$scratch" XDG_RUNTIME_DIR="$scratch/runtime" "$@"); }
out=$(run_installed "$usr/bin/elastic-lab-cli" --version) || fail "elastic-lab-cli --version failed"
[ "$out" = "elastic-lab-cli $version" ] || fail "elastic-lab-cli --version says '$out'"
run_installed "$usr/bin/elastic-lab-cli" run --scene ring2d --duration 0.05 --csv "$scratch/run.csv" >"$scratch/run.log" 2>&1 ||
  { cat "$scratch/run.log" >&2; fail "the installed elastic-lab-cli run failed"; }
# The CSV: a header with the documented columns, rows up to t = 0.05 s, finite energies.
header=$(head -n 1 "$scratch/run.csv")
[[ "$header" == step,t,dt,* ]] || fail "CSV header is '$header'"
awk -F, -v duration=0.05 '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i
            if (!("energy_total" in col) || !("volume_inner" in col)) { print "missing columns"; exit 1 }
            next }
  { rows++; t = $2 + 0; dt = $3 + 0; e = $(col["energy_total"]); v = $(col["volume_inner"])
    if (e !~ /^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/ || !(v + 0 > 0)) { print "bad row " NR ": " $0; exit 1 } }
  END { if (rows < 2) { print "only " rows " rows"; exit 1 }
        if (t < duration - 1e-12 || t > duration + dt) { print "last row at t = " t ", not " duration; exit 1 } }
' "$scratch/run.csv" || fail "the CSV of the installed run"
echo "run: $(($(wc -l <"$scratch/run.csv") - 1)) rows up to t = $(tail -n 1 "$scratch/run.csv" | cut -d, -f2)"

if [ "$python" = ON ]; then
  # The Python module from the unpacked tree (not the build tree's): a 1D spring for 0.05 s.
  # The package's python3 version is the Recommends' lower bound.
  python3_version=$(sed -n 's/.*python3 (>= \([0-9.]*\)).*/\1/p' <<<"$recommends")
  out=$(run_installed env PYTHONPATH="$usr/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 \
        "python$python3_version" -c '
import elasticlab, sys
assert elasticlab.__file__.startswith(sys.argv[1]), elasticlab.__file__
sim = elasticlab.Simulation("spring1d", integrator="rk4")
sim.run(0.05)
energy = sim.diagnostics["energy_total"]
assert sim.time >= 0.05 - 1e-12 and sim.step_count > 0 and energy == energy, (sim.time, sim.step_count, energy)
print(sim.step_count)' "$usr/") || fail "the installed Python module"
  echo "python: elasticlab from the package ran $out steps"
fi

if [ "$gui" = ON ]; then
  # --version needs no display (the GUI picks the offscreen platform for it).
  out=$(run_installed "$usr/bin/elastic-lab" --version) || fail "elastic-lab --version failed"
  [ "$out" = "elastic-lab $version" ] || fail "elastic-lab --version says '$out'"

  # Desktop entry, icon and metainfo: present, valid, and naming each other and the binary.
  desktop=$usr/share/applications/$app_id.desktop
  icon=$usr/share/icons/hicolor/scalable/apps/$app_id.svg
  metainfo=$usr/share/metainfo/$app_id.metainfo.xml
  for f in "$desktop" "$icon" "$metainfo"; do [ -s "$f" ] || fail "missing ${f#"$root"}"; done
  exec_bin=$(sed -n 's/^Exec=\([^ ]*\).*/\1/p' "$desktop")
  [ -x "$usr/bin/$exec_bin" ] || fail "the desktop entry runs '$exec_bin', which is not installed"
  [ "$(sed -n 's/^Icon=//p' "$desktop")" = "$app_id" ] || fail "the desktop entry's Icon is not $app_id"
  grep -q '<svg' "$icon" || fail "the icon is not an SVG"
  grep -q "<launchable type=\"desktop-id\">$app_id.desktop</launchable>" "$metainfo" ||
    fail "the metainfo does not launch $app_id.desktop"
  grep -q "<release version=\"$version\"" "$metainfo" || fail "the metainfo has no release $version"
  # Today's integrator count, the homepage and screenshots.
  count=$(run_installed "$usr/bin/elastic-lab-cli" integrators | wc -l)
  grep -q "<li>$count integrators" "$metainfo" || fail "the metainfo does not say $count integrators (elastic-lab-cli integrators)"
  grep -q '<url type="homepage">https\?://' "$metainfo" || fail "the metainfo has no homepage"
  [ "$(grep -c '<image>https\?://' "$metainfo")" -ge 1 ] || fail "the metainfo has no screenshot"
  # Scene files: the desktop entry takes a file (%f) of the lab's MIME type, whose definition
  # is installed and tells a scene file from other JSON by its content.
  grep -q '^Exec=elastic-lab %f$' "$desktop" || fail "the desktop entry's Exec takes no file (%f)"
  grep -q '^MimeType=application/x-elastic-lab-scene;$' "$desktop" || fail "the desktop entry names no scene MIME type"
  mime=$usr/share/mime/packages/$app_id.xml
  [ -s "$mime" ] || fail "missing ${mime#"$root"}"
  grep -q 'type="application/x-elastic-lab-scene"' "$mime" || fail "$mime does not define the scene type"
  if command -v update-mime-database >/dev/null; then
    # The type as a desktop's MIME database compiles it: a sub-class of JSON with a content
    # match on the scene files' first line, so it wins over the *.json glob for them only.
    mkdir -p "$scratch/xdg/mime/packages"
    cp "$mime" "$scratch/xdg/mime/packages/"
    update-mime-database "$scratch/xdg/mime" >"$scratch/mime.log" 2>&1 || { cat "$scratch/mime.log" >&2; fail "update-mime-database"; }
    grep -qx 'application/x-elastic-lab-scene application/json' "$scratch/xdg/mime/subclasses" ||
      fail "the scene type is not a sub-class of application/json"
    grep -aq '^\[80:application/x-elastic-lab-scene\]' "$scratch/xdg/mime/magic" || fail "the scene type has no content match"
    run_installed "$usr/bin/elastic-lab-cli" run --scene ring2d --duration 0.01 --quiet --save-scene "$scratch/saved.json" ||
      fail "save a scene file"
    start=$(head -c 64 "$scratch/saved.json" | tr -d '\n')
    grep -q '"format": "elastic-lab-scene"' <<<"$start" ||
      fail "a saved scene does not open with the \"format\" the content match looks for"
  else
    echo "scene MIME type not compiled: update-mime-database not found (Debian: shared-mime-info)"
  fi
  if [ -n "$desktop_validate" ]; then
    "$desktop_validate" "$desktop" || fail "desktop-file-validate"
  else
    echo "not validated: desktop-file-validate not found (Debian: desktop-file-utils)"
  fi
  if [ -n "$appstreamcli" ]; then
    "$appstreamcli" validate --no-net --strict "$metainfo" >"$scratch/appstream.log" 2>&1 ||
      { cat "$scratch/appstream.log" >&2; fail "appstreamcli validate"; }
  else
    echo "not validated: appstreamcli not found (Debian: appstream)"
  fi
fi

# Man pages: made from the binaries' own --help (an option only the help text names is there).
if [ "$man" = ON ]; then
  check_man() { # check_man NAME OPTION
    local page=$usr/share/man/man1/$1.1.gz
    [ -s "$page" ] || fail "missing ${page#"$root"}"
    gzip -t "$page" || fail "$1.1.gz is not gzip"
    zcat "$page" | grep -q "^\.TH \"\?${1^^}\"\? \"\?1\"\?" || fail "$1.1 has no .TH ${1^^} 1 line"
    zcat "$page" | grep -q -- "$2" || fail "$1.1 does not mention $2 (from --help)"
  }
  check_man elastic-lab-cli 'stability'
  # ... and the CLI's, each command's options (run's --duration, with its unit).
  zcat "$usr/share/man/man1/elastic-lab-cli.1.gz" | grep -q '^\.SS "run"' || fail "elastic-lab-cli.1 has no run command"
  zcat "$usr/share/man/man1/elastic-lab-cli.1.gz" | grep -q 'simulated time to run \[s\]' ||
    fail "elastic-lab-cli.1 lacks the description of run --duration"
  [ "$gui" = ON ] && check_man elastic-lab 'screenshot'
  # Nothing of the build machine in the pages: bench --threads says its default in words.
  page=$(zcat "$usr/share/man/man1/elastic-lab-cli.1.gz")
  threads=$(grep -A3 'fB\\-\\-threads' <<<"$page")
  grep -q 'all CPUs this process may use' <<<"$threads" ||
    fail "elastic-lab-cli.1: bench --threads does not say 'all CPUs this process may use'"
  grep -q '\[[0-9][0-9]*\]' <<<"$threads" && fail "elastic-lab-cli.1: bench --threads shows a number as its default: $threads"
fi

# The bash completion (app/cli), written by the tool from its command tree.
completion=$usr/share/bash-completion/completions/elastic-lab-cli
[ -s "$completion" ] || fail "missing ${completion#"$root"}"
grep -q 'complete .*elastic-lab-cli' "$completion" || fail "the completion does not complete elastic-lab-cli"
# What it offers, asked through bash itself: scene files after --scene, parameter keys after --set.
mkdir -p "$scratch/complete/sub"
touch "$scratch/complete/ball.json" "$scratch/complete/notes.txt"
completions() { # completions WORD...: what TAB offers for the last word
  (cd "$scratch/complete" && bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
     _elastic_lab_cli; printf "%s\n" "${COMPREPLY[@]}"' _ "$completion" elastic-lab-cli "$@")
}
offered=$(completions run --scene "")
grep -qx ball.json <<<"$offered" || fail "run --scene does not offer the scene file ball.json: $offered"
grep -qx notes.txt <<<"$offered" && fail "run --scene offers notes.txt (not a scene file)"
grep -qx ring2d <<<"$offered" || fail "run --scene does not offer the built-in scenes"
offered=$(completions run --set "k")
grep -qx 'ks=' <<<"$offered" || fail "run --set k does not offer ks=: $offered"
offered=$(completions run --csv-dialect "")
grep -qx 'excel-semicolon' <<<"$offered" || fail "run --csv-dialect does not offer excel-semicolon: $offered"

# Docs in the repository's layout: every relative link to a file in them resolves.
doc=$usr/share/doc/elastic-lab
[ -s "$doc/README.md" ] || fail "missing README.md in share/doc/elastic-lab"
[ -s "$doc/docs/architecture.md" ] || fail "missing docs/architecture.md in share/doc/elastic-lab"
grep -q "^License: GPL-3.0-or-later" "$doc/copyright" || fail "share/doc/elastic-lab/copyright has no licence"
changelog=$(zcat "$doc/changelog.gz" | head -n 1)
[ "$changelog" = "elastic-lab ($version) unstable; urgency=medium" ] || fail "changelog.gz begins '$changelog'"
if [ "$gui" = ON ]; then
  grep -q "<project_license>GPL-3.0-or-later</project_license>" "$usr/share/metainfo/$app_id.metainfo.xml" ||
    fail "the metainfo's licence is not the copyright file's"
fi
links=0
while IFS= read -r page; do
  while IFS= read -r target; do
    links=$((links + 1))
    [ -e "$(dirname "$page")/$target" ] || fail "${page#"$doc/"} links $target, which is not installed"
  done < <(grep -o '](\([A-Za-z0-9._/-]*\.\(md\|png\|svg\|csv\|txt\|py\)\)[)#]' "$page" | sed 's/^](//; s/[)#]$//')
done < <(find "$doc" -name '*.md')
[ "$links" -gt 0 ] || fail "no relative link found in the installed docs"
echo "docs: $links relative links resolve"
echo "test_package: passed"
