# Camera rendering with llvmpipe (or the GPU's EGL): bench_render under build/bench/, the synthetic
# scenes of tools/bench and the city and forest scene files.
airis_add_benchmark(bench_render SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_bench.cc DEPS airis_bench)
target_compile_definitions(bench_render PRIVATE AIRIS_BENCH_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes")
