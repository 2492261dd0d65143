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

# The main job: fly the city survey and write a small labeled dataset (about 100 frames of RGB, depth,
# segmentation and COCO annotations) into out/demo_dataset, then print where its contact sheet is.
DEMO_OUT ?= out/demo_dataset
demo: build
	rm -rf $(DEMO_OUT)
	./$(BUILD)/airis dataset scenes/city.yaml --mission scenes/missions/city_survey.yaml --out $(DEMO_OUT)

# Every Google Benchmark program under tests/bench/.
bench: build
	@for b in $(BUILD)/bench/bench_*; do echo "== $$b"; $$b --benchmark_min_time=0.2; done

format:
	find engine vehicles sensors scenes tools tests -name '*.h' -o -name '*.cc' | xargs clang-format -i

clean:
	rm -rf $(BUILD)
