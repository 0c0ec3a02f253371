# Every third-party package comes from Debian 12 (scripts/install-deps).
# Imported targets are SYSTEM so strict warnings apply only to dynamap's own code.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(spdlog REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(Threads REQUIRED)

if(DYNAMAP_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(DYNAMAP_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

set(DYNAMAP_SHARED_DATA_DIR "${PROJECT_SOURCE_DIR}/../shared/data" CACHE PATH
    "Third-party test data (shared/data beside the project root)")

# Debian ships OpenCV's CMake config only in the all-modules libopencv-dev; the three
# modules dynamap uses (core, imgproc, imgcodecs) are found directly instead.
find_path(DYNAMAP_OPENCV_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4 REQUIRED)
add_library(dynamap_opencv INTERFACE)
target_include_directories(dynamap_opencv SYSTEM INTERFACE ${DYNAMAP_OPENCV_INCLUDE_DIR})
foreach(module core imgproc imgcodecs)
  find_library(DYNAMAP_OPENCV_${module} opencv_${module} REQUIRED)
  target_link_libraries(dynamap_opencv INTERFACE ${DYNAMAP_OPENCV_${module}})
endforeach()
