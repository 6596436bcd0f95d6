#!/bin/sh
# Prints the N slowest tests of a ctest log (ctest's own "Test #k: name ...
# Passed 1.23 sec" lines), so that whoever reads CI's output sees where the
# time goes.
#   slowest_tests.sh LOG [N]
log=$1 count=${2:-20}
echo "The $count slowest tests of $(basename "$log" .log):"
sed -n 's/^ *[0-9]*\/[0-9]* Test *#[0-9]*: \([^ ]*\) \.*[^0-9]*\([0-9.]*\) sec$/\2 \1/p' "$log" |
  sort -rn | head -n "$count" | awk '{ printf "  %7.2f s  %s\n", $1, $2 }'
