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
#   BUILD_APPS=ON|OFF      one executable per apps/lsd_advance_bench/NAME.cpp (the benchmark, the
#                          sweep, the detect CLI), named NAME; they read the method files of
#                          apps/lsd_advance_bench/methods/ in the source tree and are not installed
#   OPENCV_SOURCE_DIR=<dir> OpenCV source tree (same version as the installed OpenCV) for `ts`.
#                          Default: $ENV{OPENCV_SOURCE_DIR}, else
#                          ${XDG_CACHE_HOME:-~/.cache}/lsd_advance/opencv-<version>, fetched there
#                          by scripts/fetch_opencv_source.sh when missing (Debian).
#   LSD_ADVANCE_WERROR=ON  treat warnings as errors in the module's own targets
#   LSD_ADVANCE_SANITIZE=<list>  build the module's targets (library, tests, samples, apps; not ts) with
#                          -fsanitize=<list>, e.g. address,undefined (scripts/sanitizers.sh);
#                          reports are fatal (-fno-sanitize-recover=all)
#   LSD_ADVANCE_SCALAR=ON  compile the module's universal-intrinsics paths out (src/primitives.hpp):
#                          every `#if CV_SIMD128` takes its scalar `#else` (scripts/check_scalar.sh)
#   LSD_ADVANCE_TEST_FILES=<list>  the test/*.cpp files (names) opencv_test_lsd_advance is built from;
#                          empty (the default): all of them. scripts/sanitizers.sh builds the
#                          ThreadSanitizer run from the threaded tests' files only.
#   LSD_ADVANCE_FUZZ=ON    the libFuzzer target lsd_advance_fuzz (fuzz/; needs clang; scripts/fuzz.sh)
#   LSD_ADVANCE_ELSED_DIR=<dir>  ELSED's sources (<dir>/src/ELSED.cpp; CI: ../shared/peers/elsed),
#                          compiled from that folder as an optional peer: the apps get the method
#                          `elsed` and the perf suite its ELSED cases. Default: empty, no peer.
#
# `cmake --install <build> [--prefix <p>]` (GNUInstallDirs; scripts/check_install.sh checks it):
#   include/opencv4/opencv2/lsd_advance.hpp, include/opencv4/opencv2/lsd_advance/*.hpp  (as OpenCV's)
#   ${CMAKE_INSTALL_LIBDIR}/libopencv_lsd_advance.so*
#   ${CMAKE_INSTALL_LIBDIR}/cmake/opencv_lsd_advance/   find_package(opencv_lsd_advance) ->
#                                                       opencv_lsd_advance::opencv_lsd_advance
#   ${CMAKE_INSTALL_LIBDIR}/pkgconfig/opencv_lsd_advance.pc
#   bin/lsd_advance_*                                   the sample programs (BUILD_EXAMPLES=ON)
#   bin/setup_vars_lsd_advance.sh                       PATH, LD_LIBRARY_PATH, PKG_CONFIG_PATH,
#                                                       CMAKE_PREFIX_PATH, PYTHONPATH of the install
#   share/opencv4/samples/lsd_advance/                  the sample sources (C++ and Python)
# Tests, perf tests, OpenCV's ts and the fuzzer are not installed.
# Version: the module carries the version of the OpenCV it is built against, as opencv_contrib
# modules do (library VERSION, package and pkg-config version); SOVERSION is its major.minor.

option(BUILD_TESTS "Build accuracy and performance tests (needs an OpenCV source tree for ts)" ON)
option(BUILD_EXAMPLES "Build samples/*.cpp as executables" ON)
option(BUILD_APPS "Build the benchmark apps apps/lsd_advance_bench/*.cpp as executables" ON)
option(LSD_ADVANCE_WERROR "Treat compiler warnings as errors in the module's targets" OFF)
set(LSD_ADVANCE_SANITIZE "" CACHE STRING "Sanitizers for every target, e.g. address,undefined (empty: none)")
option(LSD_ADVANCE_SCALAR "Compile the module's vector paths out: the scalar paths only" OFF)
set(LSD_ADVANCE_TEST_FILES "" CACHE STRING "test/*.cpp files (names) of opencv_test_lsd_advance (empty: all)")
option(LSD_ADVANCE_FUZZ "Build the libFuzzer target lsd_advance_fuzz (needs clang)" OFF)
set(LSD_ADVANCE_ELSED_DIR "" CACHE PATH "ELSED source folder, built as an optional peer of the apps and perf suite (empty: none)")

include(GNUInstallDirs)

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()

# OpenCV 4.x itself is built as C++11: use the same here so that both modes accept the same code.
set(CMAKE_CXX_STANDARD 11)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)

set(_lsda_required core imgproc imgcodecs calib3d ximgproc)
set(_lsda_optional line_descriptor highgui videoio)
if(BUILD_TESTS)
  # ts itself needs highgui and videoio
  list(APPEND _lsda_required highgui videoio)
elseif(BUILD_EXAMPLES OR BUILD_APPS)
  # lsd_advance_video and lsd_advance_detect read videos
  list(APPEND _lsda_required videoio)
endif()
if(BUILD_APPS)
  # the benchmark's pose evaluation compares lines with ORB points
  list(APPEND _lsda_required features2d)
endif()
list(REMOVE_ITEM _lsda_optional ${_lsda_required})
find_package(OpenCV 4.5.4 REQUIRED
  COMPONENTS ${_lsda_required}
  OPTIONAL_COMPONENTS ${_lsda_optional})
message(STATUS "lsd_advance: OpenCV ${OpenCV_VERSION} from ${OpenCV_DIR}")
set(LSDA_VERSION "${OpenCV_VERSION}")

set(LSDA_ROOT "${CMAKE_CURRENT_SOURCE_DIR}")
set(LSDA_DEPS opencv_core opencv_imgproc opencv_imgcodecs opencv_calib3d opencv_ximgproc)
set(LSDA_OPTIONAL_DEPS "")
foreach(_m line_descriptor highgui videoio)
  if(OpenCV_${_m}_FOUND OR TARGET opencv_${_m})
    list(APPEND LSDA_OPTIONAL_DEPS opencv_${_m})
  endif()
endforeach()
message(STATUS "lsd_advance: optional OpenCV modules found: ${LSDA_OPTIONAL_DEPS}")

# HAVE_OPENCV_LINE_DESCRIPTOR switches the public KeyLine API on. It is a public definition of
# the library (so every user of the library, installed or not, sees the API the library was built
# with, whatever its opencv_modules.hpp says), defined empty: identical to the #define in OpenCV's
# opencv_modules.hpp, so the two together are no redefinition.
set(LSDA_MODULE_DEFINITIONS "")
if(TARGET opencv_line_descriptor)
  list(APPEND LSDA_MODULE_DEFINITIONS HAVE_OPENCV_LINE_DESCRIPTOR=)
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
if(LSD_ADVANCE_SCALAR)
  add_compile_definitions(LSD_ADVANCE_SCALAR)
  message(STATUS "lsd_advance: scalar build (no universal intrinsics)")
endif()

if(LSD_ADVANCE_SANITIZE)
  # The module's own code (library, tests, samples, apps) is instrumented; OpenCV's ts, like the
  # installed OpenCV itself, is not: it only needs to link with the sanitizer runtime.
  set(LSDA_SANITIZE_OPTIONS -fsanitize=${LSD_ADVANCE_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${LSD_ADVANCE_SANITIZE})
  message(STATUS "lsd_advance: sanitizers ${LSD_ADVANCE_SANITIZE}")
endif()

# ---------------------------------------------------------------------------------------------
# The library: shared, hidden visibility and CVAPI_EXPORTS exactly like an OpenCV module, so a
# missing CV_EXPORTS fails here as it would in-tree.
# src/ and its folders (src/fast_lsd/), as OpenCV's module build globs them.
file(GLOB_RECURSE LSDA_SOURCES CONFIGURE_DEPENDS "${LSDA_ROOT}/src/*.cpp")
file(GLOB_RECURSE LSDA_INTERNAL_HEADERS CONFIGURE_DEPENDS "${LSDA_ROOT}/src/*.hpp" "${LSDA_ROOT}/src/*.h")
file(GLOB LSDA_PUBLIC_HEADERS CONFIGURE_DEPENDS
  "${LSDA_ROOT}/include/opencv2/lsd_advance.hpp"
  "${LSDA_ROOT}/include/opencv2/lsd_advance/*.hpp"
  "${LSDA_ROOT}/include/opencv2/lsd_advance/*.h")
if(NOT LSDA_SOURCES)
  message(FATAL_ERROR "lsd_advance: no sources found in ${LSDA_ROOT}/src/*.cpp")
endif()

add_library(opencv_lsd_advance SHARED ${LSDA_SOURCES} ${LSDA_INTERNAL_HEADERS} ${LSDA_PUBLIC_HEADERS})
# OpenCV's imported targets carry no include directories: OpenCV_INCLUDE_DIRS is added here for
# the build tree and by opencv_lsd_advanceConfig.cmake for the install tree.
target_include_directories(opencv_lsd_advance
  PUBLIC "$<BUILD_INTERFACE:${LSDA_ROOT}/include>"
         "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/opencv4>"
         "$<BUILD_INTERFACE:${OpenCV_INCLUDE_DIRS}>"
  PRIVATE "${LSDA_ROOT}/src")
target_link_libraries(opencv_lsd_advance PUBLIC ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
target_compile_definitions(opencv_lsd_advance PRIVATE CVAPI_EXPORTS PUBLIC ${LSDA_MODULE_DEFINITIONS})
target_compile_features(opencv_lsd_advance PUBLIC cxx_std_11)
target_compile_options(opencv_lsd_advance PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
set_target_properties(opencv_lsd_advance PROPERTIES
  CXX_VISIBILITY_PRESET hidden
  VISIBILITY_INLINES_HIDDEN ON
  VERSION ${LSDA_VERSION}
  SOVERSION ${OpenCV_VERSION_MAJOR}.${OpenCV_VERSION_MINOR}
  LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/lib")
# Undefined symbols in the shared library are errors (as in OpenCV's build on Linux).
if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  target_link_options(opencv_lsd_advance PRIVATE "LINKER:--no-undefined")
endif()

# ---------------------------------------------------------------------------------------------
# ELSED, the optional peer detector: compiled from its own folder (never copied here) for
# side-by-side measurement in the apps and the perf suite, which see LSD_ADVANCE_HAVE_ELSED.
set(LSDA_PEER_LIBS "")
if(LSD_ADVANCE_ELSED_DIR)
  get_filename_component(_elsed_dir "${LSD_ADVANCE_ELSED_DIR}" ABSOLUTE)
  set(_elsed_srcs "")
  foreach(_f EdgeDrawer.cpp ELSED.cpp FullSegmentInfo.cpp)
    if(NOT EXISTS "${_elsed_dir}/src/${_f}")
      message(FATAL_ERROR "lsd_advance: LSD_ADVANCE_ELSED_DIR=${LSD_ADVANCE_ELSED_DIR} has no src/${_f} "
                          "(expected ELSED's sources; leave the option empty to build without the peer)")
    endif()
    list(APPEND _elsed_srcs "${_elsed_dir}/src/${_f}")
  endforeach()
  add_library(lsda_elsed_peer STATIC ${_elsed_srcs})
  # SYSTEM: its headers are not ours and are not held to the module's warning set.
  target_include_directories(lsda_elsed_peer SYSTEM PUBLIC "${_elsed_dir}/src" ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(lsda_elsed_peer PUBLIC opencv_core opencv_imgproc)
  target_compile_definitions(lsda_elsed_peer PUBLIC LSD_ADVANCE_HAVE_ELSED=1)
  set_target_properties(lsda_elsed_peer PROPERTIES POSITION_INDEPENDENT_CODE ON)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(lsda_elsed_peer PRIVATE -w)
  endif()
  set(LSDA_PEER_LIBS lsda_elsed_peer)
  message(STATUS "lsd_advance: ELSED peer from ${_elsed_dir}")
endif()

# ---------------------------------------------------------------------------------------------
# Samples (the public API only) and the benchmark apps (with the method files and the peer)
set(LSDA_METHODS_DIR "${LSDA_ROOT}/apps/lsd_advance_bench/methods")
set(LSDA_SAMPLE_TARGETS "")
foreach(_kind samples apps)
  if(_kind STREQUAL "samples" AND BUILD_EXAMPLES)
    file(GLOB _srcs CONFIGURE_DEPENDS "${LSDA_ROOT}/samples/*.cpp")
  elseif(_kind STREQUAL "apps" AND BUILD_APPS)
    file(GLOB _srcs CONFIGURE_DEPENDS "${LSDA_ROOT}/apps/lsd_advance_bench/*.cpp")
  else()
    continue()
  endif()
  foreach(_src ${_srcs})
    get_filename_component(_name "${_src}" NAME_WE)
    add_executable(${_name} "${_src}")
    target_link_libraries(${_name} PRIVATE opencv_lsd_advance ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
    target_compile_options(${_name} PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
    set_target_properties(${_name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}")
    if(_kind STREQUAL "apps")
      target_link_libraries(${_name} PRIVATE ${LSDA_PEER_LIBS} opencv_features2d)
      target_compile_definitions(${_name} PRIVATE LSD_ADVANCE_METHODS_DIR="${LSDA_METHODS_DIR}")
    else()
      list(APPEND LSDA_SAMPLE_TARGETS ${_name})
    endif()
  endforeach()
endforeach()

# ---------------------------------------------------------------------------------------------
# Tests
if(BUILD_TESTS)
  include("${CMAKE_CURRENT_LIST_DIR}/opencv_ts.cmake")   # -> target lsda_opencv_ts
  enable_testing()

  foreach(_kind test perf)
    file(GLOB _srcs CONFIGURE_DEPENDS "${LSDA_ROOT}/${_kind}/*.cpp")
    file(GLOB _hdrs CONFIGURE_DEPENDS "${LSDA_ROOT}/${_kind}/*.hpp")
    if(_kind STREQUAL "test" AND LSD_ADVANCE_TEST_FILES)
      set(_srcs "")
      foreach(_f ${LSD_ADVANCE_TEST_FILES})
        if(NOT EXISTS "${LSDA_ROOT}/test/${_f}")
          message(FATAL_ERROR "LSD_ADVANCE_TEST_FILES: test/${_f} does not exist")
        endif()
        list(APPEND _srcs "${LSDA_ROOT}/test/${_f}")
      endforeach()
    endif()
    if(NOT _srcs)
      message(STATUS "lsd_advance: no ${_kind}/*.cpp, opencv_${_kind}_lsd_advance not built")
      continue()
    endif()
    set(_target opencv_${_kind}_lsd_advance)
    add_executable(${_target} ${_srcs} ${_hdrs})
    target_include_directories(${_target} PRIVATE "${LSDA_ROOT}/${_kind}" "${LSDA_ROOT}/src")
    target_link_libraries(${_target} PRIVATE opencv_lsd_advance lsda_opencv_ts
      ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
    target_compile_options(${_target} PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
    set_target_properties(${_target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}")
    if(_kind STREQUAL "perf")
      target_link_libraries(${_target} PRIVATE ${LSDA_PEER_LIBS})
      target_compile_definitions(${_target} PRIVATE LSD_ADVANCE_METHODS_DIR="${LSDA_METHODS_DIR}")
    endif()
  endforeach()

  # The layout of an OpenCV whose LineSegmentDetector has moved from imgproc to ximgproc
  # (opencv#29349, opencv_contrib#4158): the module's sources and a BASE_LSD test compiled against
  # the header layer test/compat/lsd_in_ximgproc/include (its sources .cxx: OpenCV's in-tree build
  # globs test/**/*.cpp into the module's tests), which hides imgproc's LSD and declares
  # ximgproc's, forwarded to the installed implementation by a library compiled without the layer.
  set(_compat "${LSDA_ROOT}/test/compat/lsd_in_ximgproc")
  add_library(lsda_lsd_in_ximgproc_forward STATIC "${_compat}/line_segment_detector.cxx")
  target_include_directories(lsda_lsd_in_ximgproc_forward PRIVATE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(lsda_lsd_in_ximgproc_forward PUBLIC opencv_core opencv_imgproc)
  set(_target opencv_test_lsd_advance_lsd_in_ximgproc)
  add_executable(${_target} ${LSDA_SOURCES} "${_compat}/test_lsd_in_ximgproc.cxx")
  target_include_directories(${_target} BEFORE PRIVATE "${_compat}/include" "${LSDA_ROOT}/include" "${LSDA_ROOT}/src"
    ${OpenCV_INCLUDE_DIRS})
  target_compile_definitions(${_target} PRIVATE ${LSDA_MODULE_DEFINITIONS})
  target_link_libraries(${_target} PRIVATE lsda_lsd_in_ximgproc_forward lsda_opencv_ts ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
  target_compile_options(${_target} PRIVATE ${LSDA_WARNINGS} ${LSDA_SANITIZE_OPTIONS})
  set_target_properties(${_target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}")

  # ctest: find cv::samples::findFile() data (Debian's opencv-doc) unless the caller set it
  set(LSDA_SAMPLES_DATA_PATH "/usr/share/doc/opencv-doc/examples/data" CACHE PATH
      "OPENCV_SAMPLES_DATA_PATH for tests run through ctest")
  if(TARGET opencv_test_lsd_advance)
    add_test(NAME opencv_test_lsd_advance COMMAND opencv_test_lsd_advance)
  endif()
  add_test(NAME opencv_test_lsd_advance_lsd_in_ximgproc COMMAND opencv_test_lsd_advance_lsd_in_ximgproc)
  if(TARGET opencv_perf_lsd_advance)
    add_test(NAME opencv_perf_lsd_advance_smoke
      COMMAND opencv_perf_lsd_advance --perf_min_samples=1 --perf_force_samples=1 --perf_time_limit=1)
  endif()
  foreach(_t opencv_test_lsd_advance opencv_test_lsd_advance_lsd_in_ximgproc opencv_perf_lsd_advance_smoke)
    if(TEST ${_t} AND NOT DEFINED ENV{OPENCV_SAMPLES_DATA_PATH})
      set_tests_properties(${_t} PROPERTIES ENVIRONMENT "OPENCV_SAMPLES_DATA_PATH=${LSDA_SAMPLES_DATA_PATH}")
    endif()
  endforeach()
endif()

if(LSD_ADVANCE_FUZZ)
  add_subdirectory("${LSDA_ROOT}/fuzz" "${CMAKE_BINARY_DIR}/fuzz")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/python.cmake")   # Python module (LSD_ADVANCE_PYTHON; python/)

# ---------------------------------------------------------------------------------------------
# Install: headers, library, CMake package, pkg-config file, sample programs and sources.
include(CMakePackageConfigHelpers)
set(LSDA_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/opencv_lsd_advance")
set(LSDA_INSTALL_SAMPLESDIR "${CMAKE_INSTALL_DATADIR}/opencv4/samples/lsd_advance")

install(DIRECTORY "${LSDA_ROOT}/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/opencv4"
  FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(TARGETS opencv_lsd_advance EXPORT opencv_lsd_advanceTargets
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
# An OpenCV outside the linker's default directories stays found after installation.
set_target_properties(opencv_lsd_advance ${LSDA_SAMPLE_TARGETS} PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)

# The package: opencv_lsd_advance::opencv_lsd_advance, which brings the OpenCV modules the library
# links (find_dependency with the same components) and HAVE_OPENCV_LINE_DESCRIPTOR when built so.
install(EXPORT opencv_lsd_advanceTargets NAMESPACE opencv_lsd_advance::
  DESTINATION "${LSDA_INSTALL_CMAKEDIR}")
set(LSDA_OPENCV_COMPONENTS "")
foreach(_dep ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
  string(REGEX REPLACE "^opencv_" "" _component "${_dep}")
  list(APPEND LSDA_OPENCV_COMPONENTS ${_component})
endforeach()
list(JOIN LSDA_OPENCV_COMPONENTS " " LSDA_OPENCV_COMPONENTS)
configure_package_config_file("${LSDA_ROOT}/cmake/opencv_lsd_advanceConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/install/opencv_lsd_advanceConfig.cmake"
  INSTALL_DESTINATION "${LSDA_INSTALL_CMAKEDIR}")
# Same major version as requested and at least the requested one: OpenCV's own rule.
write_basic_package_version_file("${CMAKE_BINARY_DIR}/install/opencv_lsd_advanceConfigVersion.cmake"
  VERSION ${LSDA_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${CMAKE_BINARY_DIR}/install/opencv_lsd_advanceConfig.cmake"
              "${CMAKE_BINARY_DIR}/install/opencv_lsd_advanceConfigVersion.cmake"
  DESTINATION "${LSDA_INSTALL_CMAKEDIR}")

# pkg-config: written at install time, so that its prefix is the one given to
# `cmake --install --prefix` (CMAKE_INSTALL_PREFIX of the install script), not the configured one.
# So is bin/setup_vars_lsd_advance.sh, the environment of an install outside the system's
# directories (as OpenCV's bin/setup_vars_opencv4.sh); its PYTHONPATH line is there when the
# Python module is installed.
set(LSDA_PC_CFLAGS "")
foreach(_def ${LSDA_MODULE_DEFINITIONS})
  string(APPEND LSDA_PC_CFLAGS " -D${_def}")
endforeach()
set(LSDA_SETUP_PYTHONDIR "")
if(LSD_ADVANCE_PYTHON)
  set(LSDA_SETUP_PYTHONDIR "${LSD_ADVANCE_PYTHON_INSTALL_DIR}")
endif()
install(CODE "
  set(LSDA_TEMPLATE_DIR \"${LSDA_ROOT}/cmake\")
  set(LSDA_GENERATED_DIR \"${CMAKE_BINARY_DIR}/install\")
  set(LSDA_PC_CFLAGS \"${LSDA_PC_CFLAGS}\")
  set(LSDA_VERSION \"${LSDA_VERSION}\")
  set(LSDA_INSTALL_LIBDIR \"${CMAKE_INSTALL_LIBDIR}\")
  set(LSDA_INSTALL_INCLUDEDIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(LSDA_INSTALL_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
  set(LSDA_INSTALL_PYTHONDIR \"${LSDA_SETUP_PYTHONDIR}\")")
install(CODE [[
  set(LSDA_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  foreach(_dir LIBDIR INCLUDEDIR BINDIR PYTHONDIR)
    if(IS_ABSOLUTE "${LSDA_INSTALL_${_dir}}")
      set(LSDA_PC_${_dir} "${LSDA_INSTALL_${_dir}}")
      set(LSDA_SETUP_${_dir} "${LSDA_INSTALL_${_dir}}")
    else()
      set(LSDA_PC_${_dir} "\${prefix}/${LSDA_INSTALL_${_dir}}")
      set(LSDA_SETUP_${_dir} "${CMAKE_INSTALL_PREFIX}/${LSDA_INSTALL_${_dir}}")
    endif()
  endforeach()
  configure_file("${LSDA_TEMPLATE_DIR}/opencv_lsd_advance.pc.in" "${LSDA_GENERATED_DIR}/opencv_lsd_advance.pc" @ONLY)
  set(LSDA_SETUP_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(LSDA_SETUP_PYTHON_LINE "")
  if(LSDA_INSTALL_PYTHONDIR)
    set(LSDA_SETUP_PYTHON_LINE "export PYTHONPATH=\"${LSDA_SETUP_PYTHONDIR}\${PYTHONPATH:+:\$PYTHONPATH}\"")
  endif()
  configure_file("${LSDA_TEMPLATE_DIR}/setup_vars_lsd_advance.sh.in" "${LSDA_GENERATED_DIR}/setup_vars_lsd_advance.sh"
                 @ONLY)
]])
install(FILES "${CMAKE_BINARY_DIR}/install/opencv_lsd_advance.pc"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
install(PROGRAMS "${CMAKE_BINARY_DIR}/install/setup_vars_lsd_advance.sh" DESTINATION "${CMAKE_INSTALL_BINDIR}")

# Samples: the programs, with an RPATH to the installed library, and their sources (as OpenCV
# installs a module's samples). The apps are this repository's tooling: not installed.
if(LSDA_SAMPLE_TARGETS)
  file(RELATIVE_PATH _lsda_bin_to_lib "${CMAKE_INSTALL_FULL_BINDIR}" "${CMAKE_INSTALL_FULL_LIBDIR}")
  set_target_properties(${LSDA_SAMPLE_TARGETS} PROPERTIES INSTALL_RPATH "$ORIGIN/${_lsda_bin_to_lib}")
  install(TARGETS ${LSDA_SAMPLE_TARGETS} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
endif()
file(GLOB LSDA_SAMPLE_SOURCES CONFIGURE_DEPENDS "${LSDA_ROOT}/samples/*.cpp")
install(FILES ${LSDA_SAMPLE_SOURCES} DESTINATION "${LSDA_INSTALL_SAMPLESDIR}")

message(STATUS "lsd_advance: BUILD_TESTS=${BUILD_TESTS} BUILD_EXAMPLES=${BUILD_EXAMPLES} BUILD_APPS=${BUILD_APPS}")
