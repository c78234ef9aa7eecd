// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// OpenCV's LineSegmentDetector wherever the OpenCV built against has it: in cv (imgproc, up to
// 4.x) or in cv::ximgproc (where opencv#29349 and opencv_contrib#4158 move it), or, with neither,
// a stand-in whose factory throws StsNotImplemented. Found at compile time by C++ name lookup,
// with no configure step (the same in both builds): an unqualified name used inside
// cv::ximgproc::lsda is looked up in lsda, then cv::ximgproc, then cv, and only then in the global
// namespace, where the using-directive below puts the stand-in's names for lsda's code alone.
// BASE_LSD (base_detector.cpp) and the tests' oracle (test/opencv_lsd_oracle.hpp) use the names
// of lsda below.

#ifndef OPENCV_LSD_ADVANCE_OPENCV_LSD_HPP
#define OPENCV_LSD_ADVANCE_OPENCV_LSD_HPP

#include "opencv2/core.hpp"
#include "opencv2/imgproc.hpp"
#include "opencv2/ximgproc.hpp"
#include <type_traits>

//! The stand-in for an OpenCV without LineSegmentDetector: its interface, and a factory that throws.
namespace lsda_without_opencv_lsd {

enum LineSegmentDetectorModes
{
    LSD_REFINE_NONE = 0,
    LSD_REFINE_STD = 1,
    LSD_REFINE_ADV = 2
};

class LineSegmentDetector : public cv::Algorithm
{
public:
    virtual void detect(cv::InputArray image, cv::OutputArray lines, cv::OutputArray width = cv::noArray(),
                        cv::OutputArray prec = cv::noArray(), cv::OutputArray nfa = cv::noArray()) = 0;
    virtual void drawSegments(cv::InputOutputArray image, cv::InputArray lines) = 0;
    virtual int compareSegments(const cv::Size& size, cv::InputArray lines1, cv::InputArray lines2,
                                cv::InputOutputArray image = cv::noArray()) = 0;
};

inline cv::Ptr<LineSegmentDetector> createLineSegmentDetector(int = LSD_REFINE_STD, double = 0.8, double = 0.6,
                                                              double = 2.0, double = 22.5, double = 0,
                                                              double = 0.7, int = 1024)
{
    CV_Error(cv::Error::StsNotImplemented,
             "BASE_LSD: this OpenCV has no cv::LineSegmentDetector, neither in imgproc nor in ximgproc; "
             "use BASE_FAST_LSD (the LSD algorithm, the default base)");
}

} // namespace lsda_without_opencv_lsd

namespace cv {
namespace ximgproc {
namespace lsda {

using namespace ::lsda_without_opencv_lsd;

//! OpenCV's LSD: cv::ximgproc::LineSegmentDetector, cv::LineSegmentDetector or the stand-in.
typedef LineSegmentDetector OpenCVLineSegmentDetector;

//! Whether this OpenCV has a LineSegmentDetector (else BASE_LSD throws StsNotImplemented).
constexpr bool kHaveOpenCVLsd = !std::is_same<OpenCVLineSegmentDetector, ::lsda_without_opencv_lsd::LineSegmentDetector>::value;

//! cv::LineSegmentDetectorModes, wherever they are declared.
constexpr int kLsdRefineNone = LSD_REFINE_NONE, kLsdRefineStd = LSD_REFINE_STD, kLsdRefineAdv = LSD_REFINE_ADV;

//! createLineSegmentDetector() of OpenCV's LSD; throws StsNotImplemented without one.
inline Ptr<OpenCVLineSegmentDetector> createOpenCVLineSegmentDetector(int refine = kLsdRefineStd, double scale = 0.8,
                                                                      double sigmaScale = 0.6, double quant = 2.0,
                                                                      double angleTolerance = 22.5, double logEps = 0,
                                                                      double densityThreshold = 0.7, int numBins = 1024)
{
    return createLineSegmentDetector(refine, scale, sigmaScale, quant, angleTolerance, logEps, densityThreshold, numBins);
}

}}} // namespace cv::ximgproc::lsda

#endif
