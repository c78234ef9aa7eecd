// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 2: angle bins + endpoint adjacency -> merge groups (connected components).

#include "precomp.hpp"
#include "primitives.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

int binCount(double binWidth)
{
    return std::max(1, (int)std::ceil(180.0 / binWidth - 1e-9));
}

// The bin whose endpoints those of bin b are compared with besides their own, so that each pair
// of neighbouring bins is visited from one side only: the next one, 170-180 wrapping to 0-10; -1
// for none (strict bins, a single bin, or bin 1 of two, already visited from bin 0).
int nextBin(int b, int bins, bool neighbourBins)
{
    if (!neighbourBins || bins < 2 || (bins == 2 && b == 1))
        return -1;
    return (b + 1) % bins;
}

// Cells within +-kCellLimit (checked before the int casts; processSegments' coordinates, within
// kMaxCoordinate, are at the smallest endpointDistance) and bins below 256 make one key each.
// Cells of one bin that shared a key would only be compared needlessly.
constexpr double kCellLimit = 1 << 27;

int64 cellKey(int bin, int x, int y)
{
    return (int64)(((uint64)bin << 56) | (((uint64)(uint32_t)x & 0xFFFFFFF) << 28) | ((uint64)(uint32_t)y & 0xFFFFFFF));
}

// A dense grid has bins x (cells of the endpoints' bounding box): it is taken while that is at
// most kDenseCellsPerEndpoint cells per endpoint plus kDenseCellsAllowance (an image's segments,
// at the bins and distances of the presets), so that its memory and its running sum stay bounded
// by the number of endpoints.
constexpr int64 kDenseCellsPerEndpoint = 32, kDenseCellsAllowance = 1 << 16;

// Open-addressing hash table from a cell key to a dense cell number: O(1) per look-up whatever
// the spread of the coordinates.
class CellTable
{
public:
    CellTable(std::vector<int64>& keyBuffer, std::vector<int>& cellBuffer, int entries)
        : keys(keyBuffer), cells(cellBuffer)
    {
        size_t capacity = 16;
        while (capacity < 2 * (size_t)entries)
            capacity *= 2;
        mask = capacity - 1;
        keys.resize(capacity);
        cells.assign(capacity, -1);
    }
    // Dense number of the cell, -1 when absent.
    int find(int64 key) const
    {
        for (size_t slot = hash(key);; slot = (slot + 1) & mask)
            if (cells[slot] < 0 || keys[slot] == key)
                return cells[slot];
    }
    // Dense number of the cell, given the next free number when absent.
    int insert(int64 key, int& cellCount)
    {
        size_t slot = hash(key);
        while (cells[slot] >= 0 && keys[slot] != key)
            slot = (slot + 1) & mask;
        if (cells[slot] < 0)
        {
            keys[slot] = key;
            cells[slot] = cellCount++;
        }
        return cells[slot];
    }

private:
    size_t hash(int64 key) const { return (size_t)(((uint64)key * 0x9E3779B97F4A7C15ull) >> 29) & mask; }

    std::vector<int64>& keys;
    std::vector<int>& cells;
    size_t mask;
};

// The comparisons of endpoints, queued as pairs of filed positions and done in batches. Most
// fail, and which ones do is unpredictable, as is how many endpoints a cell holds: a range of up
// to four endpoints is queued without a branch on its length, and a batch is compared without a
// branch on the outcomes (every comparison writes its pair, a pass keeps it).
constexpr int kComparisonBatch = 1024;

class EndpointComparisons
{
public:
    EndpointComparisons(const std::vector<Point2d>& points_, const std::vector<int>& segmentOf_, double maxDistSq_,
                        std::vector<int>& fromBuffer, std::vector<int>& toBuffer, std::vector<Vec2i>& pairBuffer,
                        UnionFind& segmentSets)
        : points(points_), segmentOf(segmentOf_), maxDistSq(maxDistSq_), from(fromBuffer), to(toBuffer),
          pairs(pairBuffer), sets(segmentSets)
    {
        from.resize(kComparisonBatch + 4);
        to.resize(kComparisonBatch + 4);
        pairs.resize(kComparisonBatch + 4);
    }
    // Queues the comparisons of filed endpoint k with the filed endpoints [begin, end).
    void add(int k, int begin, int end)
    {
        int* const queuedFrom = &from[count];
        int* const queuedTo = &to[count];
#if CV_SIMD128
        v_store(queuedFrom, v_setall_s32(k));
        v_store(queuedTo, v_setall_s32(begin) + v_int32x4(0, 1, 2, 3));
#else
        for (int i = 0; i < 4; i++)
        {
            queuedFrom[i] = k;
            queuedTo[i] = begin + i;
        }
#endif
        count += std::min(end - begin, 4);
        if (end - begin > 4 || count >= kComparisonBatch)
            addRest(k, begin + 4, end);
    }
    // Compares the queued pairs and unites the segments of the adjacent ones.
    void compareAndUnite()
    {
        const Point2d* point = points.data();
        const int* segment = segmentOf.data();
        Vec2i* adjacentPairs = pairs.data();
        int adjacent = 0;
        for (int i = 0; i < count; i++)
        {
            const int a = from[i], b = to[i];
            const Point2d d = point[b] - point[a];
            adjacentPairs[adjacent] = Vec2i(segment[a], segment[b]);
            adjacent += (d.dot(d) < maxDistSq) & (segment[a] != segment[b]);
        }
        for (int i = 0; i < adjacent; i++)
            sets.unite(adjacentPairs[i][0], adjacentPairs[i][1]);
        count = 0;
    }

private:
    // The endpoints of a range beyond its first four, and a full batch.
    void addRest(int k, int begin, int end)
    {
        for (int other = begin; other < end; other++)
        {
            if (count >= kComparisonBatch)
                compareAndUnite();
            from[count] = k;
            to[count++] = other;
        }
        if (count >= kComparisonBatch)
            compareAndUnite();
    }

    const std::vector<Point2d>& points;
    const std::vector<int>& segmentOf;
    const double maxDistSq;
    std::vector<int>& from;
    std::vector<int>& to;
    std::vector<Vec2i>& pairs;
    UnionFind& sets;
    int count = 0;
};

} // namespace

int angleBin(const Vec4f& s, double binWidth)
{
    double angle = std::atan2((double)s[3] - s[1], (double)s[2] - s[0]) * 180.0 / CV_PI;
    if (angle < 0)
        angle += 180.0;
    if (angle >= 180.0)
        angle -= 180.0;
    return std::min((int)(angle / binWidth), binCount(binWidth) - 1);
}

void angleBins(const std::vector<Vec4f>& segments, double binWidth, std::vector<int>& bins, std::vector<Point2d>& edges)
{
    const int count = binCount(binWidth);
    edges.resize(count + 1);
    for (int k = 0; k <= count; k++)
    {
        const double edge = std::min(k * binWidth, 180.0) * CV_PI / 180.0;
        edges[k] = Point2d(std::cos(edge), std::sin(edge));
    }
    bins.resize(segments.size());
    for (size_t i = 0; i < segments.size(); i++)
    {
        const Vec4f& s = segments[i];
        const double dx = (double)s[2] - s[0], dy = (double)s[3] - s[1];
        const double ax = std::abs(dx), ay = std::abs(dy);
        // The guess, without a branch (the octant of a direction is unpredictable): atan of the
        // smaller coordinate over the larger (Abramowitz & Stegun 4.4.47, within 1e-5 rad), turned
        // into its octant, in degrees, undirected. A NaN guesses bin 0.
        const double t = std::min(ax, ay) / std::max(ax, ay), t2 = t * t;
        double angle = t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
        angle *= 180.0 / CV_PI;
        angle += (ay > ax) * (90.0 - 2 * angle);
        const bool leftward = (dx < 0) != (dy < 0);
        angle += leftward * (180.0 - 2 * angle);
        const int guess = (int)std::min(std::max(0.0, angle / binWidth), count - 1.0);
        // The direction in the upper half-plane must lie strictly between the guessed bin's edges,
        // by a margin (1e-9 rad) far above the rounding of these products and the error of
        // angleBin's angle (below 1e-13 deg).
        const double flip = 1.0 - 2.0 * (dy < 0);
        const Point2d d(flip * dx, flip * dy);
        const double margin = 1e-9 * (ax + ay);
        const bool inside = edges[guess].cross(d) > margin && edges[guess + 1].cross(d) < -margin;
        bins[i] = inside ? guess : angleBin(s, binWidth);
    }
}

void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params,
                   SegmentGroups& groups, GroupingWorkspace& ws)
{
    const int n = (int)segments.size();
    const int bins = binCount(params.angleBinWidth);
    const bool neighbourBins = params.angleBinning == LSDAdvance::ANGLE_BINS_NEIGHBOURS;
    const double cellSize = params.endpointDistance;
    const double maxDistSq = cellSize * cellSize;

    angleBins(segments, params.angleBinWidth, ws.bin, ws.binEdges);

    auto endpoint = [&](int e) {
        const Vec4f& s = segments[e >> 1];
        return (e & 1) ? Point2d(s[2], s[3]) : Point2d(s[0], s[1]);
    };
    // Endpoints filed under their angle bin and grid cell (compressed rows, endpoints in increasing
    // order). Cells are squares of the adjacency distance, so two endpoints closer than it are in
    // the same or in neighbouring cells: an endpoint is compared with those of 9 cells of its own
    // bin and of its neighbouring bins only.
    ws.endpointCell.resize(2 * (size_t)n);
    Point lowest(INT_MAX, INT_MAX), highest(INT_MIN, INT_MIN);
    for (int e = 0; e < 2 * n; e++)
    {
        const Point2d p = endpoint(e);
        const double cx = std::floor(p.x / cellSize), cy = std::floor(p.y / cellSize);
        CV_CheckLT(std::max(std::abs(cx), std::abs(cy)), kCellLimit - 1,
                   "groupSegments: an endpoint is too far from the origin");
        const Point c((int)cx, (int)cy);
        ws.endpointCell[e] = c;
        lowest = Point(std::min(lowest.x, c.x), std::min(lowest.y, c.y));
        highest = Point(std::max(highest.x, c.x), std::max(highest.y, c.y));
    }
    // A dense grid per bin over the endpoints' cells (and a border of empty ones) when it is not
    // much larger than the endpoints (an image's segments), where the three cells of a row of a
    // neighbourhood are consecutive; a hash of the cells otherwise (spread coordinates).
    const int64 gridWidth = n > 0 ? (int64)highest.x - lowest.x + 3 : 0, gridHeight = n > 0 ? (int64)highest.y - lowest.y + 3 : 0;
    const int64 planeSize = gridWidth * gridHeight;
    const bool dense = bins * planeSize <= kDenseCellsPerEndpoint * 2 * n + kDenseCellsAllowance;
    CellTable table(ws.tableKeys, ws.tableCells, dense ? 0 : 2 * n);
    int cellCount = dense ? (int)(bins * planeSize) : 0;
    ws.cellOfEndpoint.resize(2 * (size_t)n);
    for (int e = 0; e < 2 * n; e++)
    {
        const Point c = ws.endpointCell[e];
        const int b = ws.bin[e >> 1];
        ws.cellOfEndpoint[e] = dense ? (int)(b * planeSize + (c.y - lowest.y + 1) * gridWidth + c.x - lowest.x + 1)
                                     : table.insert(cellKey(b, c.x, c.y), cellCount);
    }
    // The endpoints filed by cell (compressed rows).
    ws.cellEndpoints.resize(2 * (size_t)n);
    ws.filedCell.resize(2 * (size_t)n);
    ws.filedPoint.resize(2 * (size_t)n);
    ws.filedSegment.resize(2 * (size_t)n);
    compressRows(2 * n, cellCount, [&](int e) { return ws.cellOfEndpoint[e]; }, ws.cellStart, [&](int e, int k) {
        ws.cellEndpoints[k] = e;
        ws.filedCell[k] = ws.cellOfEndpoint[e];
        ws.filedPoint[k] = endpoint(e);
        ws.filedSegment[k] = e >> 1;
    });

    ws.sets.reset(n);
    {
        EndpointComparisons comparisons(ws.filedPoint, ws.filedSegment, maxDistSq, ws.queuedFrom, ws.queuedTo, ws.pairs,
                                        ws.sets);
        // Each pair of endpoints of one bin is compared once, from the first of them in the filed
        // order: the rest of its cell, the next cell of its row and three cells of the next row;
        // with the next bin, the 9 cells around.
        if (dense)
        {
            const int width = (int)gridWidth;
            for (int b = 0; b < bins; b++)
            {
                const int next = nextBin(b, bins, neighbourBins);
                const int nextPlane = (next - b) * (int)planeSize;
                for (int k = ws.cellStart[b * planeSize]; k < ws.cellStart[(b + 1) * planeSize]; k++)
                {
                    const int cell = ws.filedCell[k];
                    comparisons.add(k, k + 1, ws.cellStart[cell + 2]);
                    comparisons.add(k, ws.cellStart[cell + width - 1], ws.cellStart[cell + width + 2]);
                    if (next < 0)
                        continue;
                    const int centre = cell + nextPlane;
                    comparisons.add(k, ws.cellStart[centre - width - 1], ws.cellStart[centre - width + 2]);
                    comparisons.add(k, ws.cellStart[centre - 1], ws.cellStart[centre + 2]);
                    comparisons.add(k, ws.cellStart[centre + width - 1], ws.cellStart[centre + width + 2]);
                }
            }
        }
        else
            for (int k = 0; k < 2 * n; k++)
            {
                const int e = ws.cellEndpoints[k], b = ws.bin[e >> 1], next = nextBin(b, bins, neighbourBins);
                const Point c = ws.endpointCell[e];
                const auto addCell = [&](int bin, int dx, int dy) {
                    const int other = table.find(cellKey(bin, c.x + dx, c.y + dy));
                    if (other >= 0)
                        comparisons.add(k, ws.cellStart[other], ws.cellStart[other + 1]);
                };
                comparisons.add(k, k + 1, ws.cellStart[ws.filedCell[k] + 1]);
                addCell(b, 1, 0);
                for (int dx = -1; dx <= 1; dx++)
                    addCell(b, dx, 1);
                if (next < 0)
                    continue;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++)
                        addCell(next, dx, dy);
            }
        comparisons.compareAndUnite();
    }

    // The groups by root; roots are smallest members, so groups come out ordered by their smallest
    // member and members in increasing order. A root is visited before its members.
    ws.groupOf.resize(n);
    int groupCount = 0;
    for (int i = 0; i < n; i++)
    {
        const int root = ws.sets.find(i);
        ws.groupOf[i] = root == i ? groupCount++ : ws.groupOf[root];
    }
    groups.members.resize(n);
    compressRows(n, groupCount, [&](int i) { return ws.groupOf[i]; }, groups.offsets,
                 [&](int i, int k) { groups.members[k] = i; });
}

int mergeGroupCount(const SegmentGroups& groups)
{
    int count = 0;
    for (int g = 0; g < groups.count(); g++)
        count += groups.offsets[g + 1] - groups.offsets[g] > 1;
    return count;
}

void groupLabels(const SegmentGroups& groups, std::vector<int>& labels)
{
    labels.assign(groups.members.size(), -1);
    int next = 0;
    for (int g = 0; g < groups.count(); g++)
    {
        if (groups.offsets[g + 1] - groups.offsets[g] < 2)
            continue;
        for (int k = groups.offsets[g]; k < groups.offsets[g + 1]; k++)
            labels[groups.members[k]] = next;
        next++;
    }
}

}}} // namespace cv::ximgproc::lsda
