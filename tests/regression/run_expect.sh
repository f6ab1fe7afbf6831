#!/usr/bin/env bash
# run_expect.sh EXIT_STATUS REGEX [--mpi] -- COMMAND [ARGS...]
# Runs COMMAND and passes when it exits with EXIT_STATUS and, for a non-zero status, its stderr is
# exactly one line matching REGEX (Contessa's contract for bad input: one line, non-zero exit).
# With --mpi, mpiexec's own notice about the exit status is ignored: one line from contessa.
set -u
expected_status="$1"; regex="$2"; shift 2
mpi=0
[ "$1" = "--mpi" ] && { mpi=1; shift; }
[ "$1" = "--" ] && shift
stderr_file="$(mktemp)"
"$@" >/dev/null 2>"$stderr_file"
status=$?
if [ "$mpi" = 1 ]; then
  stderr="$(grep '^contessa' "$stderr_file")"
else
  stderr="$(cat "$stderr_file")"
fi
rm -f "$stderr_file"
if [ "$status" != "$expected_status" ]; then
  echo "FAIL: exit status $status, expected $expected_status; stderr:"; echo "$stderr"; exit 1
fi
if [ -n "$regex" ]; then
  lines="$(printf '%s' "$stderr" | grep -c '')"
  if [ "$lines" != "1" ]; then echo "FAIL: stderr has $lines lines, expected 1:"; echo "$stderr"; exit 1; fi
  if ! printf '%s' "$stderr" | grep -Eq -- "$regex"; then
    echo "FAIL: stderr does not match /$regex/:"; echo "$stderr"; exit 1
  fi
fi
echo "ok: exit $status${regex:+, stderr: $stderr}"
