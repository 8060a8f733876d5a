#!/usr/bin/env bash
# The scripts read their arguments before they do anything: `--help` prints the
# script's usage (exit 0), a mistyped option is refused in one line (exit 2).
# Each call is bounded by a timeout: a script that ignored its arguments would
# otherwise start its whole job (a build, minutes of meshing).
#   tests/scripts/script_arguments.sh REPO
set -uo pipefail
repo=${1:?usage: script_arguments.sh REPO}
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

check_help() {  # check_help NAME COMMAND...: --help prints a usage of two lines or more
  local name=$1 out rc
  shift
  out=$(timeout 20 "$@" --help 2>/dev/null); rc=$?
  [ "$rc" -eq 0 ] || fail "$name --help: exit $rc, not 0"
  [ "$(printf '%s\n' "$out" | wc -l)" -ge 2 ] || fail "$name --help: no usage printed"
}

check() {  # check NAME COMMAND...: --help, and --no-such-option refused naming it
  local name=$1 err rc
  check_help "$@"
  shift
  err=$(timeout 20 "$@" --no-such-option 2>&1 >/dev/null); rc=$?
  [ "$rc" -eq 2 ] || fail "$name --no-such-option: exit $rc, not 2"
  printf '%s\n' "$err" | grep -q -- "--no-such-option" || fail "$name --no-such-option: the error does not name it: $err"
}

for name in check-embed cost-table demo forms-table fuzz mesh-table modes-table parts-check setup-deps test \
            same-quads svg-to-png verdict-check cluster/test-slurm; do
  check "$name" bash "$repo/scripts/$name"
done
for name in scan-cuts check-links readme-block bench-vs-gmsh plate-sweep; do
  check "$name" python3 "$repo/scripts/$name"
done
# the scripts that pass their arguments on (to CMake, to CTest, to quadmesh batch)
# still print their usage
for name in build sanitize cluster/parallel-hosts cluster/slurm-run; do
  check_help "$name" bash "$repo/scripts/$name"
done
# one argument more than a script takes is refused too
err=$(timeout 20 bash "$repo/scripts/demo" extra 2>&1 >/dev/null); rc=$?
[ "$rc" -eq 2 ] && printf '%s\n' "$err" | grep -q "extra" || fail "demo extra: exit $rc: $err"
# a job scan-cuts does not have is refused before any file is written
tmp=$(mktemp -d)
timeout 20 python3 "$repo/scripts/scan-cuts" "$tmp/out" no-such-job >/dev/null 2>&1; rc=$?
[ "$rc" -eq 2 ] || fail "scan-cuts no-such-job: exit $rc, not 2"
[ ! -e "$tmp/out" ] || fail "scan-cuts no-such-job: wrote $tmp/out"
rm -rf "$tmp"
[ "$failures" -eq 0 ] && echo "script arguments: every check passed"
exit $((failures > 0))
