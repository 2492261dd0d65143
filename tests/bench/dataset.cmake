# Labeled dataset writing: the writer's encoding throughput on a synthetic frame, and the whole `airis dataset`
# job of the README demo (city survey) in labeled frames per second.
airis_add_benchmark(bench_dataset SOURCES ${CMAKE_CURRENT_LIST_DIR}/dataset_bench.cc DEPS airis_bench)
target_compile_definitions(bench_dataset PRIVATE AIRIS_BENCH_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
