// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD: region growth. A pixel joins a region when its unit level-line vector u is within
// the tolerance of the region's direction, the sum S of its pixels' vectors: u.S >= cos(tolerance)
// |u| |S|. A border of undefined pixels around the buffers removes the bounds checks, and the test
// of a neighbour has no branch until its outcome (whether a neighbour is free is as good as
// random). Growth per neighbourhood (LSDParams::regionGrowth) tests the 8 neighbours of a region's
// pixel together, four at a time, against the region's direction before any of them joined, with
// one branch where the LSD algorithm's growth has eight unpredictable ones.

#include "../precomp.hpp"
#include "parts.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

namespace {

// Each variant of the growth compiled as a function of its own (LSDA_NOINLINE): inlined into
// growRegion's choice of variant, the loop of the one that runs loses registers to the others.

// The region's direction (sx, sy) and the limit of the test, each in the four lanes of a vector.
struct DirectionLanes
{
#if CV_SIMD128
    CV_ALWAYS_INLINE void set(float sx, float sy, float limit)
    {
        x = v_setall_f32(sx);
        y = v_setall_f32(sy);
        least = v_setall_f32(limit);
    }
    v_float32x4 x, y, least;
#else
    void set(float, float, float) {}
#endif
};

// Whether the pixel of vector v passes the test of the region's direction: v.S >= limit. With an
// acute tolerance the test is strict, so that a (0, 0) vector fails it without a test of its own;
// equality has no weight on real data. No branch until the outcome: whether a neighbour is free is
// as good as random.
template <bool acute>
CV_ALWAYS_INLINE bool passes(const Vec2s& v, float sx, float sy, float limit)
{
    const float d = sx * v[0] + sy * v[1];
    return acute ? d > limit : (isFree(v) & (d >= limit));
}

// Which of the four pixels from q on pass the test, a bit each, with the same float operations
// (the vectors one 32-bit lane each).
template <bool acute>
CV_ALWAYS_INLINE unsigned aligned4(const Vec2s* u, int q, float sx, float sy, float limit, const DirectionLanes& lanes)
{
#if CV_SIMD128
    CV_UNUSED(sx);
    CV_UNUSED(sy);
    CV_UNUSED(limit);
    const v_int32x4 w = v_reinterpret_as_s32(v_load((const short*)(u + q)));
    const v_float32x4 d = v_cvt_f32(v_shr<16>(v_shl<16>(w))) * lanes.x + v_cvt_f32(v_shr<16>(w)) * lanes.y;
    return (unsigned)v_signmask(acute ? d > lanes.least : (d >= lanes.least) & v_reinterpret_as_f32(w != v_setzero_s32()));
#else
    CV_UNUSED(lanes);
    unsigned passing = 0;
    for (int k = 0; k < 4; k++)
        passing |= (unsigned)passes<acute>(u[q + k], sx, sy, limit) << k;
    return passing;
#endif
}

// GROWTH_PER_NEIGHBOURHOOD: the neighbours of pixel c that pass against the direction before any
// of them joins, a bit each in the order of the published algorithm (row by row): one test of the
// 3 (4) pixels of each row.
template <bool acute>
CV_ALWAYS_INLINE unsigned passingNeighbours(const Vec2s* u, int c, int s, bool visitsAbove, bool visitsBelow, float sx,
                                           float sy, float limit, const DirectionLanes& lanes)
{
    const unsigned middle = aligned4<acute>(u, c - 1, sx, sy, limit, lanes);
    unsigned joining = ((middle & 1u) << 3) | ((middle & 4u) << 2);
    if (visitsAbove)
        joining |= aligned4<acute>(u, c - s - 1, sx, sy, limit, lanes) & 7u;
    if (visitsBelow)
        joining |= (aligned4<acute>(u, c + s - 1, sx, sy, limit, lanes) & 7u) << 5;
    return joining;
}

// A pixel that joins keeps (0, 0) in u, its vector going to kept when kept; the region's
// direction (sx, sy) takes it. (Functions on the growth's locals, always inlined: a lambda or a
// structure of them cost the hot loop its registers in a translation unit this small.)
CV_ALWAYS_INLINE void join(Vec2s* u, int* index, Vec2s* kept, bool keeping, int q, int& size, float& sx, float& sy)
{
    const Vec2s v = u[q];
    if (keeping)
        kept[size] = v;
    index[size++] = q;
    u[q] = Vec2s(0, 0);
    sx += v[0];
    sy += v[1];
}

// GROWTH_PER_PIXEL: the pixel joins when it passes, and the direction turns at once.
template <bool acute>
CV_ALWAYS_INLINE void visit(Vec2s* u, int* index, Vec2s* kept, bool keeping, int q, float cosUnit, int& size, float& sx,
                            float& sy, float& limit)
{
    if (!passes<acute>(u[q], sx, sy, limit))
        return;
    join(u, index, kept, keeping, q, size, sx, sy);
    limit = cosUnit * std::sqrt(sx * sx + sy * sy);
}

// The growth from seed. GROWTH_PER_PIXEL visits the 8 neighbours one by one, row by row, as the
// published algorithm: the order decides which pixels join, since the region's direction changes
// with every pixel. GROWTH_PER_NEIGHBOURHOOD joins those that passed together (passingNeighbours),
// with one branch when none does (most neighbours are taken, undefined or of another direction).
template <bool acute, bool mayOutgrow, bool bounded, bool perNeighbourhood>
LSDA_NOINLINE void growFrom(GradientField& field, const GrowthBounds& bounds, int seed, float cosUnit, Region& region)
{
    if (mayOutgrow && region.index.size() < 9 + kCompactionSlack)
        region.reserve(9);
    Vec2s* const u = field.level.data();
    int* index = region.index.data();
    Vec2s* kept = region.vector.data();
    const bool keeping = region.keepsVectors;
    int capacity = (int)(region.index.size() - kCompactionSlack);
    float sx = u[seed][0], sy = u[seed][1];
    float limit = cosUnit * std::sqrt(sx * sx + sy * sy);
    DirectionLanes lanes;
    lanes.set(sx, sy, limit);
    index[0] = seed;
    if (keeping)
        kept[0] = u[seed];
    u[seed] = Vec2s(0, 0);
    int size = 1;
    const int s = field.stride;
    const int neighbours[8] = { -s - 1, -s, -s + 1, -1, 1, s - 1, s, s + 1 };
    bool above = false, below = false;
    for (int i = 0; i < size; i++)
    {
        if (mayOutgrow && size + 8 > capacity)
        {
            region.reserve(2 * (size_t)capacity + 8);
            index = region.index.data();
            kept = region.vector.data();
            capacity = (int)(region.index.size() - kCompactionSlack);
        }
        const int c = index[i];
        // In a tile, the neighbours in the rows of the tiles above and below are not its own.
        const bool visitsAbove = !bounded || c >= bounds.firstRowEnd, visitsBelow = !bounded || c < bounds.lastRow;
        above |= !visitsAbove;
        below |= !visitsBelow;
        if (perNeighbourhood)
        {
            unsigned joining = passingNeighbours<acute>(u, c, s, visitsAbove, visitsBelow, sx, sy, limit, lanes);
            if (!joining)
                continue;
            do
            {
                join(u, index, kept, keeping, c + neighbours[trailingZeros32(joining)], size, sx, sy);
                joining &= joining - 1;
            } while (joining);
            limit = cosUnit * std::sqrt(sx * sx + sy * sy);
            lanes.set(sx, sy, limit);
            continue;
        }
        if (visitsAbove)
        {
            visit<acute>(u, index, kept, keeping, c - s - 1, cosUnit, size, sx, sy, limit);
            visit<acute>(u, index, kept, keeping, c - s, cosUnit, size, sx, sy, limit);
            visit<acute>(u, index, kept, keeping, c - s + 1, cosUnit, size, sx, sy, limit);
        }
        visit<acute>(u, index, kept, keeping, c - 1, cosUnit, size, sx, sy, limit);
        visit<acute>(u, index, kept, keeping, c + 1, cosUnit, size, sx, sy, limit);
        if (visitsBelow)
        {
            visit<acute>(u, index, kept, keeping, c + s - 1, cosUnit, size, sx, sy, limit);
            visit<acute>(u, index, kept, keeping, c + s, cosUnit, size, sx, sy, limit);
            visit<acute>(u, index, kept, keeping, c + s + 1, cosUnit, size, sx, sy, limit);
        }
    }
    region.size = size;
    region.sum = Point2f(sx, sy);
    region.reachesAbove = above;
    region.reachesBelow = below;
}

template <bool perNeighbourhood>
void growAs(GradientField& field, const GrowthBounds& bounds, int seed, float cosUnit, Region& region)
{
    const bool bounded = bounds.bounded();
    if (cosUnit > 0)
    {
        if (!region.fitsAnyRegion)
            growFrom<true, true, false, perNeighbourhood>(field, bounds, seed, cosUnit, region);
        else if (bounded)
            growFrom<true, false, true, perNeighbourhood>(field, bounds, seed, cosUnit, region);
        else
            growFrom<true, false, false, perNeighbourhood>(field, bounds, seed, cosUnit, region);
    }
    else if (!region.fitsAnyRegion)
        growFrom<false, true, false, perNeighbourhood>(field, bounds, seed, cosUnit, region);
    else if (bounded)
        growFrom<false, false, true, perNeighbourhood>(field, bounds, seed, cosUnit, region);
    else
        growFrom<false, false, false, perNeighbourhood>(field, bounds, seed, cosUnit, region);
}

} // namespace

void growRegion(GradientField& field, const GrowthBounds& bounds, int regionGrowth, int seed, float cosUnit,
                Region& region)
{
    if (regionGrowth == LSDAdvance::GROWTH_PER_NEIGHBOURHOOD)
        growAs<true>(field, bounds, seed, cosUnit, region);
    else
        growAs<false>(field, bounds, seed, cosUnit, region);
}

void Region::reserve(size_t pixels)
{
    // index holds more: the compaction of the seeds writes past the last.
    if (index.size() < pixels + kCompactionSlack)
        index.resize(pixels + kCompactionSlack);
    if (keepsVectors && vector.size() < pixels)
        vector.resize(pixels);
}

}}}} // namespace cv::ximgproc::lsda::fast_lsd
