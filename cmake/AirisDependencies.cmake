# Third-party dependencies, all from Debian 12 packages (scripts/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(Threads REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
# PNG and JPEG through libpng, libdeflate and libjpeg-turbo directly (engine/core/image_codec.h).
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)
if(AIRIS_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(AIRIS_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# OpenCV: only core and imgproc are installed (libopencv-dev would bring ~600 MB), and those Debian packages
# ship no OpenCVConfig.cmake or opencv4.pc, so the target is assembled here: airis::opencv. Images are read
# and written with libpng and libjpeg-turbo (engine/core/image_codec.h), not OpenCV's imgcodecs, which
# links GDAL and some 140 shared libraries that every process would load.
find_path(AIRIS_OPENCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4 REQUIRED)
add_library(airis_opencv INTERFACE)
target_include_directories(airis_opencv SYSTEM INTERFACE ${AIRIS_OPENCV_INCLUDE_DIR})
foreach(part core imgproc)
  find_library(AIRIS_OPENCV_${part}_LIBRARY opencv_${part} REQUIRED)
  target_link_libraries(airis_opencv INTERFACE ${AIRIS_OPENCV_${part}_LIBRARY})
endforeach()
add_library(airis::opencv ALIAS airis_opencv)
