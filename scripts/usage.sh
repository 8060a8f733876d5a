# Sourced by the shell scripts beside it, before they do anything:
#   usage_check ALLOWED COUNT "$@"
# -h or --help prints the script's header comment (its usage) and exits 0; an
# option not matching ALLOWED (a |-separated list of regular expressions, empty
# for none) or more than COUNT other arguments is refused in one line on stderr,
# exit 2. (Without it, a script that reads no arguments ran its whole job on a
# mistyped one, and `--help` started minutes of meshing.)
usage_print() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
}

usage_check() {
  local allowed=$1 most=$2 count=0 arg
  shift 2
  for arg in "$@"; do
    case $arg in -h | --help) usage_print; exit 0 ;; esac
  done
  for arg in "$@"; do
    if [[ $arg == -* ]]; then
      if [[ -z $allowed || ! $arg =~ ^($allowed)$ ]]; then
        echo "$(basename "$0"): no option $arg (--help says what it takes)" >&2
        exit 2
      fi
    else
      count=$((count + 1))
      if ((count > most)); then
        echo "$(basename "$0"): one argument too many: $arg (--help says what it takes)" >&2
        exit 2
      fi
    fi
  done
}
