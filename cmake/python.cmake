# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# Python module of the standalone build: `import lsd_advance` (python/, pybind11), the API of the
# in-tree cv2.ximgproc bindings for use with the distribution's cv2 (Debian: python3-opencv).
# In-tree, OpenCV's own generator makes the bindings (WRAP python) and this file is not used.
#
# Options:
#   LSD_ADVANCE_PYTHON=ON|OFF  build the module into <build>/python/lsd_advance/ (use it with
#                          PYTHONPATH=<build>/python). Default: ON when pybind11 (Debian: pybind11-dev)
#                          and the Python 3 headers (python3-dev) are found, OFF with sanitizers.
#   Python3_EXECUTABLE=<python>  interpreter to build for. Default: the first of `python3` on PATH
#                          and /usr/bin/python3 that imports numpy.
#   LSD_ADVANCE_PYTHON_INSTALL_DIR=<dir>  where `cmake --install` puts the package folder
#                          lsd_advance/, relative to the install prefix (or absolute). Default:
#                          lib/python3.X/dist-packages for Debian's Python (which searches
#                          /usr/local/lib/python3.X/dist-packages), lib/python3.X/site-packages otherwise.

set(_lsda_python_default OFF)
set(_lsda_python_missing "")
if(NOT DEFINED LSD_ADVANCE_PYTHON OR LSD_ADVANCE_PYTHON)
  if(NOT DEFINED Python3_EXECUTABLE)
    # A python3 without numpy cannot use the module: prefer one that has it.
    find_program(LSDA_PATH_PYTHON3 NAMES python3)
    mark_as_advanced(LSDA_PATH_PYTHON3)
    foreach(_py ${LSDA_PATH_PYTHON3} /usr/bin/python3)
      execute_process(COMMAND "${_py}" -c "import numpy" RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
      if(_rc EQUAL 0)
        set(Python3_EXECUTABLE "${_py}" CACHE FILEPATH "Python 3 interpreter of the lsd_advance module")
        break()
      endif()
    endforeach()
  endif()
  if(CMAKE_VERSION VERSION_LESS 3.18)
    find_package(Python3 QUIET COMPONENTS Interpreter Development)
  else()
    find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
  endif()
  if(Python3_FOUND)
    find_package(pybind11 CONFIG QUIET)
  endif()
  if(NOT Python3_FOUND)
    set(_lsda_python_missing "the Python 3 interpreter and headers (Debian: python3-dev python3-numpy)")
  elseif(NOT pybind11_FOUND)
    set(_lsda_python_missing "pybind11 (Debian: pybind11-dev python3-pybind11)")
  elseif(NOT LSD_ADVANCE_SANITIZE AND NOT LSD_ADVANCE_FUZZ)
    set(_lsda_python_default ON)
  endif()
endif()
option(LSD_ADVANCE_PYTHON "Build the Python module lsd_advance (pybind11)" ${_lsda_python_default})

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

set(LSDA_PYTHON_PACKAGE_DIR "${CMAKE_BINARY_DIR}/python/lsd_advance")
# NO_EXTRAS: no link-time optimisation, which costs build time for glue code (measured 49 s -> 29 s).
pybind11_add_module(lsda_python MODULE NO_EXTRAS "${LSDA_ROOT}/python/lsd_advance_python.cpp")
target_link_libraries(lsda_python PRIVATE opencv_lsd_advance ${LSDA_DEPS} ${LSDA_OPTIONAL_DEPS})
target_include_directories(lsda_python PRIVATE "${LSDA_ROOT}/src")  # the parameter tables
target_compile_definitions(lsda_python PRIVATE ${LSDA_MODULE_DEFINITIONS})
target_compile_options(lsda_python PRIVATE ${LSDA_WARNINGS})
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

message(STATUS "lsd_advance: Python module for ${Python3_EXECUTABLE} (${Python3_VERSION}, pybind11 ${pybind11_VERSION}) "
               "in ${LSDA_PYTHON_PACKAGE_DIR}; installs to ${_lsda_python_dest} (LSD_ADVANCE_PYTHON_INSTALL_DIR)")
