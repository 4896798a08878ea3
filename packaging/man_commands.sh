#!/usr/bin/env bash
# man_commands.sh CLI OUTPUT: a help2man include file (OUTPUT) with a COMMANDS section made from
# `CLI COMMAND --help` for every command the tool's own --help lists (CLI11's layout: a line
# of description, "Usage: ...", then "Options:" with one option a line, the description from
# column 34 or on the lines below). help2man reads only the top-level --help; this puts each
# command's options, units and defaults in the man page too. Run at build time by
# packaging/CMakeLists.txt.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 CLI OUTPUT" >&2; exit 2; }
cli=$1 output=$2

commands=$("$cli" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } on && /^$/ { exit }')
[ -n "$commands" ] || { echo "$0: no commands in '$cli --help'" >&2; exit 1; }

# roff: a backslash is \e, a hyphen \-, a line may not start with . or '.
roff_awk='
function esc(s) { gsub(/\\/, "\\e", s); gsub(/-/, "\\-", s); return s }
function line(s) { if (s ~ /^[.'"'"']/) s = "\\&" s; print s }
NR == 1 { line(esc($0)); next }
/^Usage:/ { sub(/^Usage: */, ""); print ".PP"; line("\\fBUsage:\\fR " esc($0)); next }
/^Options:/ { options = 1; next }
options && /^  -/ {
  text = substr($0, 3)
  split(text, parts, /   */)                      # the option, then its description
  term = parts[1]; desc = substr(text, length(term) + 1); sub(/^ +/, "", desc)
  if (term ~ /(^|,)--help$/) { skip = 1; next }
  skip = 0
  flag = term; arg = ""
  if (index(term, " ")) { flag = substr(term, 1, index(term, " ") - 1); arg = substr(term, index(term, " ") + 1) }
  print ".TP"
  line("\\fB" esc(flag) "\\fR" (arg == "" ? "" : " \\fI" esc(arg) "\\fR"))
  if (desc != "") line(esc(desc))
  next
}
options && /^     / { if (!skip) { s = $0; sub(/^ +/, "", s); line(esc(s)) } next }
options && /^$/ { options = 0; footer = 1; next }
'
{
  echo "[COMMANDS]"
  for command in $commands; do
    echo ".SS \"$command\""
    # Each command's footer repeats the tool's (COMMAND --help, exit status): left out.
    "$cli" "$command" --help | awk '/^$/ && seen_options { exit } /^Options:/ { seen_options = 1 } { print }' | awk "$roff_awk"
  done
} >"$output.tmp"
mv "$output.tmp" "$output"
