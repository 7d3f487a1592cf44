# The two commands of the README: `make demo` and `make test`. Both install any
# missing Debian packages first, then configure and build in Release.
BUILD ?= build
JOBS ?= $(shell nproc)
DEMO_SCENE ?= scenes/paper/fig7-office-morning.json
DEMO_OUT ?= out/demo

.PHONY: all deps configure build demo test bench clean

all: build

deps:
	./scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The demo runs only the CLI, so it builds only that target (no tests, no benchmarks).
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target luxplan_cli
	./scripts/demo.sh $(BUILD)/luxplan $(DEMO_SCENE) $(DEMO_OUT)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

bench: build
	./$(BUILD)/bench/luxplan_bench

clean:
	rm -rf $(BUILD) out
