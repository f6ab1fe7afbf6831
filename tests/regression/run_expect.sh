#!/usr/bin/env bash
# run_expect.sh EXIT_STATUS REGEX [--mpi] -- COMMAND [ARGS...]
# Runs COMMAND and passes when it exits with EXIT_STATUS and, for a non-zero status, its stderr is
# exactly one line matching REGEX (Contessa's contract for bad input: one line, non-zero exit).
# Exit status 77 of COMMAND is passed on (a skipped test). With --mpi, mpiexec's own notice about the
# exit status is ignored: one line from contessa. A failure shows the end of COMMAND's stdout too.
set -u
expected_status="$1"; regex="$2"; shift 2
mpi=0
[ "$1" = "--mpi" ] && { mpi=1; shift; }
[ "$1" = "--" ] && shift
stderr_file="$(mktemp)"
stdout_file="$(mktemp)"
"$@" >"$stdout_file" 2>"$stderr_file"
status=$?
if [ "$mpi" = 1 ]; then
  stderr="$(grep '^contessa' "$stderr_file")"
else
  stderr="$(cat "$stderr_file")"
fi
rm -f "$stderr_file"
# 77: the command found it cannot run here (e.g. no permission to mount a file system); CTest reports
# the test as skipped when it has SKIP_RETURN_CODE 77.
if [ "$status" = 77 ] && [ "$expected_status" != 77 ]; then
  echo "skipped: $(cat "$stdout_file")"; rm -f "$stdout_file"; exit 77
fi
stdout_tail="$(tail -n 20 "$stdout_file")"
rm -f "$stdout_file"
if [ "$status" != "$expected_status" ]; then
  echo "FAIL: exit status $status, expected $expected_status; stderr:"; echo "$stderr"
  echo "stdout (end):"; echo "$stdout_tail"; exit 1
fi
if [ -n "$regex" ]; then
  lines="$(printf '%s' "$stderr" | grep -c '')"
  if [ "$lines" != "1" ]; then echo "FAIL: stderr has $lines lines, expected 1:"; echo "$stderr"; exit 1; fi
  if ! printf '%s' "$stderr" | grep -Eq -- "$regex"; then
    echo "FAIL: stderr does not match /$regex/:"; echo "$stderr"; exit 1
  fi
fi
echo "ok: exit $status${regex:+, stderr: $stderr}"
