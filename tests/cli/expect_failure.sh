#!/bin/sh
# Runs a dynamap command line that must fail: checks its exit code and that stderr names
# what was wrong.  Usage: expect_failure.sh CODE TEXT COMMAND [ARGS...]
code="$1"; text="$2"; shift 2
err=$("$@" 2>&1 >/dev/null)
actual=$?
if [ "$actual" -ne "$code" ]; then
  echo "expected exit code $code, got $actual from: $*" >&2
  echo "$err" >&2
  exit 1
fi
case "$err" in
  *"$text"*) exit 0 ;;
esac
echo "expected \"$text\" in the error of: $*" >&2
echo "$err" >&2
exit 1
