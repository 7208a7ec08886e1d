# Sourced by the CLI tests that count their failures (tests/*_cli.sh, skip_columns.sh): a
# scratch folder removed at exit, and fail() to report one failure and go on. The test ends
# with `[ "$fails" -eq 0 ]`.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
