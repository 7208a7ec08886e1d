# Sourced by the suite's scripts, so that each answers --help and a wrong number of arguments
# the same way as the programs do: help on stdout with status 0, a one-line error with
# status 2 before anything is written.

# script_args MIN MAX "$@": with -h or --help first, prints the script's opening comment (its
# usage line among it) and exits 0; with fewer than MIN or more than MAX arguments (MAX "-":
# no limit) prints the usage line on stderr and exits 2.
script_args() {
  _sa_min=$1 _sa_max=$2
  shift 2
  case ${1-} in
  -h | --help)
    sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p;}' "$0"
    exit 0
    ;;
  esac
  if [ $# -lt "$_sa_min" ] || { [ "$_sa_max" != - ] && [ $# -gt "$_sa_max" ]; }; then
    echo "$(basename "$0"): wrong number of arguments ($#); usage: $(sed -n 's/^# usage: *//p' "$0" |
      head -n 1 | sed 's/   .*//') (--help)" >&2
    exit 2
  fi
}
