// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_PRECOMP_HPP
#define OPENCV_LSD_ADVANCE_PRECOMP_HPP

#include "opencv2/lsd_advance.hpp"
#include "opencv2/core/utility.hpp"
#include "opencv2/imgproc.hpp"

#ifdef __OPENCV_BUILD
#include "opencv2/core/private.hpp"
#else
// Distributions do not install core/private.hpp; without instrumentation it expands to this.
#include "opencv2/core/utils/trace.hpp"
#define CV_INSTRUMENT_REGION() CV_TRACE_FUNCTION()
#endif

#include "stages.hpp"

#endif
