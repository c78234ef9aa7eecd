// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The layout of an OpenCV after opencv_contrib#4158 (test only): ximgproc with LineSegmentDetector.

#include_next <opencv2/ximgproc.hpp>
#include "opencv2/ximgproc/line_segment_detector.hpp"
