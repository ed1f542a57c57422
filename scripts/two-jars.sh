# Sourced by the scripts that compare two builds (side-by-side.sh, side-by-side-perf.sh,
# separate-jvms.sh, speed-table.sh, compare-builds.sh):
#   two_jars USAGE MIN MAX "$@"
# stops with USAGE and exit status 2 unless MIN to MAX arguments were given (MAX empty: no limit),
# and with "no such jar" unless the first two name files.
two_jars() {
  local usage=$1 min=$2 max=$3
  shift 3
  if [[ $# -lt $min || ( -n $max && $# -gt $max ) ]]; then
    echo "usage: $0 $usage" >&2
    exit 2
  fi
  local jar
  for jar in "$1" "$2"; do
    [[ -f $jar ]] || { echo "$0: no such jar: $jar" >&2; exit 2; }
  done
}
