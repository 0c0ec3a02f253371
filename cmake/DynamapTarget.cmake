# Helpers that give every project target the same warnings and layout rules.

# dynamap_warnings(TARGET): strict warnings as errors on the project's own code only;
# third-party headers come in as SYSTEM includes and are not affected.
function(dynamap_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()

# dynamap_library(NAME SOURCES... [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
# A static library whose public headers live in <folder>/include.
function(dynamap_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
                                     PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  dynamap_warnings(${name})
endfunction()

# dynamap_test(NAME SOURCES... LIBS ...): one GoogleTest executable registered with CTest.
# Tests find ../shared/data and resources/ through compile definitions.
function(dynamap_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    DYNAMAP_SHARED_DATA_DIR="${DYNAMAP_SHARED_DATA_DIR}"
    DYNAMAP_RESOURCES_DIR="${PROJECT_SOURCE_DIR}/resources"
    DYNAMAP_BINARY_DIR="${PROJECT_BINARY_DIR}")
  dynamap_warnings(${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS "${ARG_LABELS}")
endfunction()
