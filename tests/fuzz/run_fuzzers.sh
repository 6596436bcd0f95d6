#!/bin/sh
# `make fuzz`: runs every fuzz target of a build (or those named) for
# SECONDS each, one after the other, and stops at the first that finds
# something. Each target goes on from the corpus its earlier runs grew, in
# BUILD_DIR/fuzz/NAME-grown, never in the source tree (tests/README.md says
# how to fold what it found into the seeds, when you want them to keep it).
#   run_fuzzers.sh BUILD_DIR SECONDS [NAME...]
set -eu
build=$1 seconds=$2
shift 2
names="$*"
here=$(dirname "$0")
found=0
for args in "$build"/fuzz/*.args; do
  [ -f "$args" ] || continue
  name=$(basename "$args" .args)
  if [ -n "$names" ]; then
    case " $names " in *" $name "*) ;; *) continue ;; esac
  fi
  found=1
  echo "== $name, $seconds s"
  # One line: BINARY CORPUS_DIR WORK_DIR [SEED_FILE...] (fuzz_target.cmake).
  # shellcheck disable=SC2046 # words without spaces: the build's own paths
  set -- $(cat "$args")
  binary=$1 corpus=$2
  shift 3
  sh "$here/run_fuzzer.sh" --keep "$seconds" "$binary" "$corpus" "$build/fuzz/$name-grown" "$@"
done
[ "$found" = 1 ] || { echo "no fuzz target ${names:+named $names }in $build (is clang++ installed? run deploy/install-deps.sh)" >&2; exit 1; }
