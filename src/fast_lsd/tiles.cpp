// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD: the tiles (LSDParams::tileHeight) and their seams. Each tile grows its regions in
// the pseudo-ordering of its seeds (a counting sort into the bins of their gradient norm, raster
// order inside a bin) over its own rows, in its own task; the regions that reach a seam are
// joined across it afterwards with those of the other tile, and validated in tasks of their own.

#include "../precomp.hpp"
#include "parts.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

namespace {

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

// The seeds of a tile in the pseudo-ordering, into its grower: highest bin first; inside a bin,
// raster order (a stable counting sort). Those of the rows next to a seam were chosen before the
// tiles grew. Never inlined: scripts/tile_work.py counts each tile's instructions from its call.
LSDA_NOINLINE void orderSeeds(const GradientField& field, const RegionRules& rules, int seedAlignedNeighbours, Tile& tile)
{
    int defined = 0;
    for (int y = tile.y0; y < tile.y1; y++)
        defined += field.rowDefined[y];
    RegionGrower& r = tile.grower;
    r.region.keepsVectors = rules.refine >= kLsdRefineStd;
    r.region.reserve(defined);
    // The seeds in raster order, in the region's index until the regions need it (all of them
    // free: the tile's regions have not grown yet).
    int* const first = r.region.index.data();
    int* next = first;
    for (int y = tile.y0; y < tile.y1; y++)
    {
        const std::vector<int>* seam = y == tile.y0 && tile.seamAbove ? &tile.seedsAbove
                                       : y == tile.y1 - 1 && tile.seamBelow ? &tile.seedsBelow : nullptr;
        next = seam ? std::copy(seam->begin(), seam->end(), next)
                    : seedsOfRow(field, y, field.seedNorm, seedAlignedNeighbours, rules.alignedDot, next);
    }
    const int count = (int)(next - first);
    r.seeds.resize(count);
    const int bins = field.numBins;
    compressRows(count, bins, [&](int i) { return bins - 1 - field.binOf(first[i]); }, r.binStart,
                 [&](int i, int k) { r.seeds[k] = first[i]; });
}

} // namespace

void ReleasedRegions::clear()
{
    index.clear();
    vector.clear();
    start.assign(1, 0);
    sum.clear();
}

void ReleasedRegions::add(const Region& region)
{
    index.insert(index.end(), region.index.begin(), region.index.begin() + region.size);
    if (region.keepsVectors)
        vector.insert(vector.end(), region.vector.begin(), region.vector.begin() + region.size);
    start.push_back((int)index.size());
    sum.push_back(region.sum);
}

void RegionGrower::enterTile(const GradientField& field, Tile& tile)
{
    tile.releasedAbove.assign(tile.seamAbove ? field.width - 1 : 0, -1);
    tile.releasedBelow.assign(tile.seamBelow ? field.width - 1 : 0, -1);
    if (tile.seamAbove)
    {
        bounds.firstRow = (tile.y0 + 1) * field.stride;
        bounds.firstRowEnd = bounds.firstRow + field.stride;
    }
    if (tile.seamBelow)
        bounds.lastRow = tile.y1 * field.stride;
}

void RegionGrower::detect(GradientField& field, const RegionRules& rules, Tile* tile)
{
    segments.clear();
    released.clear();
    bounds = GrowthBounds();
    if (tile)
        enterTile(field, *tile);
    const Vec2s* level = field.level.data();
    const int count = (int)seeds.size(), stride = field.stride;
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
        growRegion(field, bounds, rules.regionGrowth, seed, rules.cosUnit, region);
        if (tile && (region.reachesAbove || region.reachesBelow))
        {
            releaseAtSeams(*tile);
            continue;
        }
        if (region.size >= rules.minRegionSize)
            emitRegion(field, rules);
    }
}

void RegionGrower::releaseAtSeams(Tile& tile)
{
    const int k = released.count();
    for (int i = 0; i < region.size; i++)
    {
        const int q = region.index[i];
        if (q < bounds.firstRowEnd)
            tile.releasedAbove[q - bounds.firstRow - 1] = k;
        if (q >= bounds.lastRow)
            tile.releasedBelow[q - bounds.lastRow - 1] = k;
    }
    released.add(region);
}

Tiling::Tiling()
{
    acrossSeams.region.fitsAnyRegion = false;
}

void Tiling::lay(int rows, int tileHeight)
{
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

std::vector<cv::Rect> Tiling::areas(int width) const
{
    std::vector<cv::Rect> result;
    for (const Tile& t : tiles)
        result.emplace_back(0, t.y0, width - 1, t.y1 - t.y0);
    return result;
}

void Tiling::seedSeamRows(const GradientField& field, const RegionRules& rules, int seedAlignedNeighbours)
{
    // A row next to a seam seeds at every gradient level: a segment that crosses the seam from a
    // stronger part in the other tile has its part here grown and joined. With seeds on edges, only
    // the pixels aligned with one of their three neighbours across the seam, as a segment crossing
    // it is (not the texture along it). Chosen before the tiles grow: those neighbours are pixels
    // that the other tile takes while this one grows.
    const bool onEdges = seedAlignedNeighbours > 0;
    const Vec2s* level = field.level.data();
    const auto seedsOf = [&](int y, int across, std::vector<int>& seeds) {
        seeds.resize(field.width - 1 + kCompactionSlack);
        int* const first = seeds.data();
        int* next = seedsOfRow(field, y, FLT_MIN, 0, rules.alignedDot, first);
        if (onEdges)
            next = std::remove_if(first, next, [&](int q) {
                const Vec2s u = level[q];
                for (int o = q + across - 1; o <= q + across + 1; o++)
                {
                    const Vec2s a = level[o];
                    if (isFree(a) && u[0] * a[0] + u[1] * a[1] > rules.alignedDot)
                        return false;
                }
                return true;
            });
        seeds.resize(next - first);
    };
    for (Tile& t : tiles)
    {
        if (t.seamAbove)
            seedsOf(t.y0, -field.stride, t.seedsAbove);
        if (t.seamBelow)
            seedsOf(t.y1 - 1, field.stride, t.seedsBelow);
    }
}

void Tiling::growTiles(GradientField& field, const RegionRules& rules, int seedAlignedNeighbours)
{
    tileTasks.evenly((int)tiles.size(), 1);
    runTasks(tileTasks, [&](int, const Range& range) {
        for (int t = range.start; t < range.end; t++)
        {
            Tile& tile = tiles[t];
            orderSeeds(field, rules, seedAlignedNeighbours, tile);
            tile.grower.detect(field, rules, tile.seamAbove || tile.seamBelow ? &tile : nullptr);
        }
    });
}

void Tiling::joinAcrossSeams(GradientField& field, const RegionRules& rules)
{
    acrossSeams.region.keepsVectors = rules.refine >= kLsdRefineStd;
    acrossSeams.segments.clear();
    if (tiles.size() == 1)
        return;
    releasedFirst.resize(tiles.size() + 1);
    releasedFirst[0] = 0;
    for (size_t t = 0; t < tiles.size(); t++)
        releasedFirst[t + 1] = releasedFirst[t] + tiles[t].grower.released.count();
    const int released = releasedFirst.back();
    joined.reset(released);
    joinNeighbours(field, rules);
    // The released regions of each joined region, in order; a region's root is its first.
    rootOf.resize(released);
    for (int k = 0; k < released; k++)
        rootOf[k] = joined.find(k);
    groupMembers.resize(released);
    compressRows(released, released, [&](int k) { return rootOf[k]; }, groupStart,
                 [&](int k, int position) { groupMembers[position] = k; });
    layJoinedTasks(rules);
    validateJoined(field, rules);
}

void Tiling::joinNeighbours(const GradientField& field, const RegionRules& rules)
{
    // Two released regions of tiles t and t + 1 are joined when pixels of theirs are neighbours
    // across the seam between them (one column apart at most) and their directions agree within
    // the angle tolerance, as a pixel joins a region.
    const double cosTolerance = std::cos(rules.tolerance);
    const int columns = field.width - 1;
    for (size_t t = 0; t + 1 < tiles.size(); t++)
    {
        const Tile &upper = tiles[t], &lower = tiles[t + 1];
        for (int x = 0; x < columns; x++)
        {
            const int a = upper.releasedBelow[x];
            if (a < 0)
                continue;
            const Point2f& sa = upper.grower.released.sum[a];
            for (int bx = std::max(0, x - 1); bx <= std::min(columns - 1, x + 1); bx++)
            {
                const int b = lower.releasedAbove[bx];
                if (b < 0)
                    continue;
                const Point2f& sb = lower.grower.released.sum[b];
                if (sa.dot(sb) < cosTolerance * std::sqrt((double)sa.dot(sa) * sb.dot(sb)))
                    continue;
                joined.unite(releasedFirst[t] + a, releasedFirst[t + 1] + b);
            }
        }
    }
}

void Tiling::layJoinedTasks(const RegionRules& rules)
{
    // The joined regions large enough to be valid, in tasks of at least kJoinedPixelsPerTask
    // pixels, laid out from the regions alone.
    joinedRoots.clear();
    joinedSizes.clear();
    for (int g = 0; g < (int)rootOf.size(); g++)
    {
        if (rootOf[g] != g)
            continue;
        const int size = joinedRegionSize(g);
        if (size < rules.minRegionSize)
            continue;
        joinedRoots.push_back(g);
        joinedSizes.push_back(size);
    }
    joinedTasks.byWeight((int)joinedRoots.size(), kJoinedPixelsPerTask, [&](int i) { return joinedSizes[i]; });
    while ((int)joiningGrowers.size() < joinedTasks.count())
    {
        joiningGrowers.emplace_back();
        joiningGrowers.back().region.fitsAnyRegion = false;
        joiningGrowers.back().region.keepsVectors = false;  // they grow no region again
    }
    joinedOutcome.resize(joinedRoots.size());
    joinedSegment.resize(joinedRoots.size());
}

void Tiling::validateJoined(GradientField& field, const RegionRules& rules)
{
    // The joined regions that are not grown again, a task per range of them, each with its own
    // grower; the pixels of the field are only read.
    runTasks(joinedTasks, [&](int task, const Range& items) {
        RegionGrower& grower = joiningGrowers[task];
        grower.segments.clear();
        for (int i = items.start; i < items.end; i++)
        {
            gatherJoinedRegion(field, joinedRoots[i], grower);
            const size_t found = grower.segments.size();
            if (!grower.emitUnlessRegrown(field, rules))
                joinedOutcome[i] = kGrowsAgain;
            else if (grower.segments.size() > found)
            {
                joinedOutcome[i] = kValid;
                joinedSegment[i] = grower.segments.back();
            }
            else
                joinedOutcome[i] = kRejected;
        }
    });
    // In order: the segments of the tasks, and the regions that grow again, over pixels that
    // the regions grown again before them may have freed.
    for (size_t i = 0; i < joinedRoots.size(); i++)
    {
        if (joinedOutcome[i] == kValid)
            acrossSeams.segments.push_back(joinedSegment[i]);
        else if (joinedOutcome[i] == kGrowsAgain)
        {
            gatherJoinedRegion(field, joinedRoots[i], acrossSeams);
            acrossSeams.emitRegion(field, rules);
        }
    }
}

const ReleasedRegions& Tiling::releasedPart(int k, int& local) const
{
    const int t = (int)(std::upper_bound(releasedFirst.begin(), releasedFirst.end(), k) - releasedFirst.begin()) - 1;
    local = k - releasedFirst[t];
    return tiles[t].grower.released;
}

int Tiling::joinedRegionSize(int g) const
{
    int size = 0, local;
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
        size += releasedPart(groupMembers[m], local).sizeOf(local);
    return size;
}

void Tiling::gatherJoinedRegion(const GradientField& field, int g, RegionGrower& grower) const
{
    // The joined region grows from the strongest seed of its parts (highest bin, then raster
    // order), as it would have without the seams: that part's pixels come first.
    int first = g, firstSeed = -1, local;
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
    {
        const ReleasedRegions& r = releasedPart(groupMembers[m], local);
        const int seed = r.index[r.start[local]];
        const int bin = field.binOf(seed), firstBin = firstSeed < 0 ? -1 : field.binOf(firstSeed);
        if (firstSeed < 0 || bin > firstBin || (bin == firstBin && seed < firstSeed))
        {
            first = groupMembers[m];
            firstSeed = seed;
        }
    }
    Region& region = grower.region;
    region.reserve(joinedRegionSize(g));
    region.size = 0;
    region.sum = Point2f(0, 0);
    const auto append = [&](int k) {
        const ReleasedRegions& r = releasedPart(k, local);
        const int begin = r.start[local], end = r.start[local + 1];
        std::copy(r.index.begin() + begin, r.index.begin() + end, region.index.begin() + region.size);
        if (region.keepsVectors)
            std::copy(r.vector.begin() + begin, r.vector.begin() + end, region.vector.begin() + region.size);
        region.size += end - begin;
        region.sum += r.sum[local];
    };
    append(first);
    for (int m = groupStart[g]; m < groupStart[g + 1]; m++)
        if (groupMembers[m] != first)
            append(groupMembers[m]);
}

void Tiling::appendSegments(std::vector<Vec4f>& segments) const
{
    for (const Tile& t : tiles)
        segments.insert(segments.end(), t.grower.segments.begin(), t.grower.segments.end());
    segments.insert(segments.end(), acrossSeams.segments.begin(), acrossSeams.segments.end());
}

}}}} // namespace cv::ximgproc::lsda::fast_lsd
