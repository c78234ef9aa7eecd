// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_PERF_PRECOMP_HPP
#define OPENCV_LSD_ADVANCE_PERF_PRECOMP_HPP

#include "opencv2/ts.hpp"
#include "opencv2/lsd_advance.hpp"
#include "opencv2/imgproc.hpp"
#include "opencv2/imgcodecs.hpp"

#include <functional>

#endif
