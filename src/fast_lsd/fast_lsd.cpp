// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the LSD algorithm (Grompone von Gioi et al., IPOL 2012) written for
// speed, its parts in order for a frame (parts.hpp says where each is). Where the time goes in a
// straightforward implementation, and what this one does instead:
// - level-line angles: none is computed; a pixel's unit level-line vector in fixed point is also
//   its state (gradient_seeds.cpp);
// - pseudo-ordering: a counting sort of the seeds into the bins of their gradient norm, instead of
//   a comparison sort of every pixel (tiles.cpp);
// - region growing: no bounds checks and no branch per neighbour (region_growth.cpp);
// - the NFA (refine = LSD_REFINE_ADV only): log(n!) from a table grown on demand (rectangles.cpp).
// Options of its own, each of which gives the LSD algorithm at 1, 0 or GROWTH_PER_PIXEL:
// - seeds above a gradient level (LSDParams::seedGradientRatio): regions are grown in order of
//   decreasing gradient, so a region only takes pixels weaker than its seed. Leaving out the seeds
//   below a level keeps exactly the regions of the stronger seeds and grows none of the weak ones;
// - seeds on edges (LSDParams::seedAlignedNeighbours): a pixel seeds only when its neighbours
//   along its level line are aligned with it, as on an edge. Half of the pixels grown otherwise
//   are in regions of texture too small to be segments;
// - tiles (LSDParams::tileHeight): regions grow in parallel in horizontal tiles, joined across
//   their seams (tiles.cpp); the output does not depend on the number of threads;
// - growth per neighbourhood (LSDParams::regionGrowth): the 8 neighbours of a region's pixel are
//   tested together against the region's direction before any of them joined (region_growth.cpp).
// The gradient runs in parallel over rows, the regions over tiles; nothing else depends on the
// order of the tasks.

#include "../precomp.hpp"
#include "fast_lsd.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace fast_lsd {

RegionRules::RegionRules(const LSDAdvance::LSDParams& p)
    : refine(p.refine), regionGrowth(p.regionGrowth), logEps(p.logEps), densityThreshold(p.densityThreshold),
      scale(p.scale), tolerance(CV_PI * p.angleTolerance / 180.0), probability(p.angleTolerance / 180.0),
      cosUnit(alignmentLimit(tolerance)), alignedDot((int)std::floor((double)cosUnit * kUnit))
{
}

void RegionRules::setFrame(int width, int height)
{
    logNT = 5.0 * (std::log10((double)width) + std::log10((double)height)) / 2.0 + std::log10(11.0);
    // Fewer points than this cannot give a meaningful segment, whatever their alignment.
    minRegionSize = (int)(-logNT / std::log10(probability));
}

} // namespace fast_lsd

FastLsd::FastLsd(const LSDAdvance::LSDParams& p)
    : params(p), fullScaleSmoothing(p.fullScaleSigma, p.fullScaleSmoothing), rules(p)
{
    // The parameters are in their ranges: those of the table of parameters.hpp, which every setter checks.
}

FastLsd::~FastLsd() = default;

std::vector<cv::Rect> FastLsd::tileAreas() const
{
    return tiling.areas(field.width);
}

const Mat* FastLsd::imageAtScale(const Mat& gray, const Mat& mask, const Mat*& maskAtScale)
{
    const Mat* image = &gray;
    maskAtScale = &mask;
    const double scale = params.scale;
    if (scale != 1.0)
    {
        // Anti-aliasing as the LSD algorithm prescribes: a Gaussian of sigma = sigmaScale / scale
        // over 3 sigma of precision, then the sub-sampling by scale (not by the ratio of rounded
        // sizes, which would move the samples).
        if (saturate_cast<int>(gray.cols * scale) <= 0 || saturate_cast<int>(gray.rows * scale) <= 0)
            return nullptr;
        const double sigma = scale < 1.0 ? params.sigmaScale / scale : params.sigmaScale;
        const int half = (int)std::ceil(sigma * std::sqrt(2.0 * 3.0 * std::log(10.0)));
        // BORDER_ISOLATED: the border of a view is reflected, as that of its copy, not read around it.
        GaussianBlur(gray, blurred, Size(2 * half + 1, 2 * half + 1), sigma, sigma, BORDER_REFLECT_101 | BORDER_ISOLATED);
        resize(blurred, scaled, Size(), scale, scale, INTER_LINEAR_EXACT);
        image = &scaled;
        if (!mask.empty())
        {
            resize(mask, scaledMask, Size(), scale, scale, INTER_NEAREST_EXACT);
            maskAtScale = &scaledMask;
        }
    }
    if (image->cols < 2 || image->rows < 2)
        return nullptr;
    // Pixels are addressed by int.
    if ((double)(image->cols + 1) * (image->rows + 1) >= (double)INT_MAX)
        CV_Error_(Error::StsOutOfRange,
                  ("BASE_FAST_LSD analyses at most 2^31 pixels (at its scale), got %dx%d; use a scale below 1 or BASE_LSD",
                   image->cols, image->rows));
    if (scale == 1.0 && !fullScaleSmoothing.isIdentity())
        image = &fullScaleSmoothing.apply(gray);
    return image;
}

void FastLsd::detect(const Mat& gray, std::vector<Vec4f>& segments, const Mat& mask)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "FastLsd: the image must be CV_8UC1");
    CV_Assert(mask.empty() || (mask.type() == CV_8UC1 && mask.size() == gray.size()));
    segments.clear();
    const Mat* maskAtScale = nullptr;
    const Mat* image = imageAtScale(gray, mask, maskAtScale);
    if (!image)
        return;
    // The gradient of pixel (x, y) reads the pixels (x..x+1, y..y+1).
    if (mask.empty())
        field.gradientMask.release();
    else
        erode(*maskAtScale, field.gradientMask, Mat::ones(2, 2, CV_8U), Point(0, 0));
    fast_lsd::computeGradient(*image, params, field);
    // The last row of the image has no gradient.
    tiling.lay(field.height - 1, params.tileHeight);
    rules.setFrame(field.width, field.height);
    tiling.seedSeamRows(field, rules, params.seedAlignedNeighbours);
    tiling.growTiles(field, rules, params.seedAlignedNeighbours);
    tiling.joinAcrossSeams(field, rules);
    tiling.appendSegments(segments);
}

}}} // namespace cv::ximgproc::lsda
