# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Standalone build of the lsd_advance module against an installed OpenCV (>= 4.5.4).
#
# Options:
#   BUILD_TESTS=ON|OFF     opencv_test_lsd_advance + opencv_perf_lsd_advance (needs OpenCV's `ts`,
#                          compiled here from an OpenCV source tree of the installed version)
#   BUILD_EXAMPLES=ON|OFF  one executable per samples/NAME.cpp, named NAME
#   OPENCV_SOURCE_DIR=<dir> OpenCV source tree (same version as the installed OpenCV) for `ts`.
#                          Default: $ENV{OPENCV_SOURCE_DIR}, else
#                          ${XDG_CACHE_HOME:-~/.cache}/lsd_advance/opencv-<version>, fetched there
#                          by scripts/fetch_opencv_source.sh when missing (Debian).
#   LSD_ADVANCE_WERROR=ON  treat warnings as errors in the module's own targets
#   LSD_ADVANCE_SANITIZE=<list>  build the module's targets (library, tests, samples; not ts) with
#                          -fsanitize=<list>, e.g. address,undefined (scripts/sanitizers.sh);
#                          reports are fatal (-fno-sanitize-recover=all)
#   LSD_ADVANCE_FUZZ=ON    the libFuzzer target lsd_advance_fuzz (fuzz/; needs clang; scripts/fuzz.sh)

option(BUILD_TESTS "Build accuracy and performance tests (needs an OpenCV source tree for ts)" ON)
option(BUILD_EXAMPLES "Build samples/*.cpp as executables" ON)
option(LSD_ADVANCE_WERROR "Treat compiler warnings as errors in the module's targets" OFF)
set(LSD_ADVANCE_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(LSD_ADVANCE_FUZZ "Build the libFuzzer target lsd_advance_fuzz (needs clang)" OFF)

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# OpenCV 4.x itself is built as C++11: use the same here so that both modes accept the same code.
set(CMAKE_CXX_STANDARD 11)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)

set(_lsda_required core imgproc imgcodecs ximgproc)
set(_lsda_optional line_descriptor highgui videoio)
if(BUILD_TESTS)
  # ts itself needs highgui and videoio
  list(APPEND _lsda_required highgui videoio)
elseif(BUILD_EXAMPLES)
  # lsd_advance_detect reads videos
  list(APPEND _lsda_required videoio)
endif()
list(REMOVE_ITEM _lsda_optional ${_lsda_required})
find_package(OpenCV 4.5.4 REQUIRED
  COMPONENTS ${_lsda_required}
  OPTIONAL_COMPONENTS ${_lsda_optional})
message(STATUS "lsd_advance: OpenCV ${OpenCV_VERSION} from ${OpenCV_DIR}")

set(LSDA_ROOT "${CMAKE_CURRENT_SOURCE_DIR}")
set(LSDA_DEPS opencv_core opencv_imgproc opencv_imgcodecs opencv_ximgproc)
set(LSDA_OPTIONAL_DEPS "")
foreach(_m line_descriptor highgui videoio)
  if(OpenCV_${_m}_FOUND OR TARGET opencv_${_m})
    list(APPEND LSDA_OPTIONAL_DEPS opencv_${_m})
  endif()
endforeach()
message(STATUS "lsd_advance: optional OpenCV modules found: ${LSDA_OPTIONAL_DEPS}")

# HAVE_OPENCV_<MODULE> comes from the installed opencv2/opencv_modules.hpp (as in-tree);
# define it ourselves only when that header does not.
set(LSDA_MODULE_DEFINITIONS "")
foreach(_inc ${OpenCV_INCLUDE_DIRS})
  if(EXISTS "${_inc}/opencv2/opencv_modules.hpp")
    file(READ "${_inc}/opencv2/opencv_modules.hpp" _lsda_modules_hpp)
    break()
  endif()
endforeach()
if(TARGET opencv_line_descriptor AND NOT _lsda_modules_hpp MATCHES "#define HAVE_OPENCV_LINE_DESCRIPTOR")
  list(APPEND LSDA_MODULE_DEFINITIONS HAVE_OPENCV_LINE_DESCRIPTOR)
endif()

# A subset of the warnings OpenCV's own build enables (cmake/OpenCVCompilerOptions.cmake), so
# code that is clean here is clean in-tree too.
set(LSDA_WARNINGS -Wall -Wextra -Wno-unused-parameter -Wreturn-type -Wnon-virtual-dtor
    -Wmissing-declarations -Wundef -Winit-self -Wpointer-arith -Wshadow -Wsign-promo
    -Wuninitialized -Wno-delete-non-virtual-dtor -Wno-comment)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  list(APPEND LSDA_WARNINGS -Wsuggest-override -Wimplicit-fallthrough=3)
endif()
if(LSD_ADVANCE_WERROR)
  list(APPEND LSDA_WARNINGS -Werror)
endif()

set(LSDA_SANITIZE_OPTIONS "")
if(LSD_ADVANCE_SANITIZE)
  # The module's own code (library, tests, samples) is instrumented; OpenCV's ts, like the
  # installed OpenCV itself, is not: it only needs to link with the sanitizer runtime.
  set(LSDA_SANITIZE_OPTIONS -fsanitize=${LSD_ADVANCE_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${LSD_ADVANCE_SANITIZE})
  message(STATUS "lsd_advance: sanitizers ${LSD_ADVANCE_SANITIZE}")
endif()

# ---------------------------------------------------------------------------------------------
# The library: shared, hidden visibility and CVAPI_EXPORTS exactly like an OpenCV module, so a
# missing CV_EXPORTS fails here as it would in-tree.
file(GLOB LSDA_SOURCES CONFIGURE_DEPENDS "${LSDA_ROOT}/src/*.cpp")
file(GLOB LSDA_INTERNAL_HEADERS CONFIGURE_DEPENDS "${LSDA_ROOT}/src/*.hpp" "${LSDA_ROOT}/src/*.h")
file(GLOB LSDA_PUBLIC_HEADERS CONFIGURE_DEPENDS
  "${LSDA_ROOT}/include/opencv2/lsd_advance.hpp"
  "${LSDA_ROOT}/include/opencv2/lsd_advance/*.hpp"
  "${LSDA_ROOT}/include/opencv2/lsd_advance/*.h")
if(NOT LSDA_SOURCES)
  message(FATAL_ERROR "lsd_advance: no sources found in ${LSDA_ROOT}/src/*.cpp")
endif()

add_library(opencv_lsd_advance SHARED ${LSDA_SOURCES} ${LSDA_INTERNAL_HEADERS} ${LSDA_PUBLIC_HEADERS})
target_include_directories(opencv_lsd_advance
  PUBLIC "${LSDA_ROOT}/include" ${OpenCV_INCLUDE_DIRS}
  PRIVATE "${LSDA_ROOT}/src")
target_link_libraries(opencv_lsd_advance PUBLIC ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
target_compile_definitions(opencv_lsd_advance PRIVATE CVAPI_EXPORTS ${LSDA_MODULE_DEFINITIONS})
target_compile_options(opencv_lsd_advance PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
set_target_properties(opencv_lsd_advance PROPERTIES
  CXX_VISIBILITY_PRESET hidden
  VISIBILITY_INLINES_HIDDEN ON
  VERSION ${OpenCV_VERSION}
  SOVERSION ${OpenCV_VERSION_MAJOR}.${OpenCV_VERSION_MINOR}
  LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/lib")
# Undefined symbols in the shared library are errors (as in OpenCV's build on Linux).
if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  target_link_options(opencv_lsd_advance PRIVATE "LINKER:--no-undefined")
endif()

# ---------------------------------------------------------------------------------------------
# Samples
if(BUILD_EXAMPLES)
  file(GLOB LSDA_SAMPLES CONFIGURE_DEPENDS "${LSDA_ROOT}/samples/*.cpp")
  foreach(_src ${LSDA_SAMPLES})
    get_filename_component(_name "${_src}" NAME_WE)
    add_executable(${_name} "${_src}")
    target_link_libraries(${_name} PRIVATE opencv_lsd_advance ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
    target_compile_options(${_name} PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
    set_target_properties(${_name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}")
  endforeach()
endif()

# ---------------------------------------------------------------------------------------------
# Tests
if(BUILD_TESTS)
  include("${CMAKE_CURRENT_LIST_DIR}/opencv_ts.cmake")   # -> target lsda_opencv_ts
  enable_testing()

  foreach(_kind test perf)
    file(GLOB _srcs CONFIGURE_DEPENDS "${LSDA_ROOT}/${_kind}/*.cpp")
    file(GLOB _hdrs CONFIGURE_DEPENDS "${LSDA_ROOT}/${_kind}/*.hpp")
    if(NOT _srcs)
      message(STATUS "lsd_advance: no ${_kind}/*.cpp, opencv_${_kind}_lsd_advance not built")
      continue()
    endif()
    set(_target opencv_${_kind}_lsd_advance)
    add_executable(${_target} ${_srcs} ${_hdrs})
    target_include_directories(${_target} PRIVATE "${LSDA_ROOT}/${_kind}" "${LSDA_ROOT}/src")
    target_link_libraries(${_target} PRIVATE opencv_lsd_advance lsda_opencv_ts
      ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
    target_compile_definitions(${_target} PRIVATE ${LSDA_MODULE_DEFINITIONS})
    target_compile_options(${_target} PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
    set_target_properties(${_target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}")
  endforeach()

  # ctest: find cv::samples::findFile() data (Debian's opencv-doc) unless the caller set it
  set(LSDA_SAMPLES_DATA_PATH "/usr/share/doc/opencv-doc/examples/data" CACHE PATH
      "OPENCV_SAMPLES_DATA_PATH for tests run through ctest")
  if(TARGET opencv_test_lsd_advance)
    add_test(NAME opencv_test_lsd_advance COMMAND opencv_test_lsd_advance)
  endif()
  if(TARGET opencv_perf_lsd_advance)
    add_test(NAME opencv_perf_lsd_advance_smoke
      COMMAND opencv_perf_lsd_advance --perf_min_samples=1 --perf_force_samples=1 --perf_time_limit=1)
  endif()
  foreach(_t opencv_test_lsd_advance opencv_perf_lsd_advance_smoke)
    if(TEST ${_t} AND NOT DEFINED ENV{OPENCV_SAMPLES_DATA_PATH})
      set_tests_properties(${_t} PROPERTIES ENVIRONMENT "OPENCV_SAMPLES_DATA_PATH=${LSDA_SAMPLES_DATA_PATH}")
    endif()
  endforeach()
endif()

if(LSD_ADVANCE_FUZZ)
  add_subdirectory("${LSDA_ROOT}/fuzz" "${CMAKE_BINARY_DIR}/fuzz")
endif()

message(STATUS "lsd_advance: BUILD_TESTS=${BUILD_TESTS} BUILD_EXAMPLES=${BUILD_EXAMPLES}")
