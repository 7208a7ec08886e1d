#!/bin/sh
# Prints an ISA-specific kernel file for the single-file submission: its file-scope names get
# a prefix (two ISA files define the same static helpers) and its functions the file's target
# ISA through a pragma (the course builds with no -m flags).
# usage: amalgamate-isa.sh FILE PREFIX TARGET   e.g. src/kernel_simd_avx2.c avx2_ avx2
set -eu
file=$1 prefix=$2 target=$3
names=$(
  { # static functions, also when the name starts the line after "static ... type"
    awk '{ line = $0; gsub(/__attribute__\(\([^)]*\)\)/, "", line) }
         pending && match(line, /^[a-zA-Z_][a-zA-Z0-9_]*\(/) { print substr(line, 1, RLENGTH - 1) }
         { pending = 0 }
         /^static / { if (match(line, /[a-zA-Z_][a-zA-Z0-9_]*\(/)) print substr(line, RSTART, RLENGTH - 1);
                      else if (line !~ /[;{=]/) pending = 1 }' "$file"
    grep -oE '^} [a-zA-Z_][a-zA-Z0-9_]*;' "$file" | sed -E 's/^} (.*);/\1/'
    grep -oE '^enum \{ [a-zA-Z_][a-zA-Z0-9_]* =' "$file" | sed -E 's/^enum \{ (.*) =/\1/'
    grep -oE '^[A-Z_]+_STRIP\([a-zA-Z_][a-zA-Z0-9_]*,' "$file" | sed -E 's/^[A-Z_]+\((.*),/\1/'
  } | sort -u)
macros=$(grep -oE '^#define [A-Za-z_][A-Za-z0-9_]*' "$file" | sed 's/^#define //' | sort -u)
for n in $names; do printf '#define %s %s%s\n' "$n" "$prefix" "$n"; done
cat <<PRAGMA
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("$target"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("$target")
#endif
PRAGMA
grep -v '^#include' "$file"
cat <<PRAGMA
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
PRAGMA
for n in $names $macros; do printf '#undef %s\n' "$n"; done
