# Many vehicles: a swarm flying in the city, and one flyer among parked quads, on 1 and 2 threads.
# tools/bench/bench_vehicles.cc (shared with `airis bench vehicles`) holds the scenario.
airis_add_benchmark(bench_vehicles
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/vehicles_bench.cc
  DEPS airis_bench)
