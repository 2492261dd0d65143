# Scene loading and procedural generation (scenes/): 10,000-object scenes, time and memory.
airis_add_benchmark(bench_scenes
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/scenes_bench.cc
  DEPS airis_scenes)
