# The two commands of the README, plus a few conveniences.
#   make run   install what is missing, build Release, start the server
#   make test  install what is missing, build, run every test suite
SHELL := /bin/bash
JOBS ?= $(shell nproc)
# Tests run two per core: most wait on sockets and timers; a test that keeps
# a core busy says so and takes two places (tests/CMakeLists.txt, CORES).
TEST_JOBS ?= $(shell echo $$(( 2 * $$(nproc) )))
SERVER_ARGS ?=
FUZZ_SECONDS ?= 300
FUZZ_TARGETS ?=

# The compiler cache (every preset compiles through ccache) keys on paths
# relative to the clone, so that another clone of the same tree hits it too.
export CCACHE_BASEDIR := $(CURDIR)
export CCACHE_NOHASHDIR := true
# Precompiled headers (cmake/fast_build.cmake) are cached too; ccache asks
# for these sloppiness settings before it caches a file that uses one.
export CCACHE_SLOPPINESS := pch_defines,time_macros,include_file_mtime,include_file_ctime

.PHONY: all deps build run test test-asan fuzz bench facegen clean

all: build

deps:
	@bash deploy/install-deps.sh

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

run: build
	./build/bin/facewire-server serve --tcp 127.0.0.1:8081 $(SERVER_ARGS)

# The browser tests' playwright-core (it drives Debian's chromium; no browser
# is downloaded), installed exactly as tests/web/package-lock.json pins it,
# and again only when the lock file changes. Only `make test` needs it.
WEB_TEST_DEPS := tests/web/node_modules/.package-lock.json
$(WEB_TEST_DEPS): tests/web/package.json tests/web/package-lock.json | deps
	npm ci --prefix tests/web --no-audit --no-fund
	@touch $@

# Every suite; the log is kept so that the slowest tests can be listed.
test: build $(WEB_TEST_DEPS)
	@mkdir -p build/logs
	ctest --preset release-all -j $(TEST_JOBS) 2>&1 | tee build/logs/release-tests.log; \
	  status=$${PIPESTATUS[0]}; sh tests/slowest_tests.sh build/logs/release-tests.log 20; exit $$status

# The quick suites under AddressSanitizer + UndefinedBehaviorSanitizer, with
# assertions on.
test-asan: deps
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	@mkdir -p build-asan/logs
	ctest --preset asan -j $(TEST_JOBS) 2>&1 | tee build-asan/logs/asan-tests.log; \
	  status=$${PIPESTATUS[0]}; sh tests/slowest_tests.sh build-asan/logs/asan-tests.log 20; exit $$status

# Every fuzz target (or those FUZZ_TARGETS names) for FUZZ_SECONDS each,
# going on from what earlier runs found (build/fuzz/NAME-grown); make test
# runs each briefly from its seeds alone.
# They are built with -O1 for it (tests/fuzz/fuzz_target.cmake, FW_FUZZ_OPTIMIZE).
fuzz: deps
	cmake --preset release -DFW_FUZZ_OPTIMIZE=ON
	cmake --build --preset release -j $(JOBS)
	sh tests/fuzz/run_fuzzers.sh build $(FUZZ_SECONDS) $(FUZZ_TARGETS)

bench: build
	./build/bin/facewire-bench render --json
	./build/bin/facewire-bench prep --json

# Regenerates the generic face asset after a change to the generator.
facegen: build
	./build/bin/facewire-facegen -o avatar/model/assets/generic_face.json
	./build/bin/facewire-aubasis -i avatar/model/assets/generic_face.json -o avatar/model/assets/generic_face.json
	./build/bin/facewire-correctives -i avatar/model/assets/generic_face.json -o avatar/model/assets/generic_face.json \
	  --fitting avatar/physics/corpus/fitting.txt --held-out avatar/physics/corpus/held_out.txt

clean:
	rm -rf build build-debug build-asan
