# The MAVLink codec (engine/mavlink): encode and parse+decode of the PX4 lockstep messages.
airis_add_benchmark(bench_mavlink
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/mavlink_bench.cc
  DEPS airis_mavlink)

# The PX4 bridge per lockstep exchange against a peer that answers at once over loopback TCP.
airis_add_benchmark(bench_px4_bridge
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/px4_bridge_bench.cc
          ${PROJECT_SOURCE_DIR}/tests/mavlink/px4/scripted_px4.cc
  DEPS airis_jobs)
