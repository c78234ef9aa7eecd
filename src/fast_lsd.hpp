// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the module's own implementation of the LSD algorithm (Grompone von
// Gioi, Jakubowicz, Morel, Randall, "LSD: a Line Segment Detector", IPOL 2012), written for
// speed from the published description. OpenCV's LineSegmentDetector is its test oracle.

#ifndef OPENCV_LSD_ADVANCE_FAST_LSD_HPP
#define OPENCV_LSD_ADVANCE_FAST_LSD_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "full_scale_smoothing.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//! The LSD algorithm with OpenCV's LineSegmentDetector parameters and output convention (segments
//! (x1, y1, x2, y2), pixel centres at integer coordinates, brighter side on the left), and options
//! options of its own (LSDParams::seedGradientRatio, LSDParams::seedAlignedNeighbours,
//! LSDParams::tileHeight). Every buffer is kept
//! by the object and reused, so that a sequence of frames of one size allocates nothing once
//! warm. Not safe to call from two threads at once; it runs its own work in cv::parallel_for_.
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
    //! A rectangle approximating a region (IPOL's "rect"): the segment (x1, y1)-(x2, y2) with its
    //! centre, unit direction, width, and the angle tolerance (radians) and probability used to
    //! validate it.
    struct Rect
    {
        double x1, y1, x2, y2, width, x, y, dx, dy, prec, p;
    };

    class Regions;
    struct Tile;
    class GradientRows;
    class TileRegions;
    class JoinedRegions;
    void layTiles();
    void computeGradient(const Mat& image);
    //! The seeds of the rows next to the seams, into their tiles.
    void seedSeamRows();
    void orderTile(Tile& tile);
    void joinAcrossSeams();
    //! The released region k (in the frame's numbering): its tile's regions, and its index there.
    const Regions& releasedPart(int k, int& local) const;
    //! Pixels of the joined region whose root is g.
    int joinedRegionSize(int g) const;
    //! The joined region whose root is g as region's current region, the part with the strongest
    //! seed first.
    void gatherJoinedRegion(int g, Regions& region) const;
    //! Bin of a pixel in the pseudo-ordering.
    int binOf(int pixel) const;
    //! How many of the two 8-neighbours of a pixel along its level line are aligned with it.
    int alignedNeighbours(int pixel) const;
    //! Writes from `next` on the pixels of row y whose norm reaches least and, when onEdges, with
    //! seedAlignedNeighbours aligned neighbours; returns the end.
    int* seedsOfRow(int y, float least, bool onEdges, int* next) const;
    //! cos(tolerance) in the scale of the level-line vectors: Regions::growRegion's argument.
    static float alignmentLimit(double tolerance);
    double rectLogNfa(const Rect& rect, std::vector<double>& logFactorials) const;
    double logNfa(int n, int k, double p, std::vector<double>& logFactorials) const;

    // Parameters (LSD's and ours), resolved to what the loops use.
    int refine;
    double scale, sigmaScale, quant, angleTolerance, logEps, densityThreshold, seedGradientRatio;
    int numBins, seedAlignedNeighbours, tileHeight, regionGrowth;

    // Per-frame state, sized for the largest frame seen (row stride = width + 1; one border row
    // and column of "undefined" pixels above and left, so that the 8 neighbours of any pixel with
    // a defined gradient are inside the buffers).
    Mat blurred, scaled, analysed;  //!< the image smoothed, at the analysis scale; a header of the one analysed
    FullScaleSmoothing fullScaleSmoothing;  //!< at scale 1: LSDParams::fullScaleSigma
    //! The mask at the analysis scale, and where the 2x2 support of each gradient is on it (empty
    //! without a mask).
    Mat scaledMask, gradientMask;
    int width = 0, height = 0, stride = 0;
    int threshold = 0;              //!< a pixel's gradient is defined when gx^2 + gy^2 > threshold
    float seedNorm = 0;             //!< gradient norm |g| / 2 from which a pixel seeds a region
    float binScale = 0;             //!< bin of the pseudo-ordering = |g| / 2 * binScale
    double logNT = 0;
    double tolerance = 0, probability = 0;  //!< the angle tolerance in radians, and as a probability
    float cosUnit = 0;
    int alignedDot = 0;             //!< two unit vectors are aligned when their dot product exceeds it
    int minRegionSize = 0;
    //! Unit level-line vector (-gy, gx) / |g| of each free pixel, times kUnit; (0, 0) for a pixel
    //! without a defined gradient, already in a region, or on a seam while the tiles grow.
    std::vector<Vec2s> level;
    std::vector<float> gradNorm;    //!< gradient norm |g| / 2 per pixel, 0 for an undefined one
    //! Per row of the image: the largest gx^2 + gy^2, the defined pixels.
    std::vector<int> rowMaxNorm2, rowDefined;

    // The tiles, top to bottom. The regions of a tile that reach a seam (the line between two
    // tiles) are set aside (released); after the tiles, those that are neighbours across a seam
    // with the same direction are joined into one region.
    std::vector<Tile> tiles;
    std::vector<int> releasedFirst;         //!< index in the frame of each tile's first released region
    std::vector<int> joinedTo;              //!< union-find links between the released regions
    std::vector<int> groupStart, groupFill, groupMembers;  //!< the released regions of each joined region
    Ptr<Regions> acrossSeams;               //!< validates the joined regions that grow again
    //! The joined regions large enough to be valid (their roots), the first of each task of
    //! them, what the task found for each (JoinedOutcome in fast_lsd.cpp) and its segment; the
    //! region buffers of each task.
    std::vector<int> joinedRoots, joinedTaskStart;
    std::vector<char> joinedOutcome;
    std::vector<Vec4f> joinedSegment;
    std::vector<Ptr<Regions> > joiningTasks;
};

}}} // namespace cv::ximgproc::lsda

#endif
