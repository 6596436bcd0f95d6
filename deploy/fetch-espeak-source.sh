#!/usr/bin/env bash
# Fetches Debian's source of espeak-ng, checks it, and unpacks it where the
# build looks for it (cmake/espeak_source.cmake): the browser's read-aloud
# module (avatar/speech/wasm) compiles these C sources with emscripten.
# Idempotent: nothing is fetched when the unpacked tree is there.
#
# The version: the server links Debian 12's libespeak-ng 1.51, but Debian's
# archive no longer holds 1.51's orig tarball (only its .dsc and patches), so
# this takes the next release Debian ships, 1.52.0 (trixie's 1.52.0+dfsg-5).
# Its engine reads the same data format (phoneme data version 1.48.01), and
# the browser is given the server's own 1.51 voice data: web/README.md says
# what the difference measures. The .dsc is pinned by its sha256 below; the
# tarball is checked against the sha256 the .dsc gives.
#   FW_DEPS_CACHE  where to unpack (default ~/.cache/facewire)
set -euo pipefail

archive=http://deb.debian.org/debian/pool/main/e/espeak-ng
dsc=espeak-ng_1.52.0+dfsg-5.dsc
dsc_sha256=8d79bd4d12db56461ff02f7e7a4ba78b6c37b3c4cdbceefcf75cd76029883680
orig=espeak-ng_1.52.0+dfsg.orig.tar.gz
tree=espeak-ng-1.52.0+dfsg
cache=${FW_DEPS_CACHE:-$HOME/.cache/facewire}

if [ -f "$cache/$tree/src/libespeak-ng/speech.c" ]; then
  echo "fetch-espeak-source: $cache/$tree present"
  exit 0
fi
command -v curl >/dev/null || { echo "fetch-espeak-source: curl is missing; run deploy/install-deps.sh" >&2; exit 1; }
mkdir -p "$cache"
work=$(mktemp -d "$cache/fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT

fetch() {
  curl -fsS --retry 3 --max-time 300 -o "$work/$1" "$archive/$1" ||
    { echo "fetch-espeak-source: could not fetch $archive/$1 (is deb.debian.org reachable?)" >&2; exit 1; }
}
fetch "$dsc"
echo "$dsc_sha256  $work/$dsc" | sha256sum -c --quiet - ||
  { echo "fetch-espeak-source: $dsc is not the one this script pins (sha256 differs); refusing it" >&2; exit 1; }
fetch "$orig"
# The .dsc lists "sha256 size name" under Checksums-Sha256.
orig_sha256=$(awk '/^Checksums-Sha256:/ {on = 1; next} /^[^ ]/ {on = 0} on && $3 == name {print $1}' name="$orig" "$work/$dsc")
[ -n "$orig_sha256" ] || { echo "fetch-espeak-source: $dsc names no sha256 for $orig" >&2; exit 1; }
echo "$orig_sha256  $work/$orig" | sha256sum -c --quiet - ||
  { echo "fetch-espeak-source: $orig does not match the sha256 in $dsc; refusing it" >&2; exit 1; }
tar -xzf "$work/$orig" -C "$work"
rm -rf "${cache:?}/$tree"
mv "$work/$tree" "$cache/$tree"
echo "fetch-espeak-source: unpacked $orig into $cache/$tree"
