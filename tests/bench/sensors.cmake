# Sensor models and Embree ray casting (sensors engineer). tools/bench_sensors.cc (shared with
# `airis bench sensors`) is compiled in directly.
airis_add_benchmark(bench_sensors
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/sensors_bench.cc ${PROJECT_SOURCE_DIR}/tests/sensors/sensor_test_util.cc
          ${PROJECT_SOURCE_DIR}/tools/bench_sensors.cc
  DEPS airis_sensors airis_vehicles airis_world airis_environment nlohmann_json::nlohmann_json)
