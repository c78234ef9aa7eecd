// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the module's own implementation of the LSD algorithm (Grompone von
// Gioi, Jakubowicz, Morel, Randall, "LSD: a Line Segment Detector", IPOL 2012), written for
// speed from the published description. OpenCV's LineSegmentDetector is its test oracle. Its parts
// are the files of src/fast_lsd/ (parts.hpp).

#ifndef OPENCV_LSD_ADVANCE_FAST_LSD_HPP
#define OPENCV_LSD_ADVANCE_FAST_LSD_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "../full_scale_smoothing.hpp"
#include "parts.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//! The LSD algorithm with OpenCV's LineSegmentDetector parameters and output convention (segments
//! (x1, y1, x2, y2), pixel centres at integer coordinates, brighter side on the left), and options
//! of its own (LSDParams::seedGradientRatio, LSDParams::seedAlignedNeighbours,
//! LSDParams::tileHeight, LSDParams::regionGrowth). Every buffer is kept by the object and reused,
//! so that a sequence of frames of one size allocates nothing once warm. Not safe to call from two
//! threads at once; it runs its own work in cv::parallel_for_.
class CV_EXPORTS FastLsd
{
public:
    explicit FastLsd(const LSDAdvance::LSDParams& params);
    ~FastLsd();
    //! Segments of a CV_8UC1 image. With a mask (CV_8UC1 of the image's size; empty for none),
    //! a pixel whose gradient reads a masked-out (zero) pixel of the mask at the analysis scale
    //! is undefined, as a pixel of too low a gradient is: it neither seeds, nor joins a region,
    //! nor counts as aligned in a rectangle. Below scale 1 the mask is sub-sampled to the
    //! analysis scale as the image is, each pixel taking the mask's value at the full-resolution
    //! pixel nearest its centre (INTER_NEAREST_EXACT).
    void detect(const Mat& gray, std::vector<Vec4f>& segments, const Mat& mask = Mat());
    //! The tiles of the last frame: the gradient pixels (at the analysis scale) whose regions
    //! each grew alone.
    std::vector<cv::Rect> tileAreas() const;

private:
    //! The image at the analysis scale (LSDParams::scale, anti-aliased; at scale 1 pre-smoothed by
    //! LSDParams::fullScaleSigma), and the mask at that scale; null when too small for a gradient.
    const Mat* imageAtScale(const Mat& gray, const Mat& mask, const Mat*& maskAtScale);

    LSDAdvance::LSDParams params;
    Mat blurred, scaled, scaledMask;        //!< the image smoothed, at the analysis scale; the mask there
    FullScaleSmoothing fullScaleSmoothing;  //!< at scale 1: LSDParams::fullScaleSigma
    fast_lsd::GradientField field;
    fast_lsd::RegionRules rules;
    fast_lsd::Tiling tiling;
};

}}} // namespace cv::ximgproc::lsda

#endif
