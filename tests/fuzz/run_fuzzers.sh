#!/bin/sh
# `make fuzz`: runs every fuzz target of a build for SECONDS each, one after
# the other, and stops at the first that finds something.
#   run_fuzzers.sh BUILD_DIR SECONDS
set -eu
build=$1 seconds=$2
here=$(dirname "$0")
found=0
for args in "$build"/fuzz/*.args; do
  [ -f "$args" ] || continue
  found=1
  echo "== $(basename "$args" .args), $seconds s"
  # shellcheck disable=SC2046 # the file holds one line of words
  sh "$here/run_fuzzer.sh" "$seconds" $(cat "$args")
done
[ "$found" = 1 ] || { echo "no fuzz targets in $build (is clang++ installed? run deploy/install-deps.sh)" >&2; exit 1; }
