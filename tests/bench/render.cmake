# Camera rendering with llvmpipe (or the GPU's EGL): bench_render under build/bench/. With the scene loader
# built, the city and forest scene files are benchmarked too.
if(TARGET airis_render)
  airis_add_benchmark(bench_render SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_bench.cc DEPS airis_render)
  if(TARGET airis_scenes)
    target_link_libraries(bench_render PRIVATE airis_scenes)
    target_compile_definitions(bench_render PRIVATE
      AIRIS_BENCH_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes")
  endif()
endif()
