#!/bin/sh
# Writes help2man's include file for the retro man page: scripts/retro.h2m, then a COMMANDS
# section with every subcommand's own --help, so the page documents every option.
# usage: man-include.sh RETRO > retro.h2m
set -eu
. "$(dirname "$0")/usage.sh"
script_args 1 1 "$@"
retro=$1
cat scripts/retro.h2m
printf '\n[COMMANDS]\n'
for cmd in render fly kernels verify genmap accuracy; do
  printf '.SS "retro %s"\n.nf\n' "$cmd"
  # roff: backslashes doubled, a leading . or ' protected.
  "$retro" "$cmd" --help | sed -e 's/\\/\\\\/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
  printf '.fi\n'
done
