# Sensor models and Embree ray casting (sensors engineer).
airis_add_benchmark(bench_sensors
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensors_bench.cc ${PROJECT_SOURCE_DIR}/tests/sensors/sensor_test_util.cc
  DEPS airis_sensors airis_world airis_environment)
