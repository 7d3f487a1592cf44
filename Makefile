# The two commands of the README: `make demo` and `make test`. Both install any
# missing Debian packages first, then configure and build in Release.
BUILD ?= build
JOBS ?= $(shell nproc)
DEMO_SCENE ?= scenes/demo/daylit-office.json
DEMO_OUT ?= out/demo

.PHONY: all deps configure build demo python test sanitize fuzz bench clean

all: build

deps:
	./scripts/install-deps.sh

# Benchmarks are built by `make bench` only, which keeps `make test` within CI's time.
configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DLUXPLAN_BUILD_BENCH=OFF

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The demo runs only the CLI, so it builds only that target (no tests, no benchmarks).
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target luxplan_cli
	./scripts/demo.sh $(BUILD)/luxplan $(DEMO_SCENE) $(DEMO_OUT)

# The Python module luxplan into $(BUILD)/python (docs/python.md):
# PYTHONPATH=$(BUILD)/python /usr/bin/python3 -c "import luxplan".
python: configure
	cmake --build $(BUILD) -j $(JOBS) --target luxplan_python

# The whole suite in Release, then the sanitizer tree (what .ci/run calls).
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	$(MAKE) sanitize

# AddressSanitizer + UndefinedBehaviorSanitizer (docs/robustness.md): a lean tree of
# the modules that read input (their tests) and the fuzzer, whose regressions and a
# bounded fresh run are tests there too.
ASAN_BUILD ?= build-asan
ASAN_MODULES ?= core;json;io
ASAN_FUZZ_SECONDS ?= 40
sanitize: deps
	cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g1" -DLUXPLAN_SANITIZE=ON \
	  -DLUXPLAN_BUILD_BENCH=OFF "-DLUXPLAN_TEST_MODULES=$(ASAN_MODULES)" -DLUXPLAN_FUZZ_SECONDS=$(ASAN_FUZZ_SECONDS)
	cmake --build $(ASAN_BUILD) -j $(JOBS) --target luxplan_fuzz $(foreach m,$(subst ;, ,$(ASAN_MODULES)),test_$(m))
	ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(ASAN_BUILD) --output-on-failure -j $(JOBS)

# A fresh fuzz run of FUZZ_COUNT inputs (docs/robustness.md); failures kept in
# $(BUILD)/fuzz-failures, to be copied into tests/fuzz/regressions/.
FUZZ_COUNT ?= 10000
FUZZ_SEED ?= 1
fuzz: configure
	cmake --build $(BUILD) -j $(JOBS) --target luxplan_fuzz
	./$(BUILD)/tests/luxplan_fuzz --count $(FUZZ_COUNT) --seed $(FUZZ_SEED) --jobs $(JOBS) --save $(BUILD)/fuzz-failures

bench: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DLUXPLAN_BUILD_BENCH=ON
	cmake --build $(BUILD) -j $(JOBS) --target luxplan_bench luxplan_path_anatomy
	./$(BUILD)/bench/luxplan_bench

clean:
	rm -rf $(BUILD) $(ASAN_BUILD) out
