# This file is part of OpenCV project.
# It is subject to the license terms in the LICENSE file found in the top-level directory
# of this distribution and at http://opencv.org/license.html.
#
# The OpenCV source tree of the installed OpenCV's version, for what distributions do not install:
# the test framework `ts` (cmake/opencv_ts.cmake) and the Python binding generator
# (modules/python/src2, cmake/python.cmake).
#
# lsda_find_opencv_source(<fetch> <why>) sets OPENCV_SOURCE_DIR (cached) to the first of
#   1. -DOPENCV_SOURCE_DIR=<tree>
#   2. environment variable OPENCV_SOURCE_DIR
#   3. ${XDG_CACHE_HOME:-$HOME/.cache}/lsd_advance/opencv-<OpenCV_VERSION> (default of
#      scripts/fetch_opencv_source.sh); with <fetch> ON fetched there at configure time when
#      missing, with OFF left unset when missing.
# A tree given (1, 2) or fetched must be of the installed version; otherwise configuring fails,
# with <why> in the message.

include_guard(GLOBAL)

if(DEFINED ENV{XDG_CACHE_HOME} AND NOT "$ENV{XDG_CACHE_HOME}" STREQUAL "")
  set(_lsda_cache_root "$ENV{XDG_CACHE_HOME}")
else()
  set(_lsda_cache_root "$ENV{HOME}/.cache")
endif()
set(LSDA_DEFAULT_OPENCV_SOURCE_DIR "${_lsda_cache_root}/lsd_advance/opencv-${OpenCV_VERSION}")

function(_lsda_source_version dir out_var)
  set(_hdr "${dir}/modules/core/include/opencv2/core/version.hpp")
  if(NOT EXISTS "${_hdr}")
    set(${out_var} "" PARENT_SCOPE)
    return()
  endif()
  file(STRINGS "${_hdr}" _lines REGEX "^#define[ \t]+CV_VERSION_(MAJOR|MINOR|REVISION)[ \t]+[0-9]+")
  foreach(_part MAJOR MINOR REVISION)
    string(REGEX REPLACE ".*#define[ \t]+CV_VERSION_${_part}[ \t]+([0-9]+).*" "\\1" _v_${_part} "${_lines}")
  endforeach()
  set(${out_var} "${_v_MAJOR}.${_v_MINOR}.${_v_REVISION}" PARENT_SCOPE)
endfunction()

function(lsda_find_opencv_source fetch why)
  set(_hint "${why} Pass -DOPENCV_SOURCE_DIR=<OpenCV ${OpenCV_VERSION} source tree>.")
  set(_dir "${OPENCV_SOURCE_DIR}")
  if(NOT _dir AND NOT "$ENV{OPENCV_SOURCE_DIR}" STREQUAL "")
    set(_dir "$ENV{OPENCV_SOURCE_DIR}")
  endif()
  if(NOT _dir)
    _lsda_source_version("${LSDA_DEFAULT_OPENCV_SOURCE_DIR}" _v)
    if(NOT _v STREQUAL OpenCV_VERSION)
      if(NOT fetch)
        return()
      endif()
      message(STATUS "lsd_advance: no OpenCV ${OpenCV_VERSION} source tree at ${LSDA_DEFAULT_OPENCV_SOURCE_DIR}; "
                     "fetching it with scripts/fetch_opencv_source.sh (needs Debian's deb-src, root or sudo)")
      execute_process(
        COMMAND bash "${LSDA_ROOT}/scripts/fetch_opencv_source.sh" "${LSDA_DEFAULT_OPENCV_SOURCE_DIR}"
        RESULT_VARIABLE _rc)
      if(NOT _rc EQUAL 0)
        message(FATAL_ERROR "lsd_advance: fetching the OpenCV source tree failed (exit ${_rc}). ${_hint}")
      endif()
    endif()
    set(_dir "${LSDA_DEFAULT_OPENCV_SOURCE_DIR}")
  endif()
  get_filename_component(_dir "${_dir}" ABSOLUTE)
  _lsda_source_version("${_dir}" _src_version)
  if(_src_version STREQUAL "")
    message(FATAL_ERROR "lsd_advance: OPENCV_SOURCE_DIR=${_dir} is not an OpenCV source tree "
                        "(no modules/core/include/opencv2/core/version.hpp). ${_hint}")
  endif()
  if(NOT _src_version STREQUAL OpenCV_VERSION)
    message(FATAL_ERROR "lsd_advance: OpenCV source tree ${_dir} is version ${_src_version}, "
                        "but the installed OpenCV (${OpenCV_DIR}) is ${OpenCV_VERSION}. They must match. ${_hint}")
  endif()
  set(OPENCV_SOURCE_DIR "${_dir}" CACHE PATH
      "OpenCV source tree (same version as the installed OpenCV), for ts and the Python binding generator" FORCE)
endfunction()
