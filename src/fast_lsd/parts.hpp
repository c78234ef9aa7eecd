// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD's parts and what passes between them, one file each (src/fast_lsd/):
// - gradient_seeds.cpp: the gradient pass into a GradientField, and the seeds of a row;
// - region_growth.cpp: growRegion, a Region grown from a seed;
// - rectangles.cpp: a Region's rectangle, its refinement and its NFA (RegionGrower::emitRegion);
// - tiles.cpp: the tiles, each grown by its own RegionGrower, and the regions joined across their
//   seams (Tiling);
// - kernels.cpp, kernels.hpp: the vector kernels that are not inline (a gradient row, the
//   compaction of a row's seeds, a region's extents), each with its scalar path;
// - fast_lsd.cpp: FastLsd, the parts in order for a frame.
// A region travels explicitly, as the LSD algorithm's region does: growRegion fills a Region,
// regionToRect reads it and the refinement shrinks or regrows it. The pixels' state (GradientField)
// is shared by the tiles, each of which only writes the pixels of its own rows.

#ifndef OPENCV_LSD_ADVANCE_FAST_LSD_PARTS_HPP
#define OPENCV_LSD_ADVANCE_FAST_LSD_PARTS_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "../primitives.hpp"
#include <climits>
#include <vector>

// A function compiled as one of its own, never inlined.
#if defined(__GNUC__)
#define LSDA_NOINLINE __attribute__((noinline))
#else
#define LSDA_NOINLINE
#endif

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

//! The length of a unit level-line vector in the fixed point of GradientField::level.
constexpr float kUnit = 16384.f;

//! sin(22.5 deg) in that fixed point: a level line steps along an axis beyond it.
constexpr int kStep = (int)(0.38268343 * kUnit);

//! How far past its last seed seedsOfRow may write.
constexpr size_t kCompactionSlack = 4;

//! Whether a pixel's vector is not (0, 0): it has a defined gradient and is in no region yet.
inline bool isFree(const Vec2s& u)
{
    return (u[0] | u[1]) != 0;
}

inline double squaredDistance(double x1, double y1, double x2, double y2)
{
    return (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
}

//! cos(tolerance) in the scale of the level-line vectors: growRegion's argument.
inline float alignmentLimit(double tolerance)
{
    return (float)std::cos(tolerance) * kUnit;
}

//! Bin of a gradient norm in the pseudo-ordering: floor(norm * (numBins - 1) / maxNorm).
inline int binOfNorm(float norm, float binScale, int numBins)
{
    return std::min(numBins - 1, (int)(norm * binScale));
}

/** @brief The gradient of a frame at the analysis scale: the state of every pixel.

Buffers sized for the largest frame seen (row stride = width + 1; one border row and column of
undefined pixels above and left, so that the 8 neighbours of any pixel with a defined gradient are
inside the buffers). */
struct GradientField
{
    int width = 0, height = 0, stride = 0;
    int threshold = 0;    //!< a pixel's gradient is defined when gx^2 + gy^2 > threshold
    float seedNorm = 0;   //!< gradient norm |g| / 2 from which a pixel seeds a region
    float binScale = 0;   //!< bin of the pseudo-ordering = |g| / 2 * binScale
    int numBins = 0;
    //! Unit level-line vector (-gy, gx) / |g| of each free pixel, times kUnit; (0, 0) for a pixel
    //! without a defined gradient, already in a region, or on a seam while the tiles grow.
    std::vector<Vec2s> level;
    std::vector<float> gradNorm;         //!< gradient norm |g| / 2 per pixel, 0 for an undefined one
    std::vector<int> rowMaxNorm2, rowDefined;  //!< per row: the largest gx^2 + gy^2, the defined pixels
    Mat analysed;                        //!< the image analysed (a header)
    //! Where the 2x2 support of each gradient is on the mask (empty without a mask).
    Mat gradientMask;
    TaskLayout rowTasks;                 //!< the gradient pass's tasks

    int binOf(int pixel) const { return binOfNorm(gradNorm[pixel], binScale, numBins); }
    //! How many of the two 8-neighbours of a pixel along its level line are aligned with it.
    int alignedNeighbours(int pixel, int alignedDot) const;
};

//! The gradient of image (CV_8UC1, at least 2x2) into field, with LSD's threshold of params, and the
//! seed level; field.gradientMask is set before.
void computeGradient(const Mat& image, const LSDAdvance::LSDParams& params, GradientField& field);

//! Writes from `next` on the pixels of row y whose norm reaches least and, when needed > 0, with at
//! least `needed` aligned neighbours (alignedDot: GradientField::alignedNeighbours); returns the end.
//! Writes past it, by up to kCompactionSlack.
int* seedsOfRow(const GradientField& field, int y, float least, int needed, int alignedDot, int* next);

//! What a region must satisfy in a frame, from the parameters and the frame's size.
struct RegionRules
{
    explicit RegionRules(const LSDAdvance::LSDParams& params);
    void setFrame(int width, int height);

    const int refine, regionGrowth;
    const double logEps, densityThreshold, scale;
    const double tolerance, probability;  //!< the angle tolerance in radians, and as a probability
    const float cosUnit;                  //!< alignmentLimit(tolerance)
    const int alignedDot;                 //!< two unit vectors are aligned when their dot product exceeds it
    double logNT = 0;
    int minRegionSize = 0;                //!< fewer pixels cannot give a meaningful segment
};

//! A rectangle approximating a region (IPOL's "rect"): the segment (x1, y1)-(x2, y2) with its centre,
//! unit direction, width, and the angle tolerance (radians) and probability used to validate it.
struct RegionRect
{
    double x1, y1, x2, y2, width, x, y, dx, dy, prec, p;
};

//! A region: its pixels, in buffers that only grow.
struct Region
{
    //! Room for up to `pixels` pixels, and for a list of that many seeds in index.
    void reserve(size_t pixels);

    //! The buffer indices of its pixels (size of them; the seed first), with kCompactionSlack more.
    std::vector<int> index;
    std::vector<Vec2s> vector;  //!< their vectors (which GradientField::level no longer holds), when kept
    std::vector<Point> pixel;   //!< their coordinates, filled by regionToRect
    int size = 0;
    Point2f sum;                //!< the sum of their vectors: the region's direction
    //! Whether index and vector hold any region that can grow (a tile's: all its defined pixels);
    //! otherwise they grow with the region.
    bool fitsAnyRegion = true;
    //! Whether the pixels' vectors are kept: only the refinement grows a region again.
    bool keepsVectors = true;
    //! Whether it has a pixel next to the rows beyond its GrowthBounds, above and below.
    bool reachesAbove = false, reachesBelow = false;
};

//! Where a region grows: the buffer indices from which a pixel is in a tile's first row, from which
//! below its last; the rows beyond belong to other tiles (no limit at the image's border).
struct GrowthBounds
{
    int firstRow = 0, firstRowEnd = 0, lastRow = INT_MAX;
    bool bounded() const { return firstRowEnd > 0 || lastRow < INT_MAX; }
};

//! Grows region from seed (a free pixel) over the free pixels aligned with it within cosUnit
//! (alignmentLimit), the LSD algorithm's 8-connected growth in the way of rules.regionGrowth; the
//! pixels taken are marked (0, 0) in field.level.
void growRegion(GradientField& field, const GrowthBounds& bounds, int regionGrowth, int seed, float cosUnit,
                Region& region);

//! The rectangle of region (fills region.pixel) with the tolerance prec and probability p.
void regionToRect(const GradientField& field, Region& region, double prec, double p, RegionRect& rect);
//! Pixels of region per unit of its rectangle's area.
double density(const Region& region, const RegionRect& rect);
//! LSD_REFINE_STD's refinement of a region too sparse for its rectangle: regrown with a narrower
//! tolerance, then shrunk; false when nothing valid is left. The pixels let go become free again.
bool refineRegion(GradientField& field, const GrowthBounds& bounds, const RegionRules& rules, Region& region,
                  RegionRect& rect);
//! LSD_REFINE_ADV's variations of the rectangle; its -log10(NFA).
double improveRect(const GradientField& field, const RegionRules& rules, RegionRect& rect,
                   std::vector<double>& logFactorials);

//! The regions of a tile that reach a seam, set aside: region k has the pixels
//! index[start[k] .. start[k + 1]), their vectors, and the sum of them.
struct ReleasedRegions
{
    void clear();
    void add(const Region& region);
    int count() const { return (int)sum.size(); }
    int sizeOf(int k) const { return start[k + 1] - start[k]; }

    std::vector<int> index, start;
    std::vector<Vec2s> vector;
    std::vector<Point2f> sum;
};

struct Tile;

/** @brief A region grower: the seeds it grows from, the region being grown, the segments found,
and the regions a tile sets aside at its seams, in buffers that only grow. Each tile has one, the
joining of the regions across the seams others; they grow over the shared GradientField. */
class RegionGrower
{
public:
    //! Grows a region from each seed that is still free, in order; appends the segment of each
    //! valid one to segments. With a tile, a region with a pixel in a row next to one of the
    //! tile's seams is released instead (its pixels stay taken), to be joined across the seam.
    void detect(GradientField& field, const RegionRules& rules, Tile* tile);
    //! Validates the region (of at least rules.minRegionSize pixels), and appends its segment when
    //! it is valid.
    void emitRegion(GradientField& field, const RegionRules& rules);
    //! emitRegion for a region that is not grown again (dense enough at its first rectangle, or
    //! no refinement), which touches none of the field's pixels; false, and nothing done, for one
    //! that would be.
    bool emitUnlessRegrown(const GradientField& field, const RegionRules& rules);

    std::vector<int> seeds;       //!< in the order they grow
    std::vector<int> binStart;    //!< the pseudo-ordering's bins over seeds
    Region region;
    GrowthBounds bounds;
    std::vector<Vec4f> segments;
    ReleasedRegions released;

private:
    //! The bounds of a tile's growth, and its columns' released regions reset.
    void enterTile(const GradientField& field, Tile& tile);
    //! Sets the region aside (it reaches a seam of the tile) to be joined across the seam.
    void releaseAtSeams(Tile& tile);
    //! Appends the segment of rect once refined, when it is valid.
    void emitRect(const GradientField& field, const RegionRules& rules, RegionRect& rect);

    std::vector<double> logFactorials;  //!< log(n!) for n < size(), grown on demand
};

//! The rows [y0, y1) of gradient pixels, whose regions grow alone, and whether another tile is
//! above and below (the seam between them); for each column, the released region (-1: none)
//! with a pixel in the first row, and in the last.
struct Tile
{
    int y0 = 0, y1 = 0;
    bool seamAbove = false, seamBelow = false;
    std::vector<int> releasedAbove, releasedBelow;
    //! The seeds of the rows next to a seam, first and last (Tiling::seedSeamRows).
    std::vector<int> seedsAbove, seedsBelow;
    RegionGrower grower;
};

/** @brief The image cut into horizontal tiles laid out from its size alone, each grown in its own
task; the regions that reach the seam between two tiles are set aside, and those 8-connected across
it with the same direction then joined into one, so that a segment crossing a seam comes out whole.
The output does not depend on the number of threads. */
class Tiling
{
public:
    Tiling();
    //! Tiles of about tileHeight rows (0: one) over the rows with a gradient.
    void lay(int rows, int tileHeight);
    //! The seeds of the rows next to the seams, into their tiles, before the tiles grow.
    void seedSeamRows(const GradientField& field, const RegionRules& rules, int seedAlignedNeighbours);
    //! The regions of every tile, a task per tile.
    void growTiles(GradientField& field, const RegionRules& rules, int seedAlignedNeighbours);
    //! The released regions joined across the seams, validated.
    void joinAcrossSeams(GradientField& field, const RegionRules& rules);
    //! The segments of the tiles, then of the joined regions.
    void appendSegments(std::vector<Vec4f>& segments) const;
    //! The gradient pixels of each tile.
    std::vector<cv::Rect> areas(int width) const;

private:
    void joinNeighbours(const GradientField& field, const RegionRules& rules);
    void layJoinedTasks(const RegionRules& rules);
    void validateJoined(GradientField& field, const RegionRules& rules);
    //! The released region k (in the frame's numbering): its tile's regions, and its index there.
    const ReleasedRegions& releasedPart(int k, int& local) const;
    //! Pixels of the joined region whose root is g.
    int joinedRegionSize(int g) const;
    //! The joined region whose root is g into grower's region, the part with the strongest seed first.
    void gatherJoinedRegion(const GradientField& field, int g, RegionGrower& grower) const;

    std::vector<Tile> tiles;
    std::vector<int> releasedFirst;         //!< index in the frame of each tile's first released region
    UnionFind joined;                       //!< the released regions joined across the seams
    std::vector<int> rootOf;                //!< the root of each released region
    std::vector<int> groupStart, groupMembers;  //!< the released regions of each joined region
    RegionGrower acrossSeams;               //!< validates the joined regions that grow again
    //! The joined regions large enough to be valid (their roots) and their sizes, their tasks, what
    //! the task found for each (JoinedOutcome in tiles.cpp) and its segment; the grower of each task.
    std::vector<int> joinedRoots, joinedSizes;
    TaskLayout tileTasks, joinedTasks;
    std::vector<char> joinedOutcome;
    std::vector<Vec4f> joinedSegment;
    std::vector<RegionGrower> joiningGrowers;
};

}}}} // namespace cv::ximgproc::lsda::fast_lsd

#endif
