// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// cv::ximgproc::createLineSegmentDetector of the layout after the move (test only), compiled
// against the installed OpenCV: the real imgproc LSD behind the moved interface.

#include "opencv2/imgproc.hpp"
#include "include/opencv2/ximgproc/line_segment_detector.hpp"

namespace cv {
namespace ximgproc {

namespace {

class ForwardedLineSegmentDetector CV_FINAL : public LineSegmentDetector
{
public:
    explicit ForwardedLineSegmentDetector(const Ptr<cv::LineSegmentDetector>& real) : lsd(real) {}
    void detect(InputArray image, OutputArray lines, OutputArray width, OutputArray prec, OutputArray nfa) CV_OVERRIDE
    {
        lsd->detect(image, lines, width, prec, nfa);
    }
    void drawSegments(InputOutputArray image, InputArray lines) CV_OVERRIDE { lsd->drawSegments(image, lines); }
    int compareSegments(const Size& size, InputArray lines1, InputArray lines2, InputOutputArray image) CV_OVERRIDE
    {
        return lsd->compareSegments(size, lines1, lines2, image);
    }

private:
    Ptr<cv::LineSegmentDetector> lsd;
};

} // namespace

Ptr<LineSegmentDetector> createLineSegmentDetector(int refine, double scale, double sigma_scale, double quant,
                                                   double ang_th, double log_eps, double density_th, int n_bins)
{
    return makePtr<ForwardedLineSegmentDetector>(cv::createLineSegmentDetector(
        refine, scale, sigma_scale, quant, ang_th, log_eps, density_th, n_bins));
}

}} // namespace cv::ximgproc
