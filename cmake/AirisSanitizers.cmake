# AIRIS_FUZZ: the sanitized build (docs/fuzzing.md). Configured in its own folder with Debian's clang
# 14 (make test does it in build-fuzz):
#
#   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++-14 -DAIRIS_FUZZ=ON
#
# Every target is compiled with AddressSanitizer and UndefinedBehaviorSanitizer (any report stops the
# program) and with libFuzzer's coverage instrumentation; the libFuzzer targets of tests/fuzz link
# libFuzzer's main. Only the tests of the libraries that parse untrusted input are added
# (tests/CMakeLists.txt): building the whole suite this way costs more than CI has.
option(AIRIS_FUZZ "Sanitized build (clang): libFuzzer targets and the parsing libraries' tests" OFF)
if(AIRIS_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "AIRIS_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++-14 in a folder of its own")
  endif()
  # -O1 after the build type's -O3/-O2 (the last -O wins): sanitizer reports keep their stack
  # traces, and compiling costs half as much.
  add_compile_options(-O1 -gline-tables-only -fno-omit-frame-pointer
                      -fsanitize=address,undefined -fno-sanitize-recover=all
                      -fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=address,undefined)
  set(AIRIS_BUILD_PYTHON OFF CACHE BOOL "" FORCE)
  set(AIRIS_BUILD_BENCHMARKS OFF CACHE BOOL "" FORCE)
endif()
