// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_HPP
#define OPENCV_LSD_ADVANCE_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "opencv2/lsd_advance/keylines.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"
#include "opencv2/lsd_advance/pose_evaluation.hpp"

/** @defgroup lsd_advance Improved line segment detection for SLAM front ends

LSDAdvance post-processes the segments of OpenCV's line segment detector (@cite Rafael12) in the
three stages of the method of Guan, Qian and Du @cite Guan2026 : adaptive length suppression
(with an inter-frame factor for sequences), angle and endpoint grouping, and similarity-ordered
merging. It returns
fewer, longer segments than LSD, in LSD's format and orientation, so that it can replace LSD,
FastLineDetector (@cite Lee14) or EdgeDrawing's EDLines (@cite akinlar2011edlines) in existing
code with one line; either of these two can also be its base detector.

The module also gives its lines as line_descriptor KeyLines for the LBD descriptor
(@cite LBD), computes that descriptor for KeyLines of any detector (computeLBD(): line_descriptor's
descriptors, byte for byte, faster), and has the evaluation tools behind its documented results: the structural
precision/recall protocol on YorkUrban-LineSegment (@cite Denis2008, @cite Cho2018), line
matching under a homography (HPatches, @cite Balntas2017) and epipolar checks on calibrated
sequences (KITTI, @cite Geiger2012).

The module lives in namespace cv::ximgproc, next to the detectors it complements; its evaluation
tools in cv::ximgproc::line_evaluation. doc/algorithm.md gives the formulas of the stages, the
presets, and where and why the module differs from the paper.
*/

/** @example samples/lsd_advance_demo.cpp
An example comparing LSDAdvance with OpenCV's LineSegmentDetector on building.jpg.
*/

#endif
