// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// cv::ximgproc::LineSegmentDetector as opencv_contrib#4158 declares it (imgproc's interface in
// the namespace cv::ximgproc), test only: line_segment_detector.cpp forwards it to the installed
// imgproc's implementation.

#ifndef LSDA_COMPAT_XIMGPROC_LINE_SEGMENT_DETECTOR_HPP
#define LSDA_COMPAT_XIMGPROC_LINE_SEGMENT_DETECTOR_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace ximgproc {

enum LineSegmentDetectorModes
{
    LSD_REFINE_NONE = 0,
    LSD_REFINE_STD = 1,
    LSD_REFINE_ADV = 2
};

class LineSegmentDetector : public Algorithm
{
public:
    virtual void detect(InputArray image, OutputArray lines, OutputArray width = noArray(),
                        OutputArray prec = noArray(), OutputArray nfa = noArray()) = 0;
    virtual void drawSegments(InputOutputArray image, InputArray lines) = 0;
    virtual int compareSegments(const Size& size, InputArray lines1, InputArray lines2,
                                InputOutputArray image = noArray()) = 0;
    virtual ~LineSegmentDetector() {}
};

Ptr<LineSegmentDetector> createLineSegmentDetector(int refine = LSD_REFINE_STD, double scale = 0.8,
                                                   double sigma_scale = 0.6, double quant = 2.0,
                                                   double ang_th = 22.5, double log_eps = 0,
                                                   double density_th = 0.7, int n_bins = 1024);

}} // namespace cv::ximgproc

#endif
