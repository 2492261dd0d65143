# Benchmarks of engine/environment (and the geodetic conversions of engine/core it relies on).
airis_add_benchmark(bench_environment
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/environment_bench.cc
  DEPS airis_environment)
