#!/usr/bin/env bash
# changelog.sh METAINFO MAINTAINER OUTPUT: the Debian changelog (gzipped, in OUTPUT) made from
# the releases of the AppStream metainfo, the one history of versions: an entry per <release>,
# newest first, its <p> and <li> lines as the entry's items, dated by the release's date (not
# the clock). Each <p> or <li> of a release's description must be on one line. Run at build
# time by packaging/CMakeLists.txt; a release without a description is refused.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 METAINFO MAINTAINER OUTPUT" >&2; exit 2; }
metainfo=$1 maintainer=$2 output=$3
trap 'rm -f "$output.tmp"' EXIT

awk '
  /<release / {
    version = $0; sub(/.*version="/, "", version); sub(/".*/, "", version)
    date = $0; sub(/.*date="/, "", date); sub(/".*/, "", date)
    printf "R\t%s\t%s\n", version, date
    if ($0 ~ /\/>[ \t]*$/) print "E"                  # <release .../>: no description
    next
  }
  /<\/release>/ { print "E"; next }
  /<(p|li)>.*<\/(p|li)>/ {
    text = $0; sub(/^[ \t]*<(p|li)>/, "", text); sub(/<\/(p|li)>[ \t]*$/, "", text)
    printf "T\t%s\n", text
  }
' "$metainfo" | {
  entries=0
  while IFS=$'\t' read -r kind a b; do
    case $kind in
      R) version=$a date=$b items=0
         printf 'elastic-lab (%s) unstable; urgency=medium\n\n' "$version" ;;
      T) [ -n "${version:-}" ] || continue
         printf '%s\n' "$a" | fold -s -w 76 | sed 's/ *$//; 1s/^/  * /; 2,$s/^/    /'
         items=$((items + 1)) ;;
      E) [ "$items" -gt 0 ] || { echo "$0: release $version has no <p> or <li> line" >&2; exit 1; }
         printf '\n -- %s  %s\n\n' "$maintainer" "$(LC_ALL=C TZ=UTC date -R -d "$date")"
         entries=$((entries + 1)) version="" ;;
    esac
  done
  [ "$entries" -gt 0 ] || { echo "$0: no <release> in $metainfo" >&2; exit 1; }
} | sed '$d' | gzip -9n >"$output.tmp"
mv "$output.tmp" "$output"
