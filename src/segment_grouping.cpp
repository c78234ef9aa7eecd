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
struct DisjointSets
{
    std::vector<int> parent;

    explicit DisjointSets(int n) : parent(n)
    {
        for (int i = 0; i < n; i++)
            parent[i] = i;
    }
    int find(int i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
    void unite(int a, int b)
    {
        a = find(a);
        b = find(b);
        if (a < b)
            parent[b] = a;
        else if (b < a)
            parent[a] = b;
    }
};

// An endpoint filed under its grid cell. Cells are squares of the adjacency distance, so two
// endpoints closer than it are in the same or in neighbouring cells: each endpoint is compared
// with the endpoints of 9 cells only, never with all of them.
struct CellEntry
{
    int64 cell;
    int endpoint;  // 2 * segment + (0 for the start, 1 for the end)

    bool operator<(const CellEntry& o) const
    {
        return cell < o.cell || (cell == o.cell && endpoint < o.endpoint);
    }
};

// Cells fit in 32 bits: coordinates are finite and bounded (checked by the caller), and the
// cell size is at least 0.1 px.
int64 cellKey(int64 cx, int64 cy)
{
    return (int64)(((uint64)(uint32_t)cx << 32) | (uint64)(uint32_t)cy);
}

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
                   SegmentGroups& groups)
{
    CV_CheckGT(params.angleBinWidth, 0.0, "angle bins have a width");
    CV_CheckGE(params.endpointDistance, 0.1, "grid cells are at least 0.1 px");
    const int n = (int)segments.size();
    const int bins = binCount(params.angleBinWidth);
    const double cellSize = params.endpointDistance;
    const double maxDistSq = cellSize * cellSize;

    std::vector<int> bin(n);
    for (int i = 0; i < n; i++)
        bin[i] = angleBin(segments[i], params.angleBinWidth);

    auto endpoint = [&](int e) {
        const Vec4f& s = segments[e >> 1];
        return (e & 1) ? Point2d(s[2], s[3]) : Point2d(s[0], s[1]);
    };
    auto cellOf = [&](const Point2d& p) {
        return std::make_pair((int64)std::floor(p.x / cellSize), (int64)std::floor(p.y / cellSize));
    };

    std::vector<CellEntry> grid(2 * (size_t)n);
    for (int e = 0; e < 2 * n; e++)
    {
        const std::pair<int64, int64> c = cellOf(endpoint(e));
        grid[e] = { cellKey(c.first, c.second), e };
    }
    std::sort(grid.begin(), grid.end());

    DisjointSets sets(n);
    for (int e = 0; e < 2 * n; e++)
    {
        const int seg = e >> 1;
        const Point2d p = endpoint(e);
        const std::pair<int64, int64> c = cellOf(p);
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++)
            {
                const CellEntry first = { cellKey(c.first + dx, c.second + dy), 0 };
                for (auto it = std::lower_bound(grid.begin(), grid.end(), first);
                     it != grid.end() && it->cell == first.cell; ++it)
                {
                    const int other = it->endpoint >> 1;
                    if (other <= seg || !binsPair(bin[seg], bin[other], bins, params.neighbourBins))
                        continue;
                    const Point2d d = endpoint(it->endpoint) - p;
                    if (d.dot(d) < maxDistSq)
                        sets.unite(seg, other);
                }
            }
    }

    // Counting sort of segments by root; roots are smallest members, so groups come out
    // ordered by their smallest member and members in increasing order.
    std::vector<int> groupOfRoot(n, -1);
    groups.offsets.assign(1, 0);
    std::vector<int> groupOf(n);
    for (int i = 0; i < n; i++)
    {
        const int root = sets.find(i);
        if (groupOfRoot[root] < 0)
        {
            groupOfRoot[root] = groups.count();
            groups.offsets.push_back(0);
        }
        groupOf[i] = groupOfRoot[root];
        groups.offsets[groupOf[i] + 1]++;
    }
    for (int g = 0; g < groups.count(); g++)
        groups.offsets[g + 1] += groups.offsets[g];
    groups.members.resize(n);
    std::vector<int> fill(groups.offsets.begin(), groups.offsets.end() - 1);
    for (int i = 0; i < n; i++)
        groups.members[fill[groupOf[i]]++] = i;
}

}}} // namespace cv::ximgproc::lsda
