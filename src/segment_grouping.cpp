// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 2: angle bins + endpoint adjacency -> merge groups (connected components).

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

int binCount(double binWidth)
{
    return std::max(1, (int)std::ceil(180.0 / binWidth - 1e-9));
}

bool binsPair(int a, int b, int bins, bool neighbourBins)
{
    if (a == b)
        return true;
    if (!neighbourBins)
        return false;
    const int d = std::abs(a - b);
    return d == 1 || d == bins - 1;
}

// Union-find whose root is always the smallest index, so that group order does not depend
// on the order in which adjacent pairs are found.
int findRoot(std::vector<int>& parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

void unite(std::vector<int>& parent, int a, int b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

int64 cellKey(int64 cx, int64 cy)
{
    return (int64)(((uint64)(uint32_t)cx << 32) | (uint64)(uint32_t)cy);
}

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

void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params,
                   SegmentGroups& groups, GroupingWorkspace& ws)
{
    const int n = (int)segments.size();
    const int bins = binCount(params.angleBinWidth);
    const double cellSize = params.endpointDistance;
    const double maxDistSq = cellSize * cellSize;

    ws.bin.resize(n);
    for (int i = 0; i < n; i++)
        ws.bin[i] = angleBin(segments[i], params.angleBinWidth);

    auto endpoint = [&](int e) {
        const Vec4f& s = segments[e >> 1];
        return (e & 1) ? Point2d(s[2], s[3]) : Point2d(s[0], s[1]);
    };
    // Endpoints filed under their grid cell (compressed rows, endpoints in increasing order).
    // Cells are squares of the adjacency distance, so two endpoints closer than it are in the
    // same or in neighbouring cells: each endpoint is compared with the endpoints of 9 cells only.
    // The cells' coordinates fit in 32 bits: coordinates are finite and bounded (checked by the
    // caller), and the cell size, endpointDistance, is at least 0.1 px (its range, parameters.hpp).
    ws.endpointCell.resize(2 * (size_t)n);
    Point lowest(INT_MAX, INT_MAX), highest(INT_MIN, INT_MIN);
    for (int e = 0; e < 2 * n; e++)
    {
        const Point2d p = endpoint(e);
        const Point c((int)std::floor(p.x / cellSize), (int)std::floor(p.y / cellSize));
        ws.endpointCell[e] = c;
        lowest = Point(std::min(lowest.x, c.x), std::min(lowest.y, c.y));
        highest = Point(std::max(highest.x, c.x), std::max(highest.y, c.y));
    }
    // A dense grid over the endpoints' cells (and a border of empty ones) when it is not much
    // larger than the endpoints (an image's segments), where the three cells of a row of a
    // neighbourhood are consecutive; a hash of the cells otherwise (spread coordinates).
    const int64 gridWidth = n > 0 ? (int64)highest.x - lowest.x + 3 : 0, gridHeight = n > 0 ? (int64)highest.y - lowest.y + 3 : 0;
    const bool dense = gridWidth * gridHeight <= 8 * (int64)n + 4096;
    CellTable table(ws.tableKeys, ws.tableCells, dense ? 0 : 2 * n);
    int cellCount = dense ? (int)(gridWidth * gridHeight) : 0;
    ws.cellOfEndpoint.resize(2 * (size_t)n);
    for (int e = 0; e < 2 * n; e++)
    {
        const Point c = ws.endpointCell[e];
        ws.cellOfEndpoint[e] = dense ? (int)((c.y - lowest.y + 1) * gridWidth + c.x - lowest.x + 1)
                                     : table.insert(cellKey(c.x, c.y), cellCount);
    }
    ws.cellStart.assign(cellCount + 1, 0);
    for (int e = 0; e < 2 * n; e++)
        ws.cellStart[ws.cellOfEndpoint[e] + 1]++;
    for (int c = 0; c < cellCount; c++)
        ws.cellStart[c + 1] += ws.cellStart[c];
    ws.fill.assign(ws.cellStart.begin(), ws.cellStart.end() - 1);
    ws.cellEndpoints.resize(2 * (size_t)n);
    for (int e = 0; e < 2 * n; e++)
        ws.cellEndpoints[ws.fill[ws.cellOfEndpoint[e]]++] = e;

    ws.parent.resize(n);
    for (int i = 0; i < n; i++)
        ws.parent[i] = i;
    const bool neighbourBins = params.angleBinning == LSDAdvance::ANGLE_BINS_NEIGHBOURS;
    for (int e = 0; e < 2 * n; e++)
    {
        const int seg = e >> 1;
        const Point2d p = endpoint(e);
        // The endpoints of cellEndpoints[begin .. end) that are close to p join seg's group.
        const auto compare = [&](int begin, int end) {
            for (int k = begin; k < end; k++)
            {
                const int other = ws.cellEndpoints[k] >> 1;
                if (other <= seg || !binsPair(ws.bin[seg], ws.bin[other], bins, neighbourBins))
                    continue;
                const Point2d d = endpoint(ws.cellEndpoints[k]) - p;
                if (d.dot(d) < maxDistSq)
                    unite(ws.parent, seg, other);
            }
        };
        if (dense)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                const int centre = ws.cellOfEndpoint[e] + dy * (int)gridWidth;
                compare(ws.cellStart[centre - 1], ws.cellStart[centre + 2]);
            }
            continue;
        }
        const Point c = ws.endpointCell[e];
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++)
            {
                const int cell = table.find(cellKey((int64)c.x + dx, (int64)c.y + dy));
                if (cell >= 0)
                    compare(ws.cellStart[cell], ws.cellStart[cell + 1]);
            }
    }

    // Counting sort of segments by root; roots are smallest members, so groups come out
    // ordered by their smallest member and members in increasing order. The roots' slots of
    // groupOf hold their group number once visited (a root is visited before its members).
    groups.offsets.assign(1, 0);
    ws.groupOf.resize(n);
    for (int i = 0; i < n; i++)
    {
        const int root = findRoot(ws.parent, i);
        if (root == i)
        {
            ws.groupOf[i] = groups.count();
            groups.offsets.push_back(0);
        }
        else
            ws.groupOf[i] = ws.groupOf[root];
        groups.offsets[ws.groupOf[i] + 1]++;
    }
    for (int g = 0; g < groups.count(); g++)
        groups.offsets[g + 1] += groups.offsets[g];
    groups.members.resize(n);
    ws.fill.assign(groups.offsets.begin(), groups.offsets.end() - 1);
    for (int i = 0; i < n; i++)
        groups.members[ws.fill[ws.groupOf[i]]++] = i;
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
