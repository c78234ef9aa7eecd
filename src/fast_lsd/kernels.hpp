// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD's vector kernels that are not inline (kernels.cpp), each with its scalar path
// (#else: the same integers and floats, for a build without universal intrinsics), and the 2x2
// gradient that they and the rectangles' NFA share.

#ifndef OPENCV_LSD_ADVANCE_FAST_LSD_KERNELS_HPP
#define OPENCV_LSD_ADVANCE_FAST_LSD_KERNELS_HPP

#include "parts.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

//! The 2x2 gradient of pixel x of a row (LSD's mask: A, B the pixel and its right neighbour, C, D
//! the two below).
inline void gradient2x2(const uchar* above, const uchar* below, int x, int& gx, int& gy)
{
    const int da = below[x + 1] - above[x];
    const int bc = above[x + 1] - below[x];
    gx = da + bc;
    gy = da - bc;
}

//! The gradient pass of a row of n pixels: the norm |g| / 2 (0 where undefined: gx^2 + gy^2 <=
//! threshold), the unit level-line vector (0, 0 where undefined; two shorts a pixel), the maximum
//! of gx^2 + gy^2 and the count of defined pixels.
void gradientRow(const uchar* above, const uchar* below, int n, int threshold, float* norm, short* level,
                 int& rowMax, int& defined);

//! Writes row + x from next on for each x in [0, n) where norm[x] >= least, in order; returns the
//! end. Writes past it, by up to kCompactionSlack.
int* strongPixels(const float* norm, int row, int n, float least, int* next);

//! Keeps, in place from seeds on, those of the candidates [candidate, end) with at least `needed` of
//! their two neighbours along the level line aligned (GradientField::alignedNeighbours); returns the
//! end of the seeds kept.
int* edgePixels(const GradientField& field, int needed, int alignedDot, const int* candidate, const int* end,
                int* seeds);

//! The extremes of the pixels' coordinates along the unit direction dir from (cx, cy) (lMin, lMax)
//! and across it (wMin, wMax), each starting from 0.
void regionExtents(const Point* pixel, int count, double cx, double cy, const Point2d& dir, double& lMin,
                   double& lMax, double& wMin, double& wMax);

}}}} // namespace cv::ximgproc::lsda::fast_lsd

#endif
