// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What passes between the parts of computeLBD (src/lbd/): the support region of a KeyLine and the
// tiles of the gradient it reads. lbd_descriptor.cpp checks the KeyLines, samples their regions and
// describes them; gradient_tiles.cpp computes the gradient in the tiles the regions reach.

#ifndef OPENCV_LSD_ADVANCE_LBD_PARTS_HPP
#define OPENCV_LSD_ADVANCE_LBD_PARTS_HPP

#include "../precomp.hpp"
#include <cstdint>
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {
namespace lbd {

// BinaryDescriptor's defaults: 9 bands of 7 rows across the line.
constexpr int kBands = 9;
constexpr int kBandRows = 7;
constexpr int kRegionRows = kBands * kBandRows;
// Rows sampled per line: the region's and one more, so that every group of four lanes is full
// (the extra row's sums are not used).
constexpr int kLanes = 4;
constexpr int kSampledRows = (kRegionRows + kLanes - 1) / kLanes * kLanes;
// The gradient is computed in tiles of kTile x kTile pixels, a band of tiles kChunkColumns wide
// at most per task (its buffers on the stack).
constexpr int kTile = 32;
constexpr int kChunkColumns = 256;

// What a KeyLine contributes, checked: its direction, the first sample of its region and the
// region's length.
struct LineRegion
{
    float c, s;    //!< cos and sin of KeyLine::angle
    float x0, y0;  //!< the first sample of the first row
    int length;    //!< samples per row (KeyLine::numOfPixels)
    bool inside;   //!< whether every sample rounds to a pixel of the image (none is clamped)
};

// Rows [y0, y1) and columns [x0, x1) of the gradient, within one row of tiles.
struct GradientChunk
{
    int y0, y1, x0, x1;
};

//! One chunk of the gradient into gradient (a row of the image per gray.cols words): (dx, dy) of
//! each pixel as two 16-bit halves, OpenCV's GaussianBlur then Sobel, bit for bit.
void computeGradientChunk(const Mat& gray, const GradientChunk& chunk, uint32_t* gradient);

//! Marks (in tiles, tilesX per row) the tiles whose pixels the samples of region r may read, and
//! returns whether each sample rounds to a pixel of the image.
bool markRegionTiles(const LineRegion& r, Size size, int tilesX, std::vector<uchar>& tiles);

//! The chunks of the marked tiles, row of tiles by row of tiles, runs of tiles cut at kChunkColumns.
void layChunks(const std::vector<uchar>& tiles, Size size, int tilesX, std::vector<GradientChunk>& chunks);

}}}} // namespace cv::ximgproc::lsda::lbd

#endif
