# Front door. `make demo` and `make test` each install what they need, configure and build first.
BUILD ?= build
JOBS ?= $(shell nproc)

.PHONY: all deps configure build test sanitized demo bench python format format-check clean

all: build

deps:
	./scripts/install-deps.sh

# Warnings in airis's own code are errors on the supported platform (Debian 12's GCC 12), so CI fails on
# one; `make WERROR=OFF ...` (or plain cmake) for other compilers.
WERROR ?= ON
configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DAIRIS_WERROR=$(WERROR)

build: configure
	cmake --build $(BUILD) -j$(JOBS)

# The whole test suite (GoogleTest, the layer and format checks, pytest through CTest), warnings as
# errors, run twice in random order with one process per core: a test that depends on another's files
# or on the order shows up. Then the sanitized build with its fuzz targets (`make sanitized`, below).
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS) --schedule-random
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS) --schedule-random
	$(MAKE) sanitized

# The sanitized build (docs/fuzzing.md), in its own folder with Debian's clang 14: the tests of the
# libraries that parse untrusted input under AddressSanitizer and UndefinedBehaviorSanitizer, and each
# libFuzzer target from its corpus: a fixed number of executions with seed FUZZ_SEED (the same inputs
# on every machine), or FUZZ_SECONDS each when set. Any sanitizer report or fuzz finding fails.
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 0
FUZZ_SEED ?= 1
sanitized: deps
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_CXX_COMPILER=clang++-14 -DAIRIS_FUZZ=ON -DAIRIS_FUZZ_SECONDS=$(FUZZ_SECONDS) -DAIRIS_FUZZ_SEED=$(FUZZ_SEED)
	cmake --build $(FUZZ_BUILD) -j$(JOBS) --target airis_sanitized
	ctest --test-dir $(FUZZ_BUILD) --output-on-failure -j$(JOBS) --schedule-random

# The main job: fly the city survey and write a small labeled dataset (about 100 frames of RGB, depth,
# segmentation and COCO annotations) into out/demo_dataset, then print where its contact sheet is.
DEMO_OUT ?= out/demo_dataset
demo: build
	rm -rf $(DEMO_OUT)
	./$(BUILD)/airis dataset scenes/city.yaml --mission scenes/missions/city_survey.yaml --out $(DEMO_OUT)

# The Python module: builds it and makes `import airis` work for this user (airis.pth in the user's
# site-packages pointing at build/python; docs/python.md).
python: configure
	cmake --build $(BUILD) -j$(JOBS) --target airis_python
	./scripts/install-python.sh $(BUILD)

# Every Google Benchmark program under tests/bench/.
bench: build
	@for b in $(BUILD)/bench/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

format:
	find engine vehicles sensors scenes tools tests -name '*.h' -o -name '*.cc' | xargs clang-format -i

format-check:
	cmake/check_format.sh .

clean:
	rm -rf $(BUILD) $(FUZZ_BUILD)
