# The two commands of the README, plus a few conveniences.
#   make run   install what is missing, build Release, start the server
#   make test  install what is missing, build, run every test suite
JOBS ?= $(shell nproc)
SERVER_ARGS ?=

.PHONY: all deps build run test test-asan bench facegen clean

all: build

deps:
	@bash deploy/install-deps.sh

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

run: build
	./build/bin/facewire-server serve --tcp 127.0.0.1:8081 $(SERVER_ARGS)

test: build
	ctest --preset release-all -j $(JOBS)

# The same suites under AddressSanitizer + UndefinedBehaviorSanitizer.
test-asan: deps
	cmake --preset asan
	cmake --build --preset asan -j $(JOBS)
	ctest --preset asan -j $(JOBS)

bench: build
	./build/bin/facewire-bench render --json
	./build/bin/facewire-bench prep --json

# Regenerates the generic face asset after a change to the generator.
facegen: build
	./build/bin/facewire-facegen -o avatar/model/assets/generic_face.json
	./build/bin/facewire-aubasis -i avatar/model/assets/generic_face.json -o avatar/model/assets/generic_face.json

clean:
	rm -rf build build-debug build-asan
