# Physics tick benchmarks: our World vs Bullet's btDiscreteDynamicsWorld. The scenarios live in
# tools/bench/bench_physics.cc (shared with `airis bench physics`).
airis_add_benchmark(bench_physics
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/physics_bench.cc
  DEPS airis_bench)
