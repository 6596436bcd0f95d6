#!/bin/sh
# Prints the N slowest tests of a ctest log (ctest's own "k/n Test #i: name
# ... Passed 1.23 sec" lines), so that whoever reads CI's output sees where
# the time goes.
#   slowest_tests.sh LOG [N]
log=$1 count=${2:-20}
echo "The $count slowest tests of $(basename "$log" .log):"
awk '/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: / && $NF == "sec" {
       name = $4; sub(/\.+$/, "", name)
       printf "%s %s %s\n", $(NF - 1), name, $(NF - 2)
     }' "$log" |
  sort -rn | head -n "$count" | awk '{ printf "  %7.2f s  %s%s\n", $1, $2, ($3 == "Passed" ? "" : "  (" $3 ")") }'
