#!/bin/sh
# Runs one libFuzzer target for a bounded time on a scratch copy of its seed
# corpus, so that the source tree stays clean. Fails on any crash, leak,
# time-out of one input or sanitizer report.
#   run_fuzzer.sh SECONDS BINARY CORPUS_DIR WORK_DIR [SEED_FILE...]
set -eu
seconds=$1 binary=$2 corpus=$3 work=$4
shift 4
rm -rf "$work"
mkdir -p "$work"
[ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
for seed in "$@"; do cp "$seed" "$work"/; done
exec "$binary" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 -print_final_stats=1 "$work"
