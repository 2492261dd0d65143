# The Python module's vectorized environments stepped from C++ (the part of an env step that is
# not Python); tests/bench/python_bench.py times the same through Python.
if(AIRIS_BUILD_PYTHON)
  airis_add_benchmark(bench_python
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/python_bench.cc
    DEPS airis_python_core)
endif()
