// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, both LSD bases: the light Gaussian pre-smoothing at scale 1 (LSDParams::fullScaleSigma).
// A staircase edge (a line drawn without anti-aliasing, a rendered frame) has 2x2 gradients whose
// directions swing past LSD's angle tolerance at every step; a Gaussian of half a pixel makes them
// agree again, as LSD's own Gaussian does below scale 1.

#ifndef OPENCV_LSD_ADVANCE_FULL_SCALE_SMOOTHING_HPP
#define OPENCV_LSD_ADVANCE_FULL_SCALE_SMOOTHING_HPP

#include "opencv2/core.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//! A separable Gaussian of a CV_8UC1 image, each pass in 8-bit fixed point (weights that sum to
//! 256, the result rounded to 8 bits), with reflected borders (BORDER_REFLECT_101) that
//! read the image alone, never the pixels around a view. Rows in parallel, the same output for any
//! number of threads; its buffers only grow, so that frames of one size allocate nothing once warm.
//! Not safe to call from two threads at once.
class CV_EXPORTS FullScaleSmoothing
{
public:
    //! The Gaussian of sigma (px, in the range of LSDParams::fullScaleSigma) over LSD's support (3
    //! sigma of precision).
    explicit FullScaleSmoothing(double sigma);
    //! Whether apply() changes an image: sigma is 0, or too small to move a weight at 8 bits.
    bool isIdentity() const { return radius == 0; }
    //! The smoothed image: a header of the object's buffer, valid until the next call.
    const Mat& apply(const Mat& gray);

private:
    class SmoothedRows;
    int radius = 0;                //!< the kernel's half-width, its zero weights trimmed
    std::vector<ushort> weights;   //!< weights[k] of the pixels k px away, k in [0, radius]
    std::vector<uchar> vertical;   //!< each row after the vertical pass, padded by radius either side
    std::vector<uchar> pixels;
    Mat smoothed;
};

}}} // namespace cv::ximgproc::lsda

#endif
