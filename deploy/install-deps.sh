#!/usr/bin/env bash
# Installs every Debian 12 package facewire needs to build, run and test.
# Idempotent: packages already present are skipped, and `apt-get update` runs
# at most once, only when something is missing.
#   --build-only  only what building needs, not what the test suites run
#                 (deploy/Dockerfile's build stage)
set -euo pipefail

build_only=false
case "${1:-}" in
  "") ;;
  --build-only) build_only=true ;;
  *) echo "install-deps: unknown option '$1' (the one option is --build-only)" >&2; exit 2 ;;
esac

# Build toolchain and the C++ libraries the modules link.
build_packages=(
  build-essential cmake pkg-config git
  ccache                                      # compiler cache: warm CI builds in minutes
  ninja-build mold                            # build tool and linker: builds and links in less time
  libboost-dev libboost-system-dev            # Asio + Beast (server, client)
  libopencv-dev opencv-data                   # photo preparation
  libglm-dev                                  # vector maths (model, physics)
  libeigen3-dev                               # sparse LDL^T factorisation (physics' projective solver)
  libosmesa6-dev libgl-dev mesa-utils         # offscreen GL renderer (llvmpipe)
  libpng-dev libwebp-dev zlib1g-dev           # image members of avatar packages
  libjpeg-dev                                 # photos: decoded by the server, downsized by the client
  libdlib-dev libdlib-data                    # face detector + 68-landmark model
  nlohmann-json3-dev libcli11-dev libspdlog-dev
  libicu-dev                                  # display names: NFC and character classes
  libgtest-dev libgmock-dev googletest
  libhiredis-dev                              # Redis client (cluster mode)
  libcgal-dev                                 # constrained triangulation in the face generator
  libespeak-ng-dev                            # speech timing and audio for lip-sync (avatar/speech)
  emscripten                                  # avatar/model to WebAssembly for the browser (web/engine)
  curl                                        # Debian's espeak-ng source for the browser's read aloud (below)
)
# What the test suites run besides ctest.
test_packages=(
  clang libclang-rt-14-dev                    # the sanitizer build, libFuzzer targets
  chromium chromium-driver                    # browser end-to-end tests
  ffmpeg                                      # recorded room videos
  redis-server                                # cluster tests against real Redis
  python3
  python3-yaml                                # tests/deploy: the compose and Kubernetes files parse
)
if $build_only; then test_packages=(); fi

missing=()
# Node.js may come from another source than Debian (with its own npm): only
# ask Debian for it when the commands are absent.
command -v node >/dev/null || missing+=(nodejs)
$build_only || command -v npm >/dev/null || missing+=(npm)
for pkg in "${build_packages[@]}" "${test_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

# Besides packages, the build compiles espeak-ng's C sources to WebAssembly
# for the browser's read aloud (avatar/speech/wasm): Debian's source,
# fetched and checked by its own script, into a cache the build knows.
fetch_espeak_source() { bash "$(dirname "$0")/fetch-espeak-source.sh"; }

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#build_packages[@]}+${#test_packages[@]} packages present"
  fetch_espeak_source
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo; missing: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fetch_espeak_source
