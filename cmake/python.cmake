# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Python module of the standalone build: `import lsd_advance`, for use with the distribution's cv2
# (Debian: python3-opencv). Its bindings are written by OpenCV's own generator from the public
# headers, as in-tree (WRAP python), with the generator and cv2's conversions taken from the
# OpenCV source tree of the installed version (cmake/opencv_source.cmake, with its contrib
# modules: ximgproc's and line_descriptor's misc/python headers); python/gen_lsd_advance.py and
# python/lsd_advance_module.cpp say how. In-tree this file is not used.
#
# Options:
#   LSD_ADVANCE_PYTHON=ON|OFF  build the module into <build>/python/lsd_advance/ (use it with
#                          PYTHONPATH=<build>/python). Default: ON when the Python 3 headers and
#                          numpy (Debian: python3-dev python3-numpy) and the OpenCV source tree are
#                          found, OFF with sanitizers or the fuzzer; a default of OFF because
#                          something was missing is not cached (the next configure looks again).
#                          ON fetches a missing source tree.
#   Python3_EXECUTABLE=<python>  interpreter to build for. Default: the first of `python3` on PATH
#                          and /usr/bin/python3 that imports cv2 and numpy.
#   LSD_ADVANCE_PYTHON_INSTALL_DIR=<dir>  where `cmake --install` puts the package folder
#                          lsd_advance/, relative to the install prefix (or absolute). Default:
#                          lib/python3.X/dist-packages for Debian's Python (which searches
#                          /usr/local/lib/python3.X/dist-packages), lib/python3.X/site-packages otherwise.

set(_lsda_python_default OFF)
set(_lsda_python_missing "")
if(NOT DEFINED LSD_ADVANCE_PYTHON OR LSD_ADVANCE_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE)
    # The module needs cv2 and numpy at run time: prefer an interpreter that has them.
    find_program(LSDA_PATH_PYTHON3 NAMES python3)
    mark_as_advanced(LSDA_PATH_PYTHON3)
    foreach(_py ${LSDA_PATH_PYTHON3} /usr/bin/python3)
      execute_process(COMMAND "${_py}" -c "import cv2, numpy" RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
      if(_rc EQUAL 0)
        set(Python3_EXECUTABLE "${_py}" CACHE FILEPATH "Python 3 interpreter of the lsd_advance module")
        break()
      endif()
    endforeach()
  endif()
  find_package(Python3 QUIET COMPONENTS Interpreter Development.Module NumPy)
  include("${CMAKE_CURRENT_LIST_DIR}/opencv_source.cmake")
  lsda_find_opencv_source("${LSD_ADVANCE_PYTHON}"
    "The Python module is written by OpenCV's binding generator of the OpenCV ${OpenCV_VERSION} source tree; or pass -DLSD_ADVANCE_PYTHON=OFF.")
  set(LSDA_PYTHON_SRC2 "${OPENCV_SOURCE_DIR}/modules/python/src2")
  set(LSDA_PYTHON_CONTRIB "${OPENCV_SOURCE_DIR}/contrib/modules")
  if(NOT Python3_FOUND)
    set(_lsda_python_missing "the Python 3 interpreter and headers and numpy (Debian: python3-dev python3-numpy)")
  elseif(NOT OPENCV_SOURCE_DIR)
    set(_lsda_python_missing "the OpenCV ${OpenCV_VERSION} source tree (scripts/fetch_opencv_source.sh, or -DOPENCV_SOURCE_DIR)")
  elseif(NOT EXISTS "${LSDA_PYTHON_SRC2}/gen2.py" OR NOT EXISTS "${LSDA_PYTHON_CONTRIB}/ximgproc/misc/python")
    set(_lsda_python_missing "OpenCV's binding generator and contrib modules in ${OPENCV_SOURCE_DIR} (modules/python/src2, contrib/modules)")
  elseif(NOT LSD_ADVANCE_SANITIZE AND NOT LSD_ADVANCE_FUZZ)
    set(_lsda_python_default ON)
  endif()
endif()
if(DEFINED LSD_ADVANCE_PYTHON OR _lsda_python_default)
  option(LSD_ADVANCE_PYTHON "Build the Python module lsd_advance (OpenCV's binding generator)" ${_lsda_python_default})
else()
  # Not asked for and not buildable now: decided again at the next configure, so that an OFF
  # cached while the source tree was missing does not keep the module out once it is there
  # (scripts/demo.sh configures without it, scripts/test.sh then with it).
  set(LSD_ADVANCE_PYTHON OFF)
endif()

if(NOT LSD_ADVANCE_PYTHON)
  if(_lsda_python_missing)
    message(STATUS "lsd_advance: Python module not built: ${_lsda_python_missing} not found")
  else()
    message(STATUS "lsd_advance: Python module not built (LSD_ADVANCE_PYTHON=OFF; its default with sanitizers or the fuzzer)")
  endif()
  return()
endif()
if(_lsda_python_missing)
  message(FATAL_ERROR "lsd_advance: LSD_ADVANCE_PYTHON=ON needs ${_lsda_python_missing}")
endif()

# The generator reads the public headers as OpenCV's build does, and the headers of the types of
# other modules they use from the installed OpenCV.
find_path(LSDA_OPENCV_INCLUDE_DIR opencv2/core.hpp HINTS ${OpenCV_INCLUDE_DIRS} NO_DEFAULT_PATH)
mark_as_advanced(LSDA_OPENCV_INCLUDE_DIR)
set(_gen_dir "${CMAKE_BINARY_DIR}/python_bindings")
set(_generated "")
foreach(_h include funcs enums types types_content modules modules_content)
  list(APPEND _generated "${_gen_dir}/pyopencv_generated_${_h}.h")
endforeach()
list(APPEND _generated "${_gen_dir}/pyopencv_foreign_types.h")
if(TARGET opencv_line_descriptor)
  set(_with_keylines 1)
else()
  set(_with_keylines 0)
endif()
add_custom_command(OUTPUT ${_generated}
  COMMAND "${CMAKE_COMMAND}" -E make_directory "${_gen_dir}"
  COMMAND "${Python3_EXECUTABLE}" "${LSDA_ROOT}/python/gen_lsd_advance.py" "${LSDA_PYTHON_SRC2}" "${_gen_dir}"
          "${LSDA_OPENCV_INCLUDE_DIR}" ${_with_keylines} ${LSDA_PUBLIC_HEADERS} > "${_gen_dir}/generator.log"
  DEPENDS "${LSDA_ROOT}/python/gen_lsd_advance.py" "${LSDA_PYTHON_SRC2}/gen2.py" "${LSDA_PYTHON_SRC2}/hdr_parser.py"
          ${LSDA_PUBLIC_HEADERS}
  COMMENT "lsd_advance: Python bindings by OpenCV's generator (${LSDA_PYTHON_SRC2}/gen2.py)")

set(LSDA_PYTHON_PACKAGE_DIR "${CMAKE_BINARY_DIR}/python/lsd_advance")
set(_cv2_sources "${LSDA_PYTHON_SRC2}/cv2_convert.cpp" "${LSDA_PYTHON_SRC2}/cv2_util.cpp" "${LSDA_PYTHON_SRC2}/cv2_numpy.cpp")
Python3_add_library(lsda_python MODULE WITH_SOABI "${LSDA_ROOT}/python/lsd_advance_module.cpp" ${_cv2_sources} ${_generated})
target_include_directories(lsda_python PRIVATE "${_gen_dir}" "${LSDA_PYTHON_SRC2}" "${LSDA_ROOT}/misc/python"
  "${LSDA_PYTHON_CONTRIB}/ximgproc/misc/python" "${LSDA_PYTHON_CONTRIB}/line_descriptor/misc/python")
# cv2_util.cpp needs a private header of core, which is not installed: searched last, so that the
# source tree shadows no installed header.
target_compile_options(lsda_python PRIVATE "-idirafter" "${OPENCV_SOURCE_DIR}/modules/core/include")
target_link_libraries(lsda_python PRIVATE opencv_lsd_advance Python3::NumPy ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
# HAVE_OPENCV_LSD_ADVANCE: what OpenCV's build defines for a module it wraps (misc/python's headers).
target_compile_definitions(lsda_python PRIVATE ${LSDA_MODULE_DEFINITIONS} HAVE_OPENCV_LSD_ADVANCE)
# OpenCV's own code is not held to the module's warnings (the generated code is, as in-tree).
set_source_files_properties(${_cv2_sources} PROPERTIES COMPILE_OPTIONS "-w")
set_source_files_properties("${LSDA_ROOT}/python/lsd_advance_module.cpp" PROPERTIES COMPILE_OPTIONS "${LSDA_WARNINGS}")
set_target_properties(lsda_python PROPERTIES
  OUTPUT_NAME _lsd_advance
  LIBRARY_OUTPUT_DIRECTORY "${LSDA_PYTHON_PACKAGE_DIR}")
configure_file("${LSDA_ROOT}/python/lsd_advance/__init__.py" "${LSDA_PYTHON_PACKAGE_DIR}/__init__.py" COPYONLY)

include(GNUInstallDirs)
execute_process(
  COMMAND "${Python3_EXECUTABLE}" -c
          "import sys; print('dist-packages' if any(p.endswith('/dist-packages') for p in sys.path) else 'site-packages')"
  OUTPUT_VARIABLE _lsda_site_folder OUTPUT_STRIP_TRAILING_WHITESPACE)
set(LSD_ADVANCE_PYTHON_INSTALL_DIR
  "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/${_lsda_site_folder}"
  CACHE PATH "Folder of the Python package lsd_advance/, relative to the install prefix (or absolute)")
set(_lsda_python_dest "${LSD_ADVANCE_PYTHON_INSTALL_DIR}/lsd_advance")
if(IS_ABSOLUTE "${_lsda_python_dest}")
  file(RELATIVE_PATH _lsda_python_to_lib "${_lsda_python_dest}" "${CMAKE_INSTALL_FULL_LIBDIR}")
else()
  # Both relative to the prefix: the path holds for any `cmake --install --prefix`.
  file(RELATIVE_PATH _lsda_python_to_lib "/prefix/${_lsda_python_dest}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
endif()
# The installed library next to it, and an OpenCV outside the linker's default directories.
set_target_properties(lsda_python PROPERTIES
  INSTALL_RPATH "$ORIGIN/${_lsda_python_to_lib}"
  INSTALL_RPATH_USE_LINK_PATH ON)
install(TARGETS lsda_python LIBRARY DESTINATION "${_lsda_python_dest}" COMPONENT python)
install(FILES "${LSDA_ROOT}/python/lsd_advance/__init__.py" DESTINATION "${_lsda_python_dest}" COMPONENT python)
# The Python samples next to the C++ ones.
file(GLOB LSDA_PYTHON_SAMPLES CONFIGURE_DEPENDS "${LSDA_ROOT}/samples/python/*.py")
install(PROGRAMS ${LSDA_PYTHON_SAMPLES} DESTINATION "${CMAKE_INSTALL_DATADIR}/opencv4/samples/lsd_advance/python"
  COMPONENT python)

message(STATUS "lsd_advance: Python module for ${Python3_EXECUTABLE} (${Python3_VERSION}), bindings by "
               "${LSDA_PYTHON_SRC2}/gen2.py, in ${LSDA_PYTHON_PACKAGE_DIR}; installs to ${_lsda_python_dest} "
               "(LSD_ADVANCE_PYTHON_INSTALL_DIR)")
