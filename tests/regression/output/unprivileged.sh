#!/bin/sh
# unprivileged.sh COMMAND [ARGS...]: runs COMMAND as an ordinary user. Root may write into any
# directory, so a test of an unwritable directory run by root runs COMMAND as nobody (setpriv). Exit
# status 77 (skipped) when nobody cannot run COMMAND here (a build directory only its owner may read).
if [ "$(id -u)" != 0 ]; then exec "$@"; fi
as_nobody="setpriv --reuid=65534 --regid=65534 --clear-groups"
for program in "$@"; do
  case "$program" in
    /*) if [ -x "$program" ] && ! $as_nobody test -x "$program"; then
          echo "user nobody cannot run $program"; exit 77
        fi ;;
  esac
done
exec $as_nobody "$@"
