# Scene loading and procedural generation (scenes/): 10,000-object scenes, time and memory.
find_package(GDAL REQUIRED)  # the DEM benchmark writes its elevation model with GDAL
airis_add_benchmark(bench_scenes
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/scenes_bench.cc
  DEPS airis_scenes GDAL::GDAL)
