// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_HPP
#define OPENCV_LSD_ADVANCE_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"

/** @defgroup lsd_advance Improved line segment detection for SLAM front ends

LSDAdvance post-processes the segments of OpenCV's line segment detector (@cite Rafael12) in the
three stages of @cite Guan2026: adaptive length suppression with an inter-frame factor, angle and
endpoint grouping, and similarity-ordered merging. It returns fewer, longer segments than LSD,
in LSD's format and orientation, so that it can replace LSD, FastLineDetector or EdgeDrawing in
existing code with one line.

The module lives in namespace cv::ximgproc, next to the detectors it complements.
*/

#endif
