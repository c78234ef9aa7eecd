// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 3: similarity-ordered merging of each group's segments into its baselines.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

Point2d startOf(const Vec4f& s) { return Point2d(s[0], s[1]); }
Point2d endOf(const Vec4f& s) { return Point2d(s[2], s[3]); }

double pointToSegmentDistance(const Point2d& p, const Vec4f& s)
{
    const Point2d a = startOf(s), ab = endOf(s) - a;
    const double lenSq = ab.dot(ab);
    const double t = lenSq > 0 ? std::min(std::max((p - a).dot(ab) / lenSq, 0.0), 1.0) : 0.0;
    return norm(p - (a + t * ab));
}

double pointToLineDistance(const Point2d& p, const Vec4f& s)
{
    const Point2d a = startOf(s), ab = endOf(s) - a;
    const double len = norm(ab);
    if (len <= 0)
        return norm(p - a);
    return std::abs(ab.cross(p - a)) / len;
}

Point2d unitDirection(const Vec4f& s)
{
    const Point2d d = endOf(s) - startOf(s);
    const double len = norm(d);
    return len > 0 ? d * (1.0 / len) : Point2d(1, 0);
}

struct Candidate
{
    double score;
    int segment;   // index into the group's members
    int baseline;  // index into the group's members
};

// Whether seg may fuse into base: inside the perpendicular gate, closer than Dth, and scoring
// at least the threshold (the score is returned). Without the distance condition, direction and
// length alone (0.6 with the paper's weights) would join collinear pieces any distance apart.
bool passes(const Vec4f& base, const Vec4f& seg, const MergeParams& params, double& score)
{
    if (perpendicularOffset(base, seg) > params.maxPerpendicularOffset)
        return false;
    const SimilarityTerms terms = similarityTerms(base, seg, params.proximityRatio);
    if (terms.proximity <= 0)
        return false;
    score = similarityScore(terms, params);
    return score >= params.mergeThreshold;
}

// Best baseline for one segment against the current baselines; baseline -1 when none passes
// the perpendicular gate and the threshold.
Candidate bestBaseline(int segment, const std::vector<Vec4f>& geometry,
                       const std::vector<int>& baselines, const MergeParams& params)
{
    Candidate best = { -1.0, segment, -1 };
    double score;
    for (int b : baselines)
        if (passes(geometry[b], geometry[segment], params, score) && score > best.score)
            best = { score, segment, b };
    return best;
}

// The paper's rule, in place: geometry holds the group's segments, consumed marks those fused
// into a baseline.
void mergeIntoBaselines(std::vector<Vec4f>& geometry, std::vector<char>& consumed,
                        const MergeParams& params)
{
    const int n = (int)geometry.size();
    double maxLength = 0;
    for (const Vec4f& s : geometry)
        maxLength = std::max(maxLength, segmentLength(s));
    std::vector<int> baselines, pending;
    for (int i = 0; i < n; i++)
        (segmentLength(geometry[i]) >= params.baselineRatio * maxLength ? baselines : pending)
            .push_back(i);
    if (baselines.empty() || pending.empty())
        return;

    // Rounds: score every pending segment against the current baselines, fuse in decreasing
    // score order (rechecking against the baseline as grown so far), until no fusion happens.
    // A piece too far from its baseline in one round may join once its neighbour has.
    std::vector<Candidate> candidates;
    for (;;)
    {
        candidates.clear();
        for (int s : pending)
        {
            const Candidate c = bestBaseline(s, geometry, baselines, params);
            if (c.baseline >= 0)
                candidates.push_back(c);
        }
        if (candidates.empty())
            return;
        std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
            return a.score > b.score || (a.score == b.score && a.segment < b.segment);
        });
        bool fused = false;
        double score;
        for (const Candidate& c : candidates)
        {
            if (!passes(geometry[c.baseline], geometry[c.segment], params, score))
                continue;
            geometry[c.baseline] = fuseSegments(geometry[c.baseline], geometry[c.segment]);
            consumed[c.segment] = 1;
            fused = true;
        }
        if (!fused)
            return;
        pending.erase(std::remove_if(pending.begin(), pending.end(),
                                     [&](int s) { return consumed[s] != 0; }),
                      pending.end());
    }
}

// Every segment, from the longest down, absorbs the best-scoring shorter segment of its group
// again and again until none passes; equal lengths go by index. Unlike the paper's rule, two
// long collinear pieces of one edge can join.
void mergeLongestFirst(std::vector<Vec4f>& geometry, std::vector<char>& consumed,
                       const MergeParams& params)
{
    const int n = (int)geometry.size();
    std::vector<double> length(n);
    std::vector<int> order(n);
    for (int i = 0; i < n; i++)
    {
        length[i] = segmentLength(geometry[i]);
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return length[a] > length[b]; });
    for (int k = 0; k < n; k++)
    {
        const int base = order[k];
        if (consumed[base])
            continue;
        for (;;)
        {
            int best = -1;
            double bestScore = -1, score;
            for (int j = k + 1; j < n; j++)
            {
                const int seg = order[j];
                if (!consumed[seg] && passes(geometry[base], geometry[seg], params, score) && score > bestScore)
                {
                    best = seg;
                    bestScore = score;
                }
            }
            if (best < 0)
                break;
            geometry[base] = fuseSegments(geometry[base], geometry[best]);
            consumed[best] = 1;
        }
    }
}

} // namespace

double segmentDistance(const Vec4f& a, const Vec4f& b)
{
    return std::min(std::min(pointToSegmentDistance(startOf(a), b), pointToSegmentDistance(endOf(a), b)),
                    std::min(pointToSegmentDistance(startOf(b), a), pointToSegmentDistance(endOf(b), a)));
}

double perpendicularOffset(const Vec4f& baseline, const Vec4f& other)
{
    return std::max(pointToLineDistance(startOf(other), baseline),
                    pointToLineDistance(endOf(other), baseline));
}

SimilarityTerms similarityTerms(const Vec4f& baseline, const Vec4f& other, double proximityRatio)
{
    const double lb = segmentLength(baseline), lo = segmentLength(other);
    SimilarityTerms t;
    // A point has no direction: it must not score as if it pointed along the baseline.
    t.direction = lb > 0 && lo > 0 ? std::max(unitDirection(baseline).dot(unitDirection(other)), 0.0) : 0.0;
    const double threshold = proximityRatio * 0.5 * (lb + lo);
    const double dmin = segmentDistance(baseline, other);
    t.proximity = threshold > 0 ? std::max(1.0 - dmin / threshold, 0.0) : (dmin > 0 ? 0.0 : 1.0);
    const double longer = std::max(lb, lo);
    t.length = longer > 0 ? 1.0 - std::abs(lb - lo) / longer : 1.0;
    return t;
}

double similarityScore(const SimilarityTerms& t, const MergeParams& p)
{
    return p.directionWeight * t.direction + p.proximityWeight * t.proximity +
           p.lengthWeight * t.length;
}

Vec4f fuseSegments(const Vec4f& baseline, const Vec4f& other)
{
    const double l1 = segmentLength(baseline), l2 = segmentLength(other);
    const Point2d m1 = (startOf(baseline) + endOf(baseline)) * 0.5;
    const Point2d m2 = (startOf(other) + endOf(other)) * 0.5;
    const Point2d centre = l1 + l2 > 0 ? (l1 * m1 + l2 * m2) * (1.0 / (l1 + l2)) : m1;

    // Directions as unit vectors oriented like the baseline: a mean of angles would break at
    // the 0/180 wrap.
    const Point2d u1 = unitDirection(baseline);
    Point2d u2 = unitDirection(other);
    if (u2.dot(u1) < 0)
        u2 = -u2;
    Point2d dir = l1 * u1 + l2 * u2;
    const double dirNorm = norm(dir);
    dir = dirNorm > 0 ? dir * (1.0 / dirNorm) : u1;

    const Point2d ends[4] = { startOf(baseline), endOf(baseline), startOf(other), endOf(other) };
    double tMin = 0, tMax = 0;
    for (int i = 0; i < 4; i++)
    {
        const double t = (ends[i] - centre).dot(dir);
        tMin = i == 0 ? t : std::min(tMin, t);
        tMax = i == 0 ? t : std::max(tMax, t);
    }
    const Point2d a = centre + tMin * dir, b = centre + tMax * dir;
    return Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y);
}

void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                 const MergeParams& params, std::vector<Vec4f>& merged)
{
    merged.clear();
    merged.reserve(segments.size());
    std::vector<Vec4f> geometry;
    std::vector<char> consumed;
    for (int g = 0; g < groups.count(); g++)
    {
        const int begin = groups.offsets[g], end = groups.offsets[g + 1];
        geometry.clear();
        for (int k = begin; k < end; k++)
            geometry.push_back(segments[groups.members[k]]);
        consumed.assign(geometry.size(), 0);
        if (geometry.size() > 1 && params.strategy == MergeStrategy::BASELINES)
            mergeIntoBaselines(geometry, consumed, params);
        else if (geometry.size() > 1 && params.strategy == MergeStrategy::LONGEST_FIRST)
            mergeLongestFirst(geometry, consumed, params);
        for (size_t k = 0; k < geometry.size(); k++)
            if (!consumed[k])
                merged.push_back(geometry[k]);
    }
}

}}} // namespace cv::ximgproc::lsda
