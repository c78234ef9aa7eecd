// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, both LSD bases: the light Gaussian pre-smoothing at scale 1 (LSDParams::fullScaleSigma).
// A staircase edge (a line drawn without anti-aliasing, a rendered frame) has 2x2 gradients whose
// directions swing past LSD's angle tolerance at every step; a Gaussian of half a pixel makes them
// agree again, as LSD's own Gaussian does below scale 1. A photograph's edges are already spread
// by its optics, and the Gaussian only blurs its fine structure: by default
// (LSDParams::fullScaleSmoothing SMOOTH_ALIASED_IMAGES) only images whose edges are mostly steps of
// one pixel are smoothed (hasAliasedEdges).

#ifndef OPENCV_LSD_ADVANCE_FULL_SCALE_SMOOTHING_HPP
#define OPENCV_LSD_ADVANCE_FULL_SCALE_SMOOTHING_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//! Whether most edges of a CV_8UC1 image are steps of one pixel, as where it was drawn or rendered
//! without anti-aliasing (or enlarged without interpolation). An edge here is a step of at least
//! 16 gray levels between two neighbours along a row or a column; it is a step of one pixel when
//! the pixels beyond them on either side each lie within a quarter of the step from one of its two
//! levels (a line one pixel wide has its other edge there). A photograph's edges are spread over
//! more pixels by its optics. The same for any number of threads (rows in parallel, counts summed);
//! counts is its scratch (two per stripe of rows), kept by the caller so that frames of one size
//! allocate nothing once warm.
CV_EXPORTS bool hasAliasedEdges(const Mat& gray, std::vector<int64>& counts);

//! A separable Gaussian of a CV_8UC1 image, each pass in 8-bit fixed point (weights that sum to
//! 256, the result rounded to 8 bits), with reflected borders (BORDER_REFLECT_101) that
//! read the image alone, never the pixels around a view. Rows in parallel, the same output for any
//! number of threads; its buffers only grow, so that frames of one size allocate nothing once warm.
//! Not safe to call from two threads at once.
class CV_EXPORTS FullScaleSmoothing
{
public:
    //! The Gaussian of sigma (px, in the range of LSDParams::fullScaleSigma) over LSD's support (3
    //! sigma of precision), for the images of `images` (one of LSDAdvance::FullScaleSmoothing).
    FullScaleSmoothing(double sigma, int images);
    //! Whether apply() never changes an image: sigma is 0, or too small to move a weight at 8 bits.
    bool isIdentity() const { return radius == 0; }
    //! The smoothed image, a header of the object's buffer valid until the next call; gray itself
    //! when the object smooths aliased images only and gray is not one (hasAliasedEdges).
    const Mat& apply(const Mat& gray);

private:
    class SmoothedRows;
    int radius = 0;                //!< the kernel's half-width, its zero weights trimmed
    bool aliasedOnly = false;      //!< LSDAdvance::SMOOTH_ALIASED_IMAGES
    std::vector<ushort> weights;   //!< weights[k] of the pixels k px away, k in [0, radius]
    std::vector<uchar> vertical;   //!< each row after the vertical pass, padded by radius either side
    std::vector<uchar> pixels;
    std::vector<int64> edgeCounts; //!< hasAliasedEdges' scratch
    Mat smoothed;
};

}}} // namespace cv::ximgproc::lsda

#endif
