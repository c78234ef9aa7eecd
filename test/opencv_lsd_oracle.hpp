// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// OpenCV's LSD for the tests (the oracle of BASE_FAST_LSD, BASE_LSD's reference), wherever this
// OpenCV has it (src/opencv_lsd.hpp): these names, declared in opencv_test, hide those of cv and
// cv::ximgproc, so that the tests read the same in every layout. Without an OpenCV LSD, a test
// that creates one is skipped with the reason.

#ifndef OPENCV_LSD_ADVANCE_TEST_OPENCV_LSD_ORACLE_HPP
#define OPENCV_LSD_ADVANCE_TEST_OPENCV_LSD_ORACLE_HPP

#include "opencv2/ts.hpp"
#include "../src/opencv_lsd.hpp"

namespace opencv_test {

typedef cv::ximgproc::lsda::OpenCVLineSegmentDetector LineSegmentDetector;

constexpr int LSD_REFINE_NONE = cv::ximgproc::lsda::kLsdRefineNone;
constexpr int LSD_REFINE_STD = cv::ximgproc::lsda::kLsdRefineStd;
constexpr int LSD_REFINE_ADV = cv::ximgproc::lsda::kLsdRefineAdv;

//! Skips the test when this OpenCV has no LineSegmentDetector.
inline void skipWithoutOpenCVLsd()
{
    if (!cv::ximgproc::lsda::kHaveOpenCVLsd)
        throw SkipTestException("this OpenCV has no cv::LineSegmentDetector (neither in imgproc nor in ximgproc)");
}

inline Ptr<LineSegmentDetector> createLineSegmentDetector(int refine = LSD_REFINE_STD, double scale = 0.8,
                                                          double sigmaScale = 0.6, double quant = 2.0,
                                                          double angleTolerance = 22.5, double logEps = 0,
                                                          double densityThreshold = 0.7, int numBins = 1024)
{
    skipWithoutOpenCVLsd();
    return cv::ximgproc::lsda::createOpenCVLineSegmentDetector(refine, scale, sigmaScale, quant, angleTolerance,
                                                               logEps, densityThreshold, numBins);
}

} // namespace opencv_test

#endif
