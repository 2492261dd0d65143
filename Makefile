# Front door. `make demo` and `make test` each install what they need, configure and build first.
BUILD ?= build
JOBS ?= $(shell nproc)

.PHONY: all deps configure build test demo bench format clean

all: build

deps:
	./scripts/install-deps.sh

configure: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j$(JOBS)

# The whole test suite (GoogleTest through CTest).
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)

# The main job: environment at the default point (replaced by the demo mission and dataset as they land).
demo: build
	./$(BUILD)/airis env

# Every Google Benchmark program under tests/bench/.
bench: build
	@for b in $(BUILD)/bench/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

format:
	find engine vehicles sensors scenes tools tests -name '*.h' -o -name '*.cc' | xargs clang-format -i

clean:
	rm -rf $(BUILD)
