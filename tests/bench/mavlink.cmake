# The MAVLink codec (engine/mavlink): encode and parse+decode of the PX4 lockstep messages.
airis_add_benchmark(bench_mavlink
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/mavlink_bench.cc
  DEPS airis_mavlink)
