// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 3's projection sweep (segment_merging.hpp): the segments of a group filed by the start of
// their projection, in lanes across the direction, with removal.

#include "precomp.hpp"
#include "segment_merging.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

void ProjectionSweep::build(const std::vector<Vec4f>& geometry, const std::vector<int>& filed, const Point2d& dir,
                            double laneWidth)
{
    direction = dir;
    normal = Point2d(-dir.y, dir.x);
    const int m = (int)filed.size();
    across.resize(m);
    double lo = 0, hi = 0;
    for (int k = 0; k < m; k++)
    {
        const Vec4f& s = geometry[filed[k]];
        across[k] = normal.dot(Point2d(0.5 * ((double)s[0] + s[2]), 0.5 * ((double)s[1] + s[3])));
        lo = k == 0 ? across[k] : std::min(lo, across[k]);
        hi = k == 0 ? across[k] : std::max(hi, across[k]);
    }
    laneOrigin = lo;
    laneSize = std::max(laneWidth, (hi - lo) / std::max(m, 1) + 1e-9);
    const int laneCount = m == 0 ? 1 : (int)((hi - lo) / laneSize) + 1;
    sortBuffer.clear();
    for (int k = 0; k < m; k++)
    {
        const int lane = std::min((int)((across[k] - lo) / laneSize), laneCount - 1);
        sortBuffer.push_back(std::make_pair(std::make_pair(lane, project(geometry[filed[k]])[0]), filed[k]));
    }
    std::sort(sortBuffer.begin(), sortBuffer.end());
    starts.resize(m);
    ends.resize(m);
    ids.resize(m);
    segments.resize(m);
    positionOf.assign(geometry.size(), -1);
    nextFiled.resize(m + 1);
    previousFiled.resize(m + 1);
    for (int p = 0; p < m; p++)
    {
        ids[p] = sortBuffer[p].second;
        segments[p] = geometry[ids[p]];
        starts[p] = sortBuffer[p].first.second;
        ends[p] = project(geometry[ids[p]])[1];
        positionOf[ids[p]] = p;
    }
    // The lanes' rows over the positions, which are in lane order already.
    compressRows(m, laneCount, [&](int p) { return sortBuffer[p].first.first; }, laneStart, [](int, int) {});
    for (int p = 0; p <= m; p++)
        nextFiled[p] = previousFiled[p] = p;
}

void ProjectionSweep::lanesNear(const Vec4f& base, double low, double high, double maxOffset, int& first,
                                int& last) const
{
    first = 0;
    last = lanes() - 1;
    const Point2d a(base[0], base[1]), d(base[2] - base[0], base[3] - base[1]);
    const double len = std::sqrt(d.dot(d));
    if (!(len > 0))
        return;
    const Point2d u = d * (1.0 / len);
    const double along = direction.dot(u);
    if (std::abs(along) < std::sqrt(0.5))
        return;
    // Across-coordinate of the base's line at the projections low and high; a point within
    // maxOffset of the line is within maxOffset / |along| of it at the same projection.
    const double slope = normal.dot(u) / along, ta = direction.dot(a), qa = normal.dot(a);
    const double q1 = qa + (low - ta) * slope, q2 = qa + (high - ta) * slope;
    const double margin = withSlack(maxOffset / std::abs(along));
    const double qLow = std::min(q1, q2) - margin, qHigh = std::max(q1, q2) + margin;
    first = (int)std::max((double)first, std::floor((qLow - laneOrigin) / laneSize));
    last = (int)std::min((double)last, std::floor((qHigh - laneOrigin) / laneSize));
}

Vec2d ProjectionSweep::project(const Vec4f& s) const
{
    const double a = direction.x * s[0] + direction.y * s[1];
    const double b = direction.x * s[2] + direction.y * s[3];
    return Vec2d(std::min(a, b), std::max(a, b));
}

void ProjectionSweep::remove(int id)
{
    const int p = positionOf[id];
    if (p < 0)
        return;
    positionOf[id] = -1;
    nextFiled[p] = p + 1;
    previousFiled[p + 1] = p;
}

int ProjectionSweep::lowerBound(int lane, double value) const
{
    // std::lower_bound without a branch on the comparisons, which are unpredictable.
    int first = laneStart[lane], count = laneStart[lane + 1] - first;
    if (count == 0)
        return first;
    while (count > 1)
    {
        const int half = count / 2;
        first = starts[first + half] < value ? first + half : first;
        count -= half;
    }
    return first + (starts[first] < value);
}

}}} // namespace cv::ximgproc::lsda
