# Flight controller cost per tick, and the whole stack (controller + reference quad + its four sensors +
# collision in scenes/city.yaml) in ticks per second.
airis_add_benchmark(bench_control
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/control_bench.cc
  DEPS airis_scenes airis_vehicles)
