#!/bin/sh
# Runs one libFuzzer target for a bounded time on a scratch copy of its seed
# corpus, so that the source tree stays clean. Fails on any crash, leak,
# time-out of one input or sanitizer report.
#   run_fuzzer.sh [--keep] SECONDS BINARY CORPUS_DIR WORK_DIR [SEED_FILE...]
# --keep: WORK_DIR keeps what earlier runs found and this one goes on from
# there (make fuzz); without it, each run starts from the seeds alone (ctest).
# With FW_FUZZ_SEEDS_MUST_READ set (fw_fuzz_target's SEEDS_MUST_READ), each
# seed of the repository first runs once with it set, and a seed the code
# refuses fails the run (seed_check.hpp). What it finds goes next to
# WORK_DIR (WORK_DIR-crash-..., -leak-..., -timeout-...), never into the
# current directory.
set -eu
keep=0
if [ "$1" = --keep ]; then keep=1; shift; fi
seconds=$1 binary=$2 corpus=$3 work=$4
shift 4
[ "$keep" = 1 ] || rm -rf "$work"
mkdir -p "$work"
[ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
for seed in "$@"; do cp "$seed" "$work"/; done
if [ -n "${FW_FUZZ_SEEDS_MUST_READ:-}" ]; then
  [ -d "$corpus" ] && set -- "$@" "$corpus"/*
  echo "== the $# seeds of the repository must read"
  [ $# -eq 0 ] || "$binary" -artifact_prefix="${work%/}-" "$@"
  unset FW_FUZZ_SEEDS_MUST_READ
fi
exec "$binary" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 -print_final_stats=1 \
  -artifact_prefix="${work%/}-" "$work"
