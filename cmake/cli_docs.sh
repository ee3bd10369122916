#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Writes the man page ifsfx.1 and the bash completion of ifsfx from the built command itself:
# `ifsfx --help`, then `ifsfx COMMAND --help` for every subcommand that lists (and `ifsfx COMMAND
# SUBCOMMAND --help` for the subcommands a command lists), and the names
# `ifsfx presets` and `ifsfx presets --super` print. A new option or subcommand appears in both
# at the next build, with the text its --help gives.
#   sh cmake/cli_docs.sh IFSFX VERSION MAN_OUT COMPLETION_OUT
#
# CLI11's help layout, which `parse` reads: a description, a "Usage:" line, then sections whose
# title ends with ':' at the start of a line; an entry "  -x,--name TYPE=DEFAULT" padded to 30
# columns, its description from column 31 (or on the next line when the name is longer), and
# continued on lines indented by 30 spaces.
set -eu
ifsfx=$1 version=$2 man_out=$3 completion_out=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One help text as lines "KIND<TAB>TEXT[<TAB>TEXT]": D description, U usage (the program named
# ifsfx whatever path it was run by), S section title, E entry (spec, description), C the
# entry's description continued.
parse='
function rtrim(s) { sub(/ +$/, "", s); return s }
function balanced(s,  t) { t = s; return gsub(/\[/, "", t) == gsub(/\]/, "", s) && \
                           gsub(/\{/, "", t) == gsub(/\}/, "", s) }
BEGIN { OFS = "\t" }
/^Usage: / { usage = 1; u = substr($0, 8); sub(/^[^ ]*/, "ifsfx", u); print "U", u; next }
!usage { print "D", $0; next }
/^ *$/ { next }
/^[^ ].*:$/ { print "S", substr($0, 1, length($0) - 1); next }
/^                              / { print "C", substr($0, 31); next }
/^  [^ ]/ {
  head = substr($0, 1, 30)
  if (length($0) > 30 && substr($0, 30, 1) == " " && substr($0, 31, 1) != " " && balanced(head))
    print "E", rtrim(substr(head, 3)), substr($0, 31)
  else
    print "E", substr($0, 3), ""
  next
}
{ print "ifsfx help: unexpected line: " $0 > "/dev/stderr"; exit 1 }
'

"$ifsfx" --help >"$tmp/top.txt"
awk "$parse" "$tmp/top.txt" >"$tmp/top"
commands=$(awk -F '\t' '$1 == "S" { s = $2 } $1 == "E" && s == "Subcommands" { print $2 }' "$tmp/top" |
  awk '{ print $1 }')
[ -n "$commands" ] || { echo "cli_docs.sh: no subcommands in '$ifsfx --help'" >&2; exit 1; }
# A command's own subcommands (`ifsfx farm filter`, ...), by the name "COMMAND SUBCOMMAND", in
# $tmp/COMMAND.SUBCOMMAND: each gets its own man page section with its options.
subcommands_of() { awk -F '\t' '$1 == "S" { s = $2 } $1 == "E" && s == "Subcommands" { print $2 }' \
  "$tmp/$1" | awk '{ print $1 }'; }
for c in $commands; do
  "$ifsfx" "$c" --help >"$tmp/$c.txt"
  awk "$parse" "$tmp/$c.txt" >"$tmp/$c"
  for s in $(subcommands_of "$c"); do
    "$ifsfx" "$c" "$s" --help >"$tmp/$c.$s.txt"
    awk "$parse" "$tmp/$c.$s.txt" >"$tmp/$c.$s"
  done
done
# Shipped preset names: the first column of `ifsfx presets` and `ifsfx presets --super`.
"$ifsfx" presets >"$tmp/presets.txt"
"$ifsfx" presets --super >"$tmp/superpresets.txt"
presets=$(awk '{ printf "%s%s", sep, $1; sep = " " }' "$tmp/presets.txt")
superpresets=$(awk '{ printf "%s%s", sep, $1; sep = " " }' "$tmp/superpresets.txt")

# ---- the man page -------------------------------------------------------------------------------
# roff: a backslash is \e, a minus sign \- (a plain - may print as a hyphen, which a shell does
# not take for an option), and a line may not start with . or '.
roff='
function roff(s) { gsub(/\\/, "\\e", s); gsub(/-/, "\\-", s); if (s ~ /^[.'"'"']/) s = "\\&" s
                   return s }
function spec(s,  name, rest, n, parts, i, out) {
  name = s; rest = ""
  if (match(s, / /)) { name = substr(s, 1, RSTART - 1); rest = substr(s, RSTART + 1) }
  n = split(name, parts, ",")
  for (i = 1; i <= n; i++) out = out (i > 1 ? ", " : "") "\\fB" roff(parts[i]) "\\fR"
  if (rest != "") out = out " \\fI" roff(rest) "\\fR"
  return out
}
# title: the command whose help this is ("" for the top-level help; "COMMANDS" for the list of
# subcommands of the top-level help). A command'"'"'s own -h/--help-all are said once, at the top.
# A command that has subcommands of its own (farm) lists them, each then with its own section.
function wanted(s) {
  if (title == "COMMANDS") return section == "Subcommands"
  if (title == "") return section != "Subcommands"
  return s != "-h,--help" && s != "--help-all"
}
# A section title is printed with its first wanted entry: none for a section of -h alone.
function heading() { if (pending != "") { print ".PP"; print "\\fI" roff(pending) ":\\fR" }
                     pending = "" }
BEGIN { FS = "\t" }
title == "COMMANDS" && $1 == "E" && wanted($2) { split($2, w, " "); print ".TP"
                                                 print "\\fB" roff(w[1]) "\\fR" }
title == "COMMANDS" && ($1 == "E" && $3 != "" || $1 == "C") && wanted(last) { print roff($NF) }
title == "COMMANDS" { if ($1 == "S") section = $2; if ($1 == "E") last = $2; next }
$1 == "D" && $2 != "" { print roff($2) }
$1 == "U" && title != "" { print ".PP"; print "Usage: \\fB" roff($2) "\\fR" }
$1 == "S" { section = $2 }
$1 == "S" && title != "" { pending = $2 }
$1 == "S" && title == "" && $2 == "Options" { print ".SH OPTIONS" }
$1 == "E" { last = $2 }
$1 == "E" && wanted($2) { heading(); print ".TP"; print spec($2); if ($3 != "") print roff($3) }
$1 == "C" && wanted(last) { print roff($2) }
'
roff_lines() { awk -v title="$2" "$roff" "$1"; }
escape() { sed -e 's/\\/\\e/g' -e 's/-/\\-/g' -e "s/^\\([.']\\)/\\\\\&\\1/" "$@"; }

{
  printf '.\\" -*- coding: UTF-8 -*-\n'  # the preset descriptions have é and √: man runs preconv
  printf '.TH IFSFX 1 "" "ifsfx %s" "User Commands"\n' "$version"
  printf '.SH NAME\nifsfx \\- turn images and video into fractals\n'
  printf '.SH SYNOPSIS\n.B ifsfx\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR] [\\fIARGUMENTS\\fR]\n'
  printf '.SH DESCRIPTION\n'
  roff_lines "$tmp/top" ""
  printf '.SH COMMANDS\n'
  roff_lines "$tmp/top" COMMANDS
  for c in $commands; do
    printf '.SS %s\n' "$c"
    roff_lines "$tmp/$c" "$c"
    for s in $(subcommands_of "$c"); do
      printf '.SS "%s %s"\n' "$c" "$s"
      roff_lines "$tmp/$c.$s" "$c $s"
    done
  done
  printf '.SH PRESETS\n'
  printf 'The shipped IFS presets (\\fBifsfx presets\\fR):\n.PP\n.nf\n'
  escape "$tmp/presets.txt"
  printf '.fi\n.PP\nThe shipped superIFS presets (\\fBifsfx presets \\-\\-super\\fR):\n.PP\n.nf\n'
  escape "$tmp/superpresets.txt"
  printf '.fi\n.PP\n'
  printf 'They are built into the program. Copies of their files are installed in\n'
  printf '\\fIshare/ifsfx/presets/\\fR under the installation prefix (\\fI/usr\\fR for the Debian\n'
  printf 'package), as examples to copy and change; a path given on the command line reads such a file.\n'
  printf '.SH ENVIRONMENT\n.TP\n\\fBIFSFX_CPU\\fR=\\fBscalar\\fR|\\fBavx2\\fR|\\fBavx512\\fR\n'
  printf 'The kernel level (SIMD instruction set) of the chaos-game kernels. Unset, the best level\n'
  printf 'this CPU supports is chosen at start; \\fBifsfx info\\fR says which. Every level gives the\n'
  printf 'same pixels: forcing one is for tests, timings and bug reports. A level this CPU lacks, or\n'
  printf 'another word, is refused with an error.\n'
  printf '.SH EXIT STATUS\n'
  printf '0 on success, 1 on a failure, 2 for a bad command line or bad input file, 130 when\n'
  printf 'interrupted. Errors are one line on standard error starting with \\fBifsfx:\\fR.\n'
  printf '.SH SEE ALSO\n\\fBffmpeg\\fR(1), \\fBoiiotool\\fR(1)\n'
} >"$tmp/ifsfx.1"

# ---- the bash completion ------------------------------------------------------------------------
# Per command: its options, those that take a value (a type follows the name), the choices of
# {a,b} options, and the options whose description says they take a shipped (super)preset name.
options='
function flush(  n, w, k, names, i, kind) {
  if (spec == "") return
  if (section == "Positionals") {
    if (positional == "") {
      positional = "files"
      if (text ~ /shipped name/) positional = (text ~ /[Ss]uper[Ii][Ff][Ss]/) ? "superpreset" : "preset"
      print "positional", positional
    }
  } else if (section != "Subcommands") {
    n = split(spec, w, " "); k = split(w[1], names, ",")
    for (i = 1; i <= k; i++) print "option", names[i]
    if (n > 1) for (i = 1; i <= k; i++) {
      kind = "value"
      if (match(w[2], /\{[^}]*\}/)) kind = "choice " substr(w[2], RSTART + 1, RLENGTH - 2)
      else if (text ~ /shipped name/) kind = (text ~ /[Ss]uper[Ii][Ff][Ss]/) ? "superpreset" : "preset"
      print kind, names[i]
    }
  }
  spec = ""
}
BEGIN { FS = "\t" }
$1 == "S" { flush(); section = $2 }
$1 == "E" { flush(); spec = $2; text = $3 }
$1 == "C" { text = text " " $2 }
END { flush() }
'
{
  printf '# bash completion for ifsfx %s: its commands, their options, the choices of options\n' \
    "$version"
  printf '# that have them and the shipped preset names. Generated by cmake/cli_docs.sh from\n'
  printf "# 'ifsfx --help' and 'ifsfx COMMAND --help' at build time: do not edit.\n\n"
  printf '_ifsfx_presets="%s"\n' "$presets"
  printf '_ifsfx_superpresets="%s"\n\n' "$superpresets"
  printf '_ifsfx() {\n'
  printf '  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n'
  printf '  local command="" i\n'
  printf '  for ((i = 1; i < COMP_CWORD; i++)); do\n'
  printf '    case ${COMP_WORDS[i]} in -*) ;; *) command=${COMP_WORDS[i]}; break ;; esac\n'
  printf '  done\n'
  printf '  local options="" words="" files=1\n'
  printf '  case $command in\n'
  printf '    "") options="%s" words="%s" files=0 ;;\n' \
    "$(awk "$options" "$tmp/top" | awk '$1 == "option" { printf "%s%s", s, $2; s = " " }')" \
    "$(echo $commands)"
  for c in $commands; do
    awk "$options" "$tmp/$c" >"$tmp/$c.options"
    printf '    %s)\n' "$c"
    printf '      options="%s"\n' "$(awk '$1 == "option" { printf "%s%s", s, $2; s = " " }' \
      "$tmp/$c.options")"
    printf '      case $prev in\n'
    awk '$1 == "choice" { gsub(/,/, " ", $2); printf "        %s) words=\"%s\" files=0 ;;\n", $3, $2 }
         $1 == "preset" { printf "        %s) words=$_ifsfx_presets ;;\n", $2 }
         $1 == "superpreset" { printf "        %s) words=$_ifsfx_superpresets ;;\n", $2 }' \
      "$tmp/$c.options"
    values=$(awk '$1 == "value" { printf "%s%s", s, $2; s = "|" }' "$tmp/$c.options")
    [ -z "$values" ] || printf '        %s) ;;\n' "$values"
    printf '        *)\n'
    printf '          [[ $cur == -* ]] && { COMPREPLY=($(compgen -W "$options" -- "$cur")); return; }\n'
    case $(awk '$1 == "positional" { print $2 }' "$tmp/$c.options") in
      preset) printf '          words=$_ifsfx_presets ;;\n' ;;
      superpreset) printf '          words=$_ifsfx_superpresets ;;\n' ;;
      *) printf '          ;;\n' ;;
    esac
    printf '      esac ;;\n'
  done
  printf '  esac\n'
  printf '  if [[ -z $command && $cur == -* ]]; then\n'
  printf '    COMPREPLY=($(compgen -W "$options" -- "$cur"))\n'
  printf '  else\n'
  printf '    COMPREPLY=($(compgen -W "$words" -- "$cur"))\n'
  printf '    ((files)) && COMPREPLY+=($(compgen -f -- "$cur"))\n'
  printf '  fi\n'
  printf '}\n'
  printf 'complete -o filenames -F _ifsfx ifsfx\n'
} >"$tmp/ifsfx.bash"

mkdir -p "$(dirname "$man_out")" "$(dirname "$completion_out")"
mv "$tmp/ifsfx.1" "$man_out"
mv "$tmp/ifsfx.bash" "$completion_out"
