# Physics tick benchmarks: our World vs Bullet's btDiscreteDynamicsWorld. The scenarios live in
# tools/bench_physics.cc (shared with `airis bench physics`), compiled in directly.
airis_add_benchmark(bench_physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/physics_bench.cc ${PROJECT_SOURCE_DIR}/tools/bench_physics.cc
  DEPS airis_vehicles nlohmann_json::nlohmann_json)
