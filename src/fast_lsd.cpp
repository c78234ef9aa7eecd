// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the LSD algorithm (Grompone von Gioi et al., IPOL 2012) written for
// speed. Where the time goes in a straightforward implementation, and what this one does instead:
// - level-line angles: no angle is ever computed. Each pixel keeps its unit level-line vector u in
//   16-bit fixed point (4 bytes a pixel, so that the neighbourhoods of random seeds stay in the
//   caches), and a pixel is aligned with a direction r within the tolerance t when u.r >= cos(t).
//   A pixel without a defined gradient, or already in a region, keeps u = (0, 0): the vector is
//   also the pixel's state, and one load answers both questions;
// - pseudo-ordering: a counting sort of the pixels with a defined gradient into the bins of their
//   gradient norm (raster order inside a bin), instead of a comparison sort of every pixel;
// - region growing: a border of undefined pixels around the buffers removes the bounds checks, the
//   test of a neighbour has no branch (whether a neighbour is free is as good as random), and the
//   region's direction is the sum of its unit vectors, kept in float;
// - the NFA (refine = LSD_REFINE_ADV only): log(n!) from a table grown on demand.
// Options of its own, each of which gives the LSD algorithm at 1, 0 or GROWTH_PER_PIXEL:
// - seeds above a gradient level (LSDParams::seedGradientRatio): regions are grown in order of
//   decreasing gradient, so a region only takes pixels weaker than its seed. Leaving out the seeds
//   below a level keeps exactly the regions of the stronger seeds and grows none of the weak ones;
// - seeds on edges (LSDParams::seedAlignedNeighbours): a pixel seeds only when its neighbours
//   along its level line are aligned with it, as on an edge. Half of the pixels grown otherwise
//   are in regions of texture too small to be segments;
// - tiles (LSDParams::tileHeight): the image is cut into horizontal tiles laid out from its size
//   alone. The regions of each tile grow over its own rows only, each tile in its own task; the
//   regions that reach the seam between two tiles are set aside, and those 8-connected across
//   it with the same direction are then joined into one, so that a segment crossing a seam comes
//   out whole. The output does not depend on the number of threads;
// - growth per neighbourhood (LSDParams::regionGrowth): the 8 neighbours of a region's pixel are
//   tested together, four at a time, against the region's direction before any of them joined,
//   with one branch where the LSD algorithm's growth has eight unpredictable ones.
// The gradient runs in parallel over rows, the regions over tiles; nothing else depends on the
// order of the tasks.

#include "precomp.hpp"
#include "fast_lsd.hpp"
#include "opencv2/core/hal/hal.hpp"
#include "opencv2/core/hal/intrin.hpp"
#include <cstring>
#include <functional>

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

// The length of a unit level-line vector in the fixed point of FastLsd::level.
constexpr float kUnit = 16384.f;

// sin(22.5 deg) in that fixed point: a level line steps along an axis beyond it.
constexpr int kStep = (int)(0.38268343 * kUnit);

// For a mask of four lanes: the set lanes first (a left-pack), and how many are set.
alignas(16) const int kPackedLanes[16][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 },
                                              { 2, 0, 0, 0 }, { 0, 2, 0, 0 }, { 1, 2, 0, 0 }, { 0, 1, 2, 0 },
                                              { 3, 0, 0, 0 }, { 0, 3, 0, 0 }, { 1, 3, 0, 0 }, { 0, 1, 3, 0 },
                                              { 2, 3, 0, 0 }, { 0, 2, 3, 0 }, { 1, 2, 3, 0 }, { 0, 1, 2, 3 } };
const int kLaneCount[16] = { 0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4 };

// How far past its last seed FastLsd::seedsOfRow may write.
constexpr size_t kCompactionSlack = 4;

// Rows of the image whose gradients are computed by one task of the parallel loop.
constexpr int kRowsPerStripe = 16;
// Pixels of joined regions per task, at least: most joined regions are small, and a task of a
// few costs the pool more than their rectangles.
constexpr int kJoinedPixelsPerTask = 2048;
// What a task found for a joined region: no segment, a segment, or none yet (it grows again).
enum JoinedOutcome : char { kRejected, kValid, kGrowsAgain };

// How many seeds ahead the neighbourhood of a seed is fetched into the cache.
constexpr int kPrefetchDistance = 4;

inline void prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    CV_UNUSED(address);
#endif
}

// The 2x2 gradient of pixel x of a row (LSD's mask: A, B the pixel and its right neighbour, C, D
// the two below).
inline void gradient2x2(const uchar* above, const uchar* below, int x, int& gx, int& gy)
{
    const int da = below[x + 1] - above[x];
    const int bc = above[x + 1] - below[x];
    gx = da + bc;
    gy = da - bc;
}

// The gradient pass of one row, in two loops without branches that the compiler vectorises (with
// cv::hal::sqrt32f between them): gx^2 + gy^2 into norm (1 where it is 0), its maximum and the
// count of defined pixels (gx^2 + gy^2 > threshold); ...
void gradientNorms(const uchar* __restrict above, const uchar* __restrict below, int n, int threshold,
                   float* __restrict norm, int& rowMax, int& defined)
{
    int maxNorm2 = 0, count = 0;
    for (int x = 0; x < n; x++)
    {
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const int n2 = gx * gx + gy * gy;
        norm[x] = (float)(n2 + (n2 == 0));
        count += n2 > threshold;
        maxNorm2 = maxNorm2 > n2 ? maxNorm2 : n2;
    }
    rowMax = maxNorm2;
    defined = count;
}

// ... then, from |g| in norm, the unit level-line vector (-gy, gx) / |g| in fixed point and the
// gradient norm |g| / 2 ((0, 0) and 0 for an undefined pixel).
void levelLines(const uchar* __restrict above, const uchar* __restrict below, int n, int threshold,
                float* __restrict norm, short* __restrict level)
{
    for (int x = 0; x < n; x++)
    {
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const float defined = (float)(gx * gx + gy * gy > threshold);
        const float scale = defined * (kUnit / norm[x]);
        level[2 * x] = (short)(-gy * scale);
        level[2 * x + 1] = (short)(gx * scale);
        norm[x] *= 0.5f * defined;
    }
}

// The gradient pass of a row: the norm |g| / 2 (0 where undefined), the unit level-line vector
// (0, 0 where undefined), the maximum of gx^2 + gy^2 and the count of defined pixels. Eight pixels
// at a time in one pass with the same float operations as the two loops above (bit-identical),
// which do the rest of the row.
void gradientRow(const uchar* above, const uchar* below, int n, int threshold, float* norm, short* level,
                 int& rowMax, int& defined)
{
    int x = 0, maxNorm2 = 0, count = 0;
#if CV_SIMD128
    const v_int32x4 limit = v_setall_s32(threshold), one = v_setall_s32(1);
    const v_float32x4 unit = v_setall_f32(kUnit), half = v_setall_f32(0.5f);
    // The maximum in float, exact (gx^2 + gy^2 <= 2 * 510^2 < 2^24): SSE2 has no 32-bit integer max.
    v_float32x4 maxima = v_setzero_f32();
    v_int32x4 counts = v_setzero_s32();
    for (; x + 8 <= n; x += 8)
    {
        const v_int16x8 a = v_reinterpret_as_s16(v_load_expand(above + x)), b = v_reinterpret_as_s16(v_load_expand(above + x + 1));
        const v_int16x8 c = v_reinterpret_as_s16(v_load_expand(below + x)), d = v_reinterpret_as_s16(v_load_expand(below + x + 1));
        const v_int16x8 da = d - a, bc = b - c, gx = da + bc, gy = da - bc;
        v_int16x8 pairs[2];
        v_zip(gx, gy, pairs[0], pairs[1]);
        v_int32x4 gx32[2], gy32[2];
        v_expand(gx, gx32[0], gx32[1]);
        v_expand(gy, gy32[0], gy32[1]);
        v_int32x4 ux[2], uy[2];
        for (int h = 0; h < 2; h++)
        {
            const v_int32x4 n2 = v_dotprod(pairs[h], pairs[h]);
            const v_int32x4 isDefined = n2 > limit;
            maxima = v_max(maxima, v_cvt_f32(n2));
            counts -= isDefined;
            const v_float32x4 root = v_sqrt(v_cvt_f32(n2 + ((n2 == v_setzero_s32()) & one)));
            // The loops' products by 1 or 0 as masks: x or +0 (x is positive), the same floats.
            const v_float32x4 def = v_reinterpret_as_f32(isDefined);
            const v_float32x4 scale = (unit / root) & def;
            ux[h] = v_trunc(v_cvt_f32(v_setzero_s32() - gy32[h]) * scale);
            uy[h] = v_trunc(v_cvt_f32(gx32[h]) * scale);
            v_store(norm + x + 4 * h, (root * half) & def);
        }
        v_store_interleave(level + 2 * x, v_pack(ux[0], ux[1]), v_pack(uy[0], uy[1]));
    }
    maxNorm2 = (int)v_reduce_max(maxima);
    count = v_reduce_sum(counts);
#endif
    if (x < n)
    {
        int tailMax, tailDefined;
        gradientNorms(above + x, below + x, n - x, threshold, norm + x, tailMax, tailDefined);
        hal::sqrt32f(norm + x, norm + x, n - x);
        levelLines(above + x, below + x, n - x, threshold, norm + x, level + 2 * x);
        maxNorm2 = std::max(maxNorm2, tailMax);
        count += tailDefined;
    }
    rowMax = maxNorm2;
    defined = count;
}

// The mask on a row of the gradient pass (inside: the gradient's 2x2 support is on the mask):
// the pixels outside made undefined, and the row's maximum and count of defined pixels over the
// others. A row wholly inside is left as it is.
void maskRow(const uchar* inside, const uchar* above, const uchar* below, int n, int threshold, float* norm,
             Vec2s* level, int& rowMax, int& defined)
{
    if (std::find(inside, inside + n, 0) == inside + n)
        return;
    int maxNorm2 = 0, count = 0;
    for (int x = 0; x < n; x++)
    {
        if (!inside[x])
        {
            norm[x] = 0.f;
            level[x] = Vec2s(0, 0);
            continue;
        }
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const int n2 = gx * gx + gy * gy;
        count += n2 > threshold;
        maxNorm2 = std::max(maxNorm2, n2);
    }
    rowMax = maxNorm2;
    defined = count;
}

// Whether a pixel's vector is not (0, 0): it has a defined gradient and is in no region yet.
inline bool isFree(const Vec2s& u)
{
    return (u[0] | u[1]) != 0;
}

inline double squaredDistance(double x1, double y1, double x2, double y2)
{
    return (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
}

// The start of part k of [0, length) cut into `parts` parts of equal size (to one pixel).
inline int partStart(int length, int parts, int k)
{
    return (int)((int64)length * k / parts);
}

// How many tiles of about tileHeight rows cut `rows` rows (one without tiles).
inline int tilesAlong(int rows, int tileHeight)
{
    return tileHeight == 0 ? 1 : std::max(1, (rows + tileHeight / 2) / tileHeight);
}

// Strides below this give the row of a buffer index exactly from (q + 0.5) / stride in double: the
// quotient then lies at least 0.5 / stride (>= 2^-19) from an integer, and q < 2^31 keeps the
// rounding error of the product below 2^-21.
constexpr int kExactRowStride = 1 << 18;

// Pixel (x, y) of buffer index q (row stride `stride`, one border row and column), by a
// multiplication, with no integer division; the rounding of q / stride is corrected for the
// strides that need it.
inline Point pixelAt(int q, int stride, double invStride)
{
    int y = (int)((q + 0.5) * invStride);
    if (stride >= kExactRowStride)
    {
        y += (y + 1) * stride <= q;
        y -= y * stride > q;
    }
    return Point(q - y * stride - 1, y - 1);
}

// Bin of a gradient norm in the pseudo-ordering: floor(norm * (numBins - 1) / maxNorm).
inline int binOfNorm(float norm, float binScale, int numBins)
{
    return std::min(numBins - 1, (int)(norm * binScale));
}

// The least float norm in a bin (bins grow with the norm).
float lowestNormOfBin(int bin, float binScale, int numBins)
{
    float norm = (float)bin / binScale;
    while (norm > 0 && binOfNorm(std::nextafter(norm, 0.f), binScale, numBins) >= bin)
        norm = std::nextafter(norm, 0.f);
    while (binOfNorm(norm, binScale, numBins) < bin)
        norm = std::nextafter(norm, FLT_MAX);
    return norm;
}

// log(n!) from a table grown on demand.
double logFactorial(int n, std::vector<double>& table)
{
    if (table.empty())
        table.push_back(0.0);
    while ((int)table.size() <= n)
        table.push_back(table.back() + std::log((double)table.size()));
    return table[n];
}

} // namespace

// A region grower: the seeds it grows from, the region being grown, the segments found, and the
// regions a tile sets aside at its seams, in buffers that only grow. Each tile has one, the
// joining of the regions across the seams another; they grow over the detector's shared buffers.
class FastLsd::Regions
{
public:
    //! Grows a region from each seed that is still free, in order; appends the segment of each
    //! valid one to segments. With a tile, a region with a pixel in a row next to one of the
    //! tile's seams is released instead (its pixels stay taken), to be joined across the seam.
    void detect(FastLsd& lsd, Tile* tile);
    //! Room for a region of up to `pixels` pixels, and for a list of that many seeds in regionIndex.
    void reserve(size_t pixels);

    std::vector<int> seeds;      //!< in the order they grow
    std::vector<int> binStart;   //!< the counting sort's bins
    //! The current region: the buffer indices of its pixels (regionSize of them; the seed first;
    //! before the regions of a tile, its seeds in raster order), their vectors (which level no
    //! longer holds), their coordinates (filled by regionToRect), and the sum of their vectors.
    std::vector<int> regionIndex;
    std::vector<Vec2s> regionVector;
    std::vector<Vec4f> segments;
    //! The released regions: region k has the pixels releasedIndex[releasedStart[k] ..
    //! releasedStart[k + 1]), with their vectors, and the sum of them in releasedSum.
    std::vector<int> releasedIndex, releasedStart;
    std::vector<Vec2s> releasedVector;
    std::vector<Point2f> releasedSum;
    int regionSize = 0;
    Point2f regionSum;
    //! Whether regionIndex and regionVector hold any region that can grow (a tile's: all its
    //! defined pixels); otherwise they grow with the region.
    bool fitsAnyRegion = true;
    //! Whether the pixels' vectors are kept in regionVector and releasedVector: only the
    //! refinement grows a region again (4 bytes per defined pixel otherwise).
    bool keepsVectors = true;
    //! While a tile grows: the buffer indices from which a pixel is in the tile's first row, from
    //! which below its last; the rows beyond belong to other tiles (no limit at the image's border).
    int firstRow = 0, firstRowEnd = 0, lastRow = INT_MAX;
    //! Whether the current region has a pixel in the tile's first row next to a seam, in its last
    //! (set by the growth of a tile's region, which tests every pixel's row anyway).
    bool reachesSeamAbove = false, reachesSeamBelow = false;

    //! Validates the current region (regionIndex, regionVector, regionSize, regionSum), of at least
    //! minRegionSize pixels, and appends its segment when it is valid.
    void emitRegion(FastLsd& lsd);
    //! emitRegion for a region that is not grown again (dense enough at its first rectangle, or
    //! no refinement), which touches none of the detector's pixels; false, and nothing done, for
    //! one that would be.
    bool emitUnlessRegrown(const FastLsd& lsd);

private:
    void growRegion(FastLsd& lsd, int seed, float cosUnit);
    template <bool perNeighbourhood> void growRegionAs(FastLsd& lsd, int seed, float cosUnit);
    template <bool acute, bool mayOutgrow, bool bounded, bool perNeighbourhood>
    void growRegionFrom(FastLsd& lsd, int seed, float cosUnit);
    //! Sets the current region aside (it reaches a seam of the tile) to be joined across the seam.
    void releaseAtSeams(Tile& tile);
    void regionToRect(const FastLsd& lsd, double prec, double p, Rect& rect);
    //! Appends the segment of rect once refined, when it is valid.
    void emitRect(const FastLsd& lsd, Rect& rect);
    double density(const Rect& rect) const;
    bool refineRegion(FastLsd& lsd, Rect& rect);
    bool shrinkRegionRadius(FastLsd& lsd, Rect& rect, double currentDensity);
    double improveRect(const FastLsd& lsd, Rect& rect);

    std::vector<Point> regionPixel;
    std::vector<double> logFactorials;  //!< log(n!) for n < size(), grown on demand
};

//! The rows [y0, y1) of gradient pixels, whose regions grow alone, and whether another tile is
//! above and below (the seam between them); for each column, the released region (-1: none)
//! with a pixel in the first row, and in the last.
struct FastLsd::Tile
{
    int y0 = 0, y1 = 0;
    bool seamAbove = false, seamBelow = false;
    std::vector<int> releasedAbove, releasedBelow;
    //! The seeds of the rows next to a seam, first and last (FastLsd::seedSeamRows).
    std::vector<int> seedsAbove, seedsBelow;
    Regions regions;
};

inline int FastLsd::binOf(int pixel) const
{
    return binOfNorm(gradNorm[pixel], binScale, numBins);
}

inline int FastLsd::alignedNeighbours(int pixel) const
{
    // The neighbour nearest to the level-line direction u: a step along x where |u_x| > sin(22.5
    // deg), along y where |u_y| is, and the one opposite.
    const Vec2s u = level[pixel];
    const int dx = (u[0] > kStep) - (u[0] < -kStep), dy = (u[1] > kStep) - (u[1] < -kStep);
    const int offset = dy * stride + dx;
    const Vec2s a = level[pixel + offset], b = level[pixel - offset];
    const int dotA = u[0] * a[0] + u[1] * a[1], dotB = u[0] * b[0] + u[1] * b[1];
    // A neighbour that is not free, (0, 0), has a product of 0: below a limit of 0 or more (a
    // tolerance under 90 deg) without a test of its own.
    if (alignedDot >= 0)
        return (dotA > alignedDot) + (dotB > alignedDot);
    return (isFree(a) & (dotA > alignedDot)) + (isFree(b) & (dotB > alignedDot));
}

FastLsd::FastLsd(const LSDAdvance::LSDParams& p)
    : refine(p.refine), scale(p.scale), sigmaScale(p.sigmaScale), quant(p.quant),
      angleTolerance(p.angleTolerance), logEps(p.logEps), densityThreshold(p.densityThreshold),
      seedGradientRatio(p.seedGradientRatio), numBins(p.numBins), seedAlignedNeighbours(p.seedAlignedNeighbours),
      tileHeight(p.tileHeight), regionGrowth(p.regionGrowth), fullScaleSmoothing(p.fullScaleSigma, p.fullScaleSmoothing), acrossSeams(makePtr<Regions>())
{
    // The parameters are in their ranges: those of the table of parameters.hpp, which every setter checks.
    acrossSeams->fitsAnyRegion = false;
}

FastLsd::~FastLsd() = default;

std::vector<cv::Rect> FastLsd::tileAreas() const
{
    std::vector<cv::Rect> areas;
    for (const Tile& t : tiles)
        areas.emplace_back(0, t.y0, width - 1, t.y1 - t.y0);
    return areas;
}

// The gradient pass over a range of rows (a loop body rather than a lambda: std::function would
// allocate for it on every frame).
class FastLsd::GradientRows CV_FINAL : public ParallelLoopBody
{
public:
    GradientRows(FastLsd& detector, const Mat& gray) : lsd(detector), image(gray) {}
    void operator()(const Range& rows) const CV_OVERRIDE
    {
        const int n = lsd.width - 1;
        for (int y = rows.start; y < rows.end; y++)
        {
            const uchar* above = image.ptr<uchar>(y);
            const uchar* below = image.ptr<uchar>(y + 1);
            const size_t row = (size_t)(y + 1) * lsd.stride + 1;
            float* norm = &lsd.gradNorm[row];
            gradientRow(above, below, n, lsd.threshold, norm, &lsd.level[row][0], lsd.rowMaxNorm2[y], lsd.rowDefined[y]);
            if (!lsd.gradientMask.empty())
                maskRow(lsd.gradientMask.ptr<uchar>(y), above, below, n, lsd.threshold, norm, &lsd.level[row],
                        lsd.rowMaxNorm2[y], lsd.rowDefined[y]);
            lsd.level[row - 1] = lsd.level[row + n] = Vec2s(0, 0);
        }
    }

private:
    FastLsd& lsd;
    const Mat& image;
};

// The regions of the tiles, a task per tile.
class FastLsd::TileRegions CV_FINAL : public ParallelLoopBody
{
public:
    explicit TileRegions(FastLsd& detector) : lsd(detector) {}
    void operator()(const Range& range) const CV_OVERRIDE
    {
        for (int t = range.start; t < range.end; t++)
        {
            Tile& tile = lsd.tiles[t];
            lsd.orderTile(tile);
            tile.regions.detect(lsd, tile.seamAbove || tile.seamBelow ? &tile : nullptr);
        }
    }

private:
    FastLsd& lsd;
};

// The joined regions that are not grown again, a task per range of them, each with its own
// region buffers; the pixels of the detector are only read.
class FastLsd::JoinedRegions CV_FINAL : public ParallelLoopBody
{
public:
    explicit JoinedRegions(FastLsd& detector) : lsd(detector) {}
    void operator()(const Range& range) const CV_OVERRIDE
    {
        for (int t = range.start; t < range.end; t++)
        {
            Regions& region = *lsd.joiningTasks[t];
            region.segments.clear();
            for (int i = lsd.joinedTaskStart[t]; i < lsd.joinedTaskStart[t + 1]; i++)
            {
                lsd.gatherJoinedRegion(lsd.joinedRoots[i], region);
                const size_t found = region.segments.size();
                if (!region.emitUnlessRegrown(lsd))
                    lsd.joinedOutcome[i] = kGrowsAgain;
                else if (region.segments.size() > found)
                {
                    lsd.joinedOutcome[i] = kValid;
                    lsd.joinedSegment[i] = region.segments.back();
                }
                else
                    lsd.joinedOutcome[i] = kRejected;
            }
        }
    }

private:
    FastLsd& lsd;
};

void FastLsd::detect(const Mat& gray, std::vector<Vec4f>& segments, const Mat& mask)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "FastLsd: the image must be CV_8UC1");
    CV_Assert(mask.empty() || (mask.type() == CV_8UC1 && mask.size() == gray.size()));
    segments.clear();
    const Mat* image = &gray;
    const Mat* maskAtScale = &mask;
    if (scale != 1.0)
    {
        // Anti-aliasing as the LSD algorithm prescribes: a Gaussian of sigma = sigmaScale / scale
        // over 3 sigma of precision, then the sub-sampling by scale (not by the ratio of rounded
        // sizes, which would move the samples).
        if (saturate_cast<int>(gray.cols * scale) <= 0 || saturate_cast<int>(gray.rows * scale) <= 0)
            return;
        const double sigma = scale < 1.0 ? sigmaScale / scale : sigmaScale;
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
        return;
    // Pixels are addressed by int.
    if ((double)(image->cols + 1) * (image->rows + 1) >= (double)INT_MAX)
        CV_Error_(Error::StsOutOfRange,
                  ("BASE_FAST_LSD analyses at most 2^31 pixels (at its scale), got %dx%d; use a scale below 1 or BASE_LSD",
                   image->cols, image->rows));
    if (scale == 1.0 && !fullScaleSmoothing.isIdentity())
        image = &fullScaleSmoothing.apply(gray);

    analysed = *image;
    // The gradient of pixel (x, y) reads the pixels (x..x+1, y..y+1).
    if (mask.empty())
        gradientMask.release();
    else
        erode(*maskAtScale, gradientMask, Mat::ones(2, 2, CV_8U), Point(0, 0));
    width = image->cols;
    height = image->rows;
    stride = width + 1;
    layTiles();
    computeGradient(*image);

    tolerance = CV_PI * angleTolerance / 180.0;
    probability = angleTolerance / 180.0;
    logNT = 5.0 * (std::log10((double)width) + std::log10((double)height)) / 2.0 + std::log10(11.0);
    // Fewer points than this cannot give a meaningful segment, whatever their alignment.
    minRegionSize = (int)(-logNT / std::log10(probability));
    // Once per frame: most seeds grow no region, and a cosine per seed cost 4 % of the time.
    cosUnit = alignmentLimit(tolerance);
    alignedDot = (int)std::floor((double)cosUnit * kUnit);

    seedSeamRows();
    parallel_for_(Range(0, (int)tiles.size()), TileRegions(*this), (double)tiles.size());
    joinAcrossSeams();
    for (const Tile& t : tiles)
        segments.insert(segments.end(), t.regions.segments.begin(), t.regions.segments.end());
    segments.insert(segments.end(), acrossSeams->segments.begin(), acrossSeams->segments.end());
}

void FastLsd::layTiles()
{
    // The last row of the image has no gradient.
    const int rows = height - 1;
    const int count = tilesAlong(rows, tileHeight);
    tiles.resize(count);
    for (int k = 0; k < count; k++)
    {
        Tile& t = tiles[k];
        t.seamAbove = k > 0;
        t.seamBelow = k + 1 < count;
        t.y0 = partStart(rows, count, k);
        t.y1 = partStart(rows, count, k + 1);
    }
}

void FastLsd::computeGradient(const Mat& image)
{
    const size_t total = (size_t)stride * (height + 1);
    // Norm threshold rho = quant / sin(tolerance); a pixel is defined when its norm |g| / 2 > rho,
    // i.e. gx^2 + gy^2 > 4 rho^2, compared exactly on integers.
    const double rho = quant / std::sin(CV_PI * angleTolerance / 180.0);
    const double bound = std::floor(4.0 * rho * rho);
    threshold = bound >= (double)INT_MAX ? INT_MAX : (int)bound;

    // Every pixel of level is written below: the rows' gradients, the border and the pixels without
    // a gradient (last row and column) as (0, 0); and one more (0, 0) past the last row, which the
    // test of four neighbours at a time reads (GROWTH_PER_NEIGHBOURHOOD).
    level.resize(total + 1);
    std::fill(level.begin(), level.begin() + stride, Vec2s(0, 0));
    std::fill(level.end() - stride - 1, level.end(), Vec2s(0, 0));
    gradNorm.resize(total);
    rowMaxNorm2.assign(height - 1, 0);
    rowDefined.assign(height - 1, 0);

    parallel_for_(Range(0, height - 1), GradientRows(*this, image), std::max(1.0, (height - 1) / (double)kRowsPerStripe));

    const int maxNorm2 = *std::max_element(rowMaxNorm2.begin(), rowMaxNorm2.end());
    const double maxNorm = 0.5 * std::sqrt((double)maxNorm2);
    binScale = maxNorm2 > 0 ? (float)((numBins - 1) / maxNorm) : 0.f;

    // The seeds are the pixels of the bins from that of seedGradientRatio * rho up: the first
    // seeds of the LSD algorithm's order, so that the regions grown are exactly its first ones.
    // seedNorm is the least norm in those bins (undefined pixels have a norm of 0).
    const double seedLevel = seedGradientRatio * rho;
    if (seedGradientRatio == 1.0 || maxNorm2 == 0)
        seedNorm = FLT_MIN;
    else if (seedLevel > maxNorm)
        seedNorm = FLT_MAX;
    else
        seedNorm = std::max(lowestNormOfBin(binOfNorm((float)seedLevel, binScale, numBins), binScale, numBins), FLT_MIN);
}

void FastLsd::orderTile(Tile& tile)
{
    int defined = 0;
    for (int y = tile.y0; y < tile.y1; y++)
        defined += rowDefined[y];
    Regions& r = tile.regions;
    r.keepsVectors = refine >= kLsdRefineStd;
    r.reserve(defined);
    // The seeds in raster order, in regionIndex until the regions need it (all of them free: the
    // tile's regions have not grown yet); those of the rows next to a seam were chosen before the
    // tiles grew.
    int* next = r.regionIndex.data();
    for (int y = tile.y0; y < tile.y1; y++)
    {
        const std::vector<int>* seam = y == tile.y0 && tile.seamAbove ? &tile.seedsAbove
                                       : y == tile.y1 - 1 && tile.seamBelow ? &tile.seedsBelow : nullptr;
        next = seam ? std::copy(seam->begin(), seam->end(), next) : seedsOfRow(y, seedNorm, seedAlignedNeighbours > 0, next);
    }
    const int count = (int)(next - r.regionIndex.data());
    r.seeds.resize(count);
    // Highest bin first; inside a bin, raster order (a stable counting sort).
    r.binStart.assign((size_t)numBins + 1, 0);
    int* counts = r.binStart.data();
    for (int i = 0; i < count; i++)
        counts[numBins - 1 - binOf(r.regionIndex[i])]++;
    int position = 0;
    for (int b = 0; b <= numBins; b++)
    {
        const int n = counts[b];
        counts[b] = position;
        position += n;
    }
    for (int i = 0; i < count; i++)
        r.seeds[counts[numBins - 1 - binOf(r.regionIndex[i])]++] = r.regionIndex[i];
}

void FastLsd::seedSeamRows()
{
    // A row next to a seam seeds at every gradient level: a segment that crosses the seam from a
    // stronger part in the other tile has its part here grown and joined. With seeds on edges, only
    // the pixels aligned with one of their three neighbours across the seam, as a segment crossing
    // it is (not the texture along it). Chosen before the tiles grow: those neighbours are pixels
    // that the other tile takes while this one grows.
    const bool onEdges = seedAlignedNeighbours > 0;
    for (Tile& t : tiles)
    {
        const auto seedsOf = [&](int y, int across, std::vector<int>& seeds) {
            seeds.resize(width - 1 + kCompactionSlack);
            int* const first = seeds.data();
            int* next = seedsOfRow(y, FLT_MIN, false, first);
            if (onEdges)
                next = std::remove_if(first, next, [&](int q) {
                    const Vec2s u = level[q];
                    for (int o = q + across - 1; o <= q + across + 1; o++)
                    {
                        const Vec2s a = level[o];
                        if (isFree(a) && u[0] * a[0] + u[1] * a[1] > alignedDot)
                            return false;
                    }
                    return true;
                });
            seeds.resize(next - first);
        };
        if (t.seamAbove)
            seedsOf(t.y0, -stride, t.seedsAbove);
        if (t.seamBelow)
            seedsOf(t.y1 - 1, stride, t.seedsBelow);
    }
}

int* FastLsd::seedsOfRow(int y, float least, bool onEdges, int* next) const
{
    // Two compactions without a branch per pixel (seeds and other pixels alternate at random in
    // textured areas): the pixels whose norm reaches least, four at a time, then in place those of
    // them on edges. Most pixels are below the seed level, so the test of the neighbours runs on
    // a few. Every pixel of the first is written and the end moves on past the seeds, so it
    // writes past the last, by up to kCompactionSlack.
    const int row = (y + 1) * stride + 1, n = width - 1;
    const float* norm = &gradNorm[row];
    int* const strong = next;
    int x = 0;
#if CV_SIMD128
    const v_float32x4 leastNorm = v_setall_f32(least);
    for (; x + 4 <= n; x += 4)
    {
        const int lanes = v_signmask(v_load(norm + x) >= leastNorm);
        v_store(next, v_setall_s32(row + x) + v_load(kPackedLanes[lanes]));
        next += kLaneCount[lanes];
    }
#endif
    for (; x < n; x++)
    {
        *next = row + x;
        next += norm[x] >= least;
    }
    if (!onEdges)
        return next;
    int* seeds = strong;
    const int* candidate = strong;
#if CV_SIMD128
    // alignedNeighbours() four candidates at a time when its limit is 0 or more, in the same
    // integers: a vector (u_x, u_y) as one 32-bit lane, its products with a neighbour's in one
    // v_dotprod.
    if (alignedDot >= 0)
    {
        const auto word = [&](int pixel) {
            int w;
            std::memcpy(&w, &level[pixel], sizeof w);
            return w;
        };
        const v_int32x4 limit = v_setall_s32(alignedDot), axis = v_setall_s32(kStep), minusAxis = v_setall_s32(-kStep);
        const v_int32x4 rowStep = v_setall_s32(stride), needed = v_setall_s32(seedAlignedNeighbours);
        for (; candidate + 4 <= next; candidate += 4)
        {
            const int q[4] = { candidate[0], candidate[1], candidate[2], candidate[3] };
            const v_int32x4 u(word(q[0]), word(q[1]), word(q[2]), word(q[3]));
            const v_int32x4 ux = v_shr<16>(v_shl<16>(u)), uy = v_shr<16>(u);
            // The step along the level line: (u > kStep) - (u < -kStep) per axis, from the masks (-1).
            const v_int32x4 dx = (ux < minusAxis) - (ux > axis);
            const v_int32x4 offset = ((uy > axis) & rowStep) - ((uy < minusAxis) & rowStep) + dx;
            int off[4];
            v_store(off, offset);
            const v_int32x4 a(word(q[0] + off[0]), word(q[1] + off[1]), word(q[2] + off[2]), word(q[3] + off[3]));
            const v_int32x4 b(word(q[0] - off[0]), word(q[1] - off[1]), word(q[2] - off[2]), word(q[3] - off[3]));
            const v_int16x8 u16 = v_reinterpret_as_s16(u);
            const v_int32x4 aligned = v_setzero_s32() - (v_dotprod(u16, v_reinterpret_as_s16(a)) > limit) -
                                      (v_dotprod(u16, v_reinterpret_as_s16(b)) > limit);
            const int keep = v_signmask(aligned >= needed);
            for (int j = 0; j < 4; j++)
            {
                *seeds = q[j];
                seeds += (keep >> j) & 1;
            }
        }
    }
#endif
    for (; candidate < next; candidate++)
    {
        const int q = *candidate;
        *seeds = q;
        seeds += alignedNeighbours(q) >= seedAlignedNeighbours;
    }
    return seeds;
}

void FastLsd::joinAcrossSeams()
{
    Regions& joined = *acrossSeams;
    joined.keepsVectors = refine >= kLsdRefineStd;
    joined.segments.clear();
    if (tiles.size() == 1)
        return;
    releasedFirst.resize(tiles.size() + 1);
    releasedFirst[0] = 0;
    for (size_t t = 0; t < tiles.size(); t++)
        releasedFirst[t + 1] = releasedFirst[t] + (int)tiles[t].regions.releasedSum.size();
    const int released = releasedFirst.back();

    // Two released regions of tiles t and t + 1 are joined when pixels of theirs are neighbours
    // across the seam between them (one column apart at most) and their directions agree within
    // the angle tolerance, as a pixel joins a region.
    joinedTo.resize(released);
    for (int k = 0; k < released; k++)
        joinedTo[k] = k;
    const auto root = [&](int k) {
        while (joinedTo[k] != k)
            k = joinedTo[k] = joinedTo[joinedTo[k]];
        return k;
    };
    const double cosTolerance = std::cos(tolerance);
    const int columns = width - 1;
    for (size_t t = 0; t + 1 < tiles.size(); t++)
    {
        const Tile &upper = tiles[t], &lower = tiles[t + 1];
        for (int x = 0; x < columns; x++)
        {
            const int a = upper.releasedBelow[x];
            if (a < 0)
                continue;
            const Point2f& sa = upper.regions.releasedSum[a];
            for (int bx = std::max(0, x - 1); bx <= std::min(columns - 1, x + 1); bx++)
            {
                const int b = lower.releasedAbove[bx];
                if (b < 0)
                    continue;
                const Point2f& sb = lower.regions.releasedSum[b];
                if (sa.dot(sb) < cosTolerance * std::sqrt((double)sa.dot(sa) * sb.dot(sb)))
                    continue;
                const int ra = root(releasedFirst[t] + a), rb = root(releasedFirst[t + 1] + b);
                joinedTo[std::max(ra, rb)] = std::min(ra, rb);
            }
        }
    }

    // The released regions of each joined region, in order; a region's root is its first.
    for (int k = 0; k < released; k++)
        joinedTo[k] = root(k);
    groupStart.assign((size_t)released + 1, 0);
    for (int k = 0; k < released; k++)
        groupStart[joinedTo[k] + 1]++;
    for (int k = 0; k < released; k++)
        groupStart[k + 1] += groupStart[k];
    groupFill.assign(groupStart.begin(), groupStart.end() - 1);
    groupMembers.resize(released);
    for (int k = 0; k < released; k++)
        groupMembers[groupFill[joinedTo[k]]++] = k;

    // The joined regions large enough to be valid, in tasks of at least kJoinedPixelsPerTask
    // pixels, laid out from the regions alone.
    joinedRoots.clear();
    joinedTaskStart.clear();
    int taskPixels = 0;
    for (int g = 0; g < released; g++)
    {
        if (joinedTo[g] != g)
            continue;
        const int size = joinedRegionSize(g);
        if (size < minRegionSize)
            continue;
        if (joinedTaskStart.empty() || taskPixels >= kJoinedPixelsPerTask)
        {
            joinedTaskStart.push_back((int)joinedRoots.size());
            taskPixels = 0;
        }
        taskPixels += size;
        joinedRoots.push_back(g);
    }
    const int tasks = (int)joinedTaskStart.size();
    joinedTaskStart.push_back((int)joinedRoots.size());
    while ((int)joiningTasks.size() < tasks)
    {
        joiningTasks.push_back(makePtr<Regions>());
        joiningTasks.back()->fitsAnyRegion = false;
        joiningTasks.back()->keepsVectors = false;  // they grow no region again
    }
    joinedOutcome.resize(joinedRoots.size());
    joinedSegment.resize(joinedRoots.size());
    parallel_for_(Range(0, tasks), JoinedRegions(*this), tasks);
    // In order: the segments of the tasks, and the regions that grow again, over pixels that
    // the regions grown again before them may have freed.
    for (size_t i = 0; i < joinedRoots.size(); i++)
    {
        if (joinedOutcome[i] == kValid)
            joined.segments.push_back(joinedSegment[i]);
        else if (joinedOutcome[i] == kGrowsAgain)
        {
            gatherJoinedRegion(joinedRoots[i], joined);
            joined.emitRegion(*this);
        }
    }
}

const FastLsd::Regions& FastLsd::releasedPart(int k, int& local) const
{
    const int t = (int)(std::upper_bound(releasedFirst.begin(), releasedFirst.end(), k) - releasedFirst.begin()) - 1;
    local = k - releasedFirst[t];
    return tiles[t].regions;
}

int FastLsd::joinedRegionSize(int g) const
{
    int size = 0, local;
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
    {
        const Regions& r = releasedPart(groupMembers[m], local);
        size += r.releasedStart[local + 1] - r.releasedStart[local];
    }
    return size;
}

void FastLsd::gatherJoinedRegion(int g, Regions& region) const
{
    // The joined region grows from the strongest seed of its parts (highest bin, then raster
    // order), as it would have without the seams: that part's pixels come first.
    int first = g, firstSeed = -1, local;
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
    {
        const Regions& r = releasedPart(groupMembers[m], local);
        const int seed = r.releasedIndex[r.releasedStart[local]];
        if (firstSeed < 0 || binOf(seed) > binOf(firstSeed) || (binOf(seed) == binOf(firstSeed) && seed < firstSeed))
        {
            first = groupMembers[m];
            firstSeed = seed;
        }
    }
    region.reserve(joinedRegionSize(g));
    region.regionSize = 0;
    region.regionSum = Point2f(0, 0);
    const auto append = [&](int k) {
        const Regions& r = releasedPart(k, local);
        const int begin = r.releasedStart[local], end = r.releasedStart[local + 1];
        std::copy(r.releasedIndex.begin() + begin, r.releasedIndex.begin() + end, region.regionIndex.begin() + region.regionSize);
        if (region.keepsVectors)
            std::copy(r.releasedVector.begin() + begin, r.releasedVector.begin() + end, region.regionVector.begin() + region.regionSize);
        region.regionSize += end - begin;
        region.regionSum += r.releasedSum[local];
    };
    append(first);
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
        if (groupMembers[m] != first)
            append(groupMembers[m]);
}

void FastLsd::Regions::reserve(size_t pixels)
{
    // regionIndex holds more: the compaction of the seeds writes past the last.
    if (regionIndex.size() < pixels + kCompactionSlack)
        regionIndex.resize(pixels + kCompactionSlack);
    if (keepsVectors && regionVector.size() < pixels)
        regionVector.resize(pixels);
}

void FastLsd::Regions::detect(FastLsd& lsd, Tile* tile)
{
    segments.clear();
    releasedIndex.clear();
    releasedVector.clear();
    releasedStart.assign(1, 0);
    releasedSum.clear();
    firstRow = 0;
    firstRowEnd = 0;
    lastRow = INT_MAX;
    if (tile)
    {
        tile->releasedAbove.assign(tile->seamAbove ? lsd.width - 1 : 0, -1);
        tile->releasedBelow.assign(tile->seamBelow ? lsd.width - 1 : 0, -1);
        if (tile->seamAbove)
        {
            firstRow = (tile->y0 + 1) * lsd.stride;
            firstRowEnd = firstRow + lsd.stride;
        }
        if (tile->seamBelow)
            lastRow = tile->y1 * lsd.stride;
    }
    const Vec2s* level = lsd.level.data();
    const int count = (int)seeds.size(), stride = lsd.stride;
    for (int i = 0; i < count; i++)
    {
        // Seeds jump across the image: fetch the neighbourhood of a coming one while this one grows.
        if (i + kPrefetchDistance < count)
        {
            const int coming = seeds[i + kPrefetchDistance];
            prefetch(&level[coming - stride]);
            prefetch(&level[coming]);
            prefetch(&level[coming + stride]);
        }
        const int seed = seeds[i];
        if (!isFree(level[seed]))
            continue;
        growRegion(lsd, seed, lsd.cosUnit);
        if (tile && (reachesSeamAbove || reachesSeamBelow))
        {
            releaseAtSeams(*tile);
            continue;
        }
        if (regionSize >= lsd.minRegionSize)
            emitRegion(lsd);
    }
}

void FastLsd::Regions::emitRegion(FastLsd& lsd)
{
    Rect rect;
    regionToRect(lsd, lsd.tolerance, lsd.probability, rect);
    if (lsd.refine >= kLsdRefineStd && !refineRegion(lsd, rect))
        return;
    emitRect(lsd, rect);
}

bool FastLsd::Regions::emitUnlessRegrown(const FastLsd& lsd)
{
    Rect rect;
    regionToRect(lsd, lsd.tolerance, lsd.probability, rect);
    if (lsd.refine >= kLsdRefineStd && density(rect) < lsd.densityThreshold)
        return false;
    emitRect(lsd, rect);
    return true;
}

void FastLsd::Regions::emitRect(const FastLsd& lsd, Rect& rect)
{
    if (lsd.refine >= kLsdRefineAdv && improveRect(lsd, rect) <= lsd.logEps)
        return;
    // The 2x2 gradient of pixel (x, y) is that of the point (x + 0.5, y + 0.5).
    Vec4f s((float)(rect.x1 + 0.5), (float)(rect.y1 + 0.5), (float)(rect.x2 + 0.5), (float)(rect.y2 + 0.5));
    if (lsd.scale != 1.0)
        s *= (float)(1.0 / lsd.scale);
    segments.push_back(s);
}

void FastLsd::Regions::releaseAtSeams(Tile& tile)
{
    const int region = (int)releasedSum.size();
    for (int i = 0; i < regionSize; i++)
    {
        const int q = regionIndex[i];
        if (q < firstRowEnd)
            tile.releasedAbove[q - firstRow - 1] = region;
        if (q >= lastRow)
            tile.releasedBelow[q - lastRow - 1] = region;
    }
    releasedIndex.insert(releasedIndex.end(), regionIndex.begin(), regionIndex.begin() + regionSize);
    if (keepsVectors)
        releasedVector.insert(releasedVector.end(), regionVector.begin(), regionVector.begin() + regionSize);
    releasedStart.push_back((int)releasedIndex.size());
    releasedSum.push_back(regionSum);
}

template <bool acute, bool mayOutgrow, bool bounded, bool perNeighbourhood>
void FastLsd::Regions::growRegionFrom(FastLsd& lsd, int seed, float cosUnit)
{
    // A pixel joins when its unit level-line vector u is within the tolerance of the region's
    // direction, the sum S of its pixels' vectors: u.S >= cos(tolerance) |u| |S| (= limit). A pixel
    // that joins keeps (0, 0), its vector going to regionVector when kept. With an acute tolerance the test
    // is strict, so that a (0, 0) vector fails it without a test of its own; equality has no
    // weight on real data.
    if (mayOutgrow && regionIndex.size() < 9 + kCompactionSlack)
        reserve(9);
    Vec2s* u = lsd.level.data();
    int* region = regionIndex.data();
    Vec2s* kept = regionVector.data();
    const bool keeping = keepsVectors;
    int capacity = (int)(regionIndex.size() - kCompactionSlack);

    float sx = u[seed][0], sy = u[seed][1];
    float limit = cosUnit * std::sqrt(sx * sx + sy * sy);
    region[0] = seed;
    if (keeping)
        kept[0] = u[seed];
    u[seed] = Vec2s(0, 0);
    int size = 1;
    const auto join = [&](int q) {
        const Vec2s v = u[q];
        if (keeping)
            kept[size] = v;
        region[size++] = q;
        u[q] = Vec2s(0, 0);
        sx += v[0];
        sy += v[1];
    };
    const auto visit = [&](int q) {
        const Vec2s v = u[q];
        const float d = sx * v[0] + sy * v[1];
        // No branch until the outcome: whether a neighbour is free is as good as random.
        const bool joins = acute ? d > limit : (isFree(v) & (d >= limit));
        if (!joins)
            return;
        join(q);
        limit = cosUnit * std::sqrt(sx * sx + sy * sy);
    };
#if CV_SIMD128
    v_float32x4 dirX = v_setall_f32(sx), dirY = v_setall_f32(sy), least = v_setall_f32(limit);
#endif
    // GROWTH_PER_NEIGHBOURHOOD: which of the four pixels from q on pass the test of visit(), a bit
    // each, with the same float operations (the vectors one 32-bit lane each).
    const auto aligned4 = [&](int q) -> unsigned {
#if CV_SIMD128
        const v_int32x4 w = v_reinterpret_as_s32(v_load((const short*)(u + q)));
        const v_float32x4 d = v_cvt_f32(v_shr<16>(v_shl<16>(w))) * dirX + v_cvt_f32(v_shr<16>(w)) * dirY;
        return (unsigned)v_signmask(acute ? d > least : (d >= least) & v_reinterpret_as_f32(w != v_setzero_s32()));
#else
        unsigned lanes = 0;
        for (int k = 0; k < 4; k++)
        {
            const Vec2s v = u[q + k];
            const float d = sx * v[0] + sy * v[1];
            lanes |= (unsigned)(acute ? d > limit : (isFree(v) && d >= limit)) << k;
        }
        return lanes;
#endif
    };
    // The 8 neighbours row by row, as the published algorithm visits them: per pixel, the order
    // decides which pixels join, since the region's direction changes with every pixel.
    const int s = lsd.stride;
    const int neighbours[8] = { -s - 1, -s, -s + 1, -1, 1, s - 1, s, s + 1 };
    bool above = false, below = false;
    for (int i = 0; i < size; i++)
    {
        if (mayOutgrow && size + 8 > capacity)
        {
            reserve(2 * (size_t)capacity + 8);
            region = regionIndex.data();
            kept = regionVector.data();
            capacity = (int)(regionIndex.size() - kCompactionSlack);
        }
        const int c = region[i];
        // In a tile, the neighbours in the rows of the tiles above and below are not its own.
        const bool visitsAbove = !bounded || c >= firstRowEnd, visitsBelow = !bounded || c < lastRow;
        above |= !visitsAbove;
        below |= !visitsBelow;
        if (perNeighbourhood)
        {
            // The neighbours that pass against the direction before any of them joined, in the
            // order of neighbours[]: one test of the 3 (4) pixels of each row, one branch when none
            // joins (most neighbours are taken, undefined or of another direction).
            const unsigned middle = aligned4(c - 1);
            unsigned joining = ((middle & 1u) << 3) | ((middle & 4u) << 2);
            if (visitsAbove)
                joining |= aligned4(c - s - 1) & 7u;
            if (visitsBelow)
                joining |= (aligned4(c + s - 1) & 7u) << 5;
            if (!joining)
                continue;
            do
            {
                join(c + neighbours[trailingZeros32(joining)]);
                joining &= joining - 1;
            } while (joining);
            limit = cosUnit * std::sqrt(sx * sx + sy * sy);
#if CV_SIMD128
            dirX = v_setall_f32(sx);
            dirY = v_setall_f32(sy);
            least = v_setall_f32(limit);
#endif
            continue;
        }
        if (visitsAbove)
        {
            visit(c - s - 1);
            visit(c - s);
            visit(c - s + 1);
        }
        visit(c - 1);
        visit(c + 1);
        if (visitsBelow)
        {
            visit(c + s - 1);
            visit(c + s);
            visit(c + s + 1);
        }
    }
    regionSize = size;
    regionSum = Point2f(sx, sy);
    reachesSeamAbove = above;
    reachesSeamBelow = below;
}

float FastLsd::alignmentLimit(double tolerance)
{
    return (float)std::cos(tolerance) * kUnit;
}

template <bool perNeighbourhood>
void FastLsd::Regions::growRegionAs(FastLsd& lsd, int seed, float cosUnit)
{
    const bool bounded = firstRowEnd > 0 || lastRow < INT_MAX;
    if (cosUnit > 0)
    {
        if (!fitsAnyRegion)
            growRegionFrom<true, true, false, perNeighbourhood>(lsd, seed, cosUnit);
        else if (bounded)
            growRegionFrom<true, false, true, perNeighbourhood>(lsd, seed, cosUnit);
        else
            growRegionFrom<true, false, false, perNeighbourhood>(lsd, seed, cosUnit);
    }
    else if (!fitsAnyRegion)
        growRegionFrom<false, true, false, perNeighbourhood>(lsd, seed, cosUnit);
    else if (bounded)
        growRegionFrom<false, false, true, perNeighbourhood>(lsd, seed, cosUnit);
    else
        growRegionFrom<false, false, false, perNeighbourhood>(lsd, seed, cosUnit);
}

void FastLsd::Regions::growRegion(FastLsd& lsd, int seed, float cosUnit)
{
    if (lsd.regionGrowth == LSDAdvance::GROWTH_PER_NEIGHBOURHOOD)
        growRegionAs<true>(lsd, seed, cosUnit);
    else
        growRegionAs<false>(lsd, seed, cosUnit);
}

void FastLsd::Regions::regionToRect(const FastLsd& lsd, double prec, double p, Rect& rect)
{
    // Centre of mass and inertia of the region, each pixel weighted by its gradient norm, from
    // moments about the seed in one pass.
    if ((int)regionPixel.size() < regionSize)
        regionPixel.resize(regionSize);  // grows to the largest region, once
    const int stride = lsd.stride;
    const double invStride = 1.0 / stride;
    const int seedY = (int)(regionIndex[0] * invStride);
    const Point origin(regionIndex[0] - seedY * stride - 1, seedY - 1);
    double sum = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < regionSize; i++)
    {
        const int q = regionIndex[i];
        const Point at = pixelAt(q, stride, invStride);
        regionPixel[i] = at;
        const double w = lsd.gradNorm[q];
        const double dx = at.x - origin.x, dy = at.y - origin.y;
        sum += w;
        sx += w * dx;
        sy += w * dy;
        sxx += w * dx * dx;
        syy += w * dy * dy;
        sxy += w * dx * dy;
    }
    const double mx = sx / sum, my = sy / sum;
    const double cx = origin.x + mx, cy = origin.y + my;
    const double ixx = syy - sum * my * my, iyy = sxx - sum * mx * mx, ixy = -(sxy - sum * mx * my);
    // The rectangle's direction is the eigenvector of the smallest eigenvalue, turned to point
    // along the region's level lines.
    const double lambda = 0.5 * (ixx + iyy - std::sqrt((ixx - iyy) * (ixx - iyy) + 4.0 * ixy * ixy));
    Point2d dir = std::abs(ixx) > std::abs(iyy) ? Point2d(ixy, lambda - ixx) : Point2d(lambda - iyy, ixy);
    const Point2d regionDir(regionSum.x, regionSum.y);
    const double dirNorm = std::sqrt(dir.dot(dir)), regionNorm = std::sqrt(regionDir.dot(regionDir));
    dir = dirNorm > 0 ? dir * (1.0 / dirNorm) : regionDir * (1.0 / regionNorm);
    if (dir.dot(regionDir) < std::cos(prec) * regionNorm)
        dir = -dir;

    double lMin = 0, lMax = 0, wMin = 0, wMax = 0;
    int i = 0;
#if CV_SIMD128_64F
    // Four pixels at a time with the same double operations (w as a difference: -a b + c = c - a b
    // exactly), the extremes in two lanes each; v_min(l, m) takes l only when l < m, as std::min(m, l).
    {
        const v_float64x2 x0 = v_setall_f64(cx), y0 = v_setall_f64(cy), ux = v_setall_f64(dir.x), uy = v_setall_f64(dir.y);
        v_float64x2 lLow = v_setzero_f64(), lHigh = lLow, wLow = lLow, wHigh = lLow;
        for (; i + 4 <= regionSize; i += 4)
        {
            v_int32x4 xs, ys;
            v_load_deinterleave(&regionPixel[i].x, xs, ys);
            const v_float64x2 ddx[2] = { v_cvt_f64(xs) - x0, v_cvt_f64_high(xs) - x0 };
            const v_float64x2 ddy[2] = { v_cvt_f64(ys) - y0, v_cvt_f64_high(ys) - y0 };
            for (int h = 0; h < 2; h++)
            {
                const v_float64x2 l = ddx[h] * ux + ddy[h] * uy, w = ddy[h] * ux - ddx[h] * uy;
                lLow = v_min(l, lLow);
                lHigh = v_max(l, lHigh);
                wLow = v_min(w, wLow);
                wHigh = v_max(w, wHigh);
            }
        }
        double lanes[4][2];
        v_store(lanes[0], lLow);
        v_store(lanes[1], lHigh);
        v_store(lanes[2], wLow);
        v_store(lanes[3], wHigh);
        lMin = std::min(lanes[0][0], lanes[0][1]);
        lMax = std::max(lanes[1][0], lanes[1][1]);
        wMin = std::min(lanes[2][0], lanes[2][1]);
        wMax = std::max(lanes[3][0], lanes[3][1]);
    }
#endif
    for (; i < regionSize; i++)
    {
        const double ddx = regionPixel[i].x - cx, ddy = regionPixel[i].y - cy;
        const double l = ddx * dir.x + ddy * dir.y;
        const double w = -ddx * dir.y + ddy * dir.x;
        lMin = std::min(lMin, l);
        lMax = std::max(lMax, l);
        wMin = std::min(wMin, w);
        wMax = std::max(wMax, w);
    }
    rect.x1 = cx + lMin * dir.x;
    rect.y1 = cy + lMin * dir.y;
    rect.x2 = cx + lMax * dir.x;
    rect.y2 = cy + lMax * dir.y;
    rect.width = std::max(wMax - wMin, 1.0);
    rect.x = cx;
    rect.y = cy;
    rect.dx = dir.x;
    rect.dy = dir.y;
    rect.prec = prec;
    rect.p = p;
}

double FastLsd::Regions::density(const Rect& rect) const
{
    return regionSize / (std::sqrt(squaredDistance(rect.x1, rect.y1, rect.x2, rect.y2)) * rect.width);
}

bool FastLsd::Regions::refineRegion(FastLsd& lsd, Rect& rect)
{
    if (density(rect) >= lsd.densityThreshold)
        return true;

    // Too sparse: grow the region again from its seed with the tolerance narrowed to twice the
    // spread of the angles near the seed.
    const int seed = regionIndex[0];
    const Point centre = regionPixel[0];
    const Point2d seedDir(regionVector[0][0], regionVector[0][1]);
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int i = 0; i < regionSize; i++)
    {
        lsd.level[regionIndex[i]] = regionVector[i];
        if (squaredDistance(centre.x, centre.y, regionPixel[i].x, regionPixel[i].y) < rect.width * rect.width)
        {
            const Point2d dir(regionVector[i][0], regionVector[i][1]);
            const double delta = std::atan2(seedDir.cross(dir), seedDir.dot(dir));
            sum += delta;
            sumSq += delta * delta;
            n++;
        }
    }
    const double mean = sum / n;
    const double tau = 2.0 * std::sqrt(std::max(0.0, (sumSq - 2.0 * mean * sum) / n + mean * mean));

    growRegion(lsd, seed, alignmentLimit(tau));
    if (regionSize < 2)
        return false;
    regionToRect(lsd, rect.prec, rect.p, rect);
    const double regrownDensity = density(rect);
    return regrownDensity >= lsd.densityThreshold || shrinkRegionRadius(lsd, rect, regrownDensity);
}

bool FastLsd::Regions::shrinkRegionRadius(FastLsd& lsd, Rect& rect, double currentDensity)
{
    const Point centre = regionPixel[0];
    double radius2 = std::max(squaredDistance(centre.x, centre.y, rect.x1, rect.y1),
                              squaredDistance(centre.x, centre.y, rect.x2, rect.y2));
    while (currentDensity < lsd.densityThreshold)
    {
        radius2 *= 0.75 * 0.75;
        for (int i = 0; i < regionSize;)
        {
            if (squaredDistance(centre.x, centre.y, regionPixel[i].x, regionPixel[i].y) > radius2)
            {
                lsd.level[regionIndex[i]] = regionVector[i];
                regionSize--;
                regionIndex[i] = regionIndex[regionSize];
                regionVector[i] = regionVector[regionSize];
                regionPixel[i] = regionPixel[regionSize];
            }
            else
                i++;
        }
        if (regionSize < 2)
            return false;
        regionToRect(lsd, rect.prec, rect.p, rect);
        currentDensity = density(rect);
    }
    return true;
}

double FastLsd::rectLogNfa(const Rect& rect, std::vector<double>& logFactorials) const
{
    // The pixels whose centres lie in the rectangle, row by row: each row meets the rectangle's
    // four sides in an interval.
    const double hw = rect.width / 2.0;
    const Point2d normal(-rect.dy * hw, rect.dx * hw);
    const Point2d corners[4] = { Point2d(rect.x1, rect.y1) + normal, Point2d(rect.x2, rect.y2) + normal,
                                 Point2d(rect.x2, rect.y2) - normal, Point2d(rect.x1, rect.y1) - normal };
    double yLow = corners[0].y, yHigh = corners[0].y;
    for (const Point2d& c : corners)
    {
        yLow = std::min(yLow, c.y);
        yHigh = std::max(yHigh, c.y);
    }
    const double cosTol = std::cos(rect.prec);
    int total = 0, aligned = 0;
    const int yFirst = std::max(0, (int)std::ceil(yLow)), yLast = std::min(height - 1, (int)std::floor(yHigh));
    for (int y = yFirst; y <= yLast; y++)
    {
        double xLow = DBL_MAX, xHigh = -DBL_MAX;
        for (int e = 0; e < 4; e++)
        {
            const Point2d& a = corners[e];
            const Point2d& b = corners[(e + 1) % 4];
            if ((y < a.y && y < b.y) || (y > a.y && y > b.y))
                continue;
            double x;
            if (a.y == b.y)
            {
                xLow = std::min(xLow, std::min(a.x, b.x));
                xHigh = std::max(xHigh, std::max(a.x, b.x));
                continue;
            }
            x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
            xLow = std::min(xLow, x);
            xHigh = std::max(xHigh, x);
        }
        if (xLow > xHigh)
            continue;
        const int xFirst = std::max(0, (int)std::ceil(xLow)), xLast = std::min(width - 1, (int)std::floor(xHigh));
        if (xFirst > xLast)
            continue;
        total += xLast - xFirst + 1;
        if (y == height - 1)
            continue;  // the last row and column have no gradient
        const uchar* above = analysed.ptr<uchar>(y);
        const uchar* below = analysed.ptr<uchar>(y + 1);
        const uchar* inside = gradientMask.empty() ? nullptr : gradientMask.ptr<uchar>(y);
        for (int x = xFirst; x <= std::min(xLast, width - 2); x++)
        {
            // Pixels of regions count here too: the test of alignment, from the image.
            int gx, gy;
            gradient2x2(above, below, x, gx, gy);
            const int n2 = gx * gx + gy * gy;
            aligned += n2 > threshold && (!inside || inside[x]) &&
                       -gy * rect.dx + gx * rect.dy >= cosTol * std::sqrt((double)n2);
        }
    }
    return logNfa(total, aligned, rect.p, logFactorials);
}

double FastLsd::Regions::improveRect(const FastLsd& lsd, Rect& rect)
{
    // The published variations of the rectangle, each kept when it lowers the NFA: finer
    // precision, thinner, one side moved in, the other side moved in, finer precision again.
    constexpr double delta = 0.5, halfDelta = delta / 2.0;
    double best = lsd.rectLogNfa(rect, logFactorials);
    if (best > lsd.logEps)
        return best;

    auto tryVariation = [&](const Rect& candidate) {
        const double value = lsd.rectLogNfa(candidate, logFactorials);
        if (value > best)
        {
            best = value;
            rect = candidate;
        }
    };

    // Five steps of one variation from the best rectangle so far; the steps that narrow the
    // rectangle, and the last phase, stop at the published minimal width. True when valid.
    auto varyFromBest = [&](bool whileWide, const std::function<void(Rect&)>& step) {
        Rect r = rect;
        for (int n = 0; n < 5; n++)
            if (!whileWide || r.width - delta >= 0.5)
            {
                step(r);
                tryVariation(r);
            }
        return best > lsd.logEps;
    };
    const auto finerPrecision = [](Rect& r) {
        r.p /= 2;
        r.prec = r.p * CV_PI;
    };
    if (varyFromBest(false, finerPrecision) || varyFromBest(true, [](Rect& r) { r.width -= delta; }))
        return best;
    for (const double side : { 1.0, -1.0 })
    {
        const auto moveSideIn = [side](Rect& r) {
            const double ox = -r.dy * halfDelta * side, oy = r.dx * halfDelta * side;
            r.x1 += ox;
            r.y1 += oy;
            r.x2 += ox;
            r.y2 += oy;
            r.width -= delta;
        };
        if (varyFromBest(true, moveSideIn))
            return best;
    }
    varyFromBest(true, finerPrecision);
    return best;
}

double FastLsd::logNfa(int n, int k, double p, std::vector<double>& logFactorials) const
{
    // -log10(NFA) with NFA = NT * sum_{i >= k} C(n, i) p^i (1 - p)^(n - i), the binomial tail summed
    // from its first term until the remaining terms cannot change it by 10 %.
    if (n == 0 || k == 0)
        return -logNT;
    if (n == k)
        return -logNT - n * std::log10(p);
    const double firstLog = logFactorial(n, logFactorials) - logFactorial(k, logFactorials) -
                            logFactorial(n - k, logFactorials) + k * std::log(p) + (n - k) * std::log(1.0 - p);
    double term = std::exp(firstLog);
    if (term == 0.0)
        return k > n * p ? -firstLog / std::log(10.0) - logNT : -logNT;
    const double ratio = p / (1.0 - p);
    double tail = term;
    for (int i = k + 1; i <= n; i++)
    {
        const double binomialRatio = (double)(n - i + 1) / i;
        const double step = binomialRatio * ratio;
        term *= step;
        tail += term;
        if (binomialRatio < 1)
        {
            // Bound of the remaining terms: a geometric series of ratio step.
            const double error = term * ((1 - std::pow(step, (double)(n - i + 1))) / (1 - step) - 1);
            if (error < 0.1 * std::abs(-std::log10(tail) - logNT) * tail)
                break;
        }
    }
    return -std::log10(tail) - logNT;
}

}}} // namespace cv::ximgproc::lsda
