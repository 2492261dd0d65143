# Sensor models and Embree ray casting. tools/bench/bench_sensors.cc (shared with `airis bench sensors`)
# holds the reference-quad scenario.
airis_add_benchmark(bench_sensors
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensors_bench.cc
  DEPS airis_bench airis_sensor_test_util)
