#!/usr/bin/env bash
# Prints the Debian packages a built program needs at run time, one a line:
# those that ship the shared libraries it links directly (apt brings what
# they in turn need), and those that ship each FILE it reads (dlib's landmark
# model, OpenCV's face cascade). deploy/Dockerfile's build stage runs it and
# its runtime stage installs exactly this list, so the image follows the
# build's libraries by itself; tests/deploy runs it on the build's server.
#   runtime-packages.sh PROGRAM [FILE...]
set -euo pipefail

if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: runtime-packages.sh PROGRAM [FILE...] (PROGRAM: a built executable, e.g. build/bin/facewire-server)" >&2
  exit 2
fi
program=$1
shift

# The files to look up: each library the program names itself (NEEDED),
# where the loader finds it, and each FILE.
files=()
loader_map=$(ldd "$program")
while read -r library; do
  path=$(awk -v lib="$library" '$1 == lib && $2 == "=>" { print $3 }' <<<"$loader_map")
  if [ -z "$path" ] || [ "$path" = "not" ]; then
    echo "runtime-packages: $program needs $library, which the loader does not find" >&2
    exit 1
  fi
  files+=("$path")
done < <(objdump -p "$program" | awk '$1 == "NEEDED" { print $2 }')
for file in "$@"; do
  if [ ! -e "$file" ]; then
    echo "runtime-packages: $file is not here (install the package that ships it first)" >&2
    exit 1
  fi
  files+=("$file")
done

# Debian 12 merged /lib into /usr/lib, but packages still name some files by
# their old path (libc6: /lib/...): each file is looked up as given,
# resolved, and on the other side of the merge. One dpkg-query for them all
# (each reads every package's file list).
candidates() {
  local given=$1 resolved
  resolved=$(readlink -f "$given")
  printf '%s\n' "$given" "$resolved" "${given/#\/usr\/lib\//\/lib\/}" "${given/#\/lib\//\/usr\/lib\/}" \
    "${resolved/#\/usr\/lib\//\/lib\/}"
}
mapfile -t queries < <(for file in "${files[@]}"; do candidates "$file"; done | sort -u)
# "libssl3:amd64: /usr/lib/..." -> PATH<TAB>libssl3; diversions are not owners.
owners=$(dpkg-query -S "${queries[@]}" 2>/dev/null | grep -v '^diversion' |
         sed -E 's/^([^:,]+)(:[a-z0-9]+)?(, [^:,]+(:[a-z0-9]+)?)*: (.*)$/\5\t\1/' || true)

packages=()
for file in "${files[@]}"; do
  package=""
  while read -r candidate; do
    package=$(awk -F'\t' -v path="$candidate" '$1 == path { print $2; exit }' <<<"$owners")
    [ -n "$package" ] && break
  done < <(candidates "$file")
  if [ -z "$package" ]; then
    echo "runtime-packages: no installed package ships $file" >&2
    exit 1
  fi
  packages+=("$package")
done

printf '%s\n' "${packages[@]}" | sort -u
