# airis_add_library(NAME SOURCES ... DEPS ... [PRIVATE_DEPS ...]): one static library per source folder.
# DEPS are what its headers expose (linked PUBLIC); PRIVATE_DEPS are implementation details (Bullet,
# Embree, OpenCV, assimp, yaml-cpp) that its users never see. Its include root is the repository root, so
# code includes "engine/core/clock.h"; which of those includes a layer may write is checked by
# cmake/check_layers.cmake (DESIGN.md's table), which fails the build.
function(airis_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}/generated)
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  if(ARG_PRIVATE_DEPS)
    target_link_libraries(${name} PRIVATE ${ARG_PRIVATE_DEPS})
  endif()
  target_compile_options(${name} PRIVATE ${AIRIS_WARNING_FLAGS})
endfunction()

# airis_add_test(NAME SOURCES ... DEPS ... [PROPERTIES ...]): one GoogleTest executable registered with
# CTest; PROPERTIES are set on each of its tests.
function(airis_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PROPERTIES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main GTest::gmock)
  target_compile_options(${name} PRIVATE ${AIRIS_WARNING_FLAGS})
  set(properties "")
  if(ARG_PROPERTIES)
    set(properties PROPERTIES ${ARG_PROPERTIES})
  endif()
  gtest_discover_tests(${name} WORKING_DIRECTORY ${PROJECT_SOURCE_DIR} DISCOVERY_TIMEOUT 60 ${properties})
endfunction()

# airis_add_benchmark(NAME SOURCES ... DEPS ...): one Google Benchmark executable under build/bench/.
function(airis_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} benchmark::benchmark benchmark::benchmark_main)
  target_compile_options(${name} PRIVATE ${AIRIS_WARNING_FLAGS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bench)
endfunction()
