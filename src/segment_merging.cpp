// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 3: similarity-ordered merging of each group's segments into its baselines.

#include "precomp.hpp"
#include "segment_merging.hpp"
#include "opencv2/core/hal/intrin.hpp"

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

// The second moment (xx, xy, yy) about c of a segment of length l as a uniform mass along it:
// l (d d^T / 12 + (m - c)(m - c)^T), with d its vector and m its centre.
Vec3d secondMoment(const Vec4f& s, double l, const Point2d& c)
{
    const Point2d d = endOf(s) - startOf(s), o = (startOf(s) + endOf(s)) * 0.5 - c;
    return l * Vec3d(d.x * d.x / 12.0 + o.x * o.x, d.x * d.y / 12.0 + o.x * o.y, d.y * d.y / 12.0 + o.y * o.y);
}

// similarityTerms() and fuseSegments() given the segments' lengths (segmentLength()): merging
// keeps the length of each segment of a group, as fusions change them, instead of measuring
// the same segments again at every comparison.
// Reach (below) relies on these terms' bounds: Sd <= 1, Sp <= 1 - gap / Dth, Sl <= the ratio of
// the lengths.
SimilarityTerms similarityTermsOfLengths(const Vec4f& baseline, const Vec4f& other, double lb, double lo,
                                         double proximityRatio)
{
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

Vec4f fuseSegmentsOfLengths(const Vec4f& baseline, const Vec4f& other, double l1, double l2)
{
    const Point2d m1 = (startOf(baseline) + endOf(baseline)) * 0.5;
    const Point2d m2 = (startOf(other) + endOf(other)) * 0.5;
    const Point2d centre = l1 + l2 > 0 ? (l1 * m1 + l2 * m2) * (1.0 / (l1 + l2)) : m1;

    // The least-squares line of the two as uniform masses: the principal axis of their second
    // moments about the centre, oriented like the baseline. Parallel runs one step apart, the
    // pieces of an aliased edge, fuse along the line through them; the mean of their directions
    // would keep the runs' direction, and the next run would fall outside the perpendicular gate.
    const Vec3d moments = secondMoment(baseline, l1, centre) + secondMoment(other, l2, centre);
    const Point2d u1 = unitDirection(baseline);
    // The eigenvector of the larger eigenvalue, from whichever of its two forms is longer: exact
    // along an axis (a border's pieces stay on it).
    const double half = 0.5 * (moments[0] - moments[2]);
    const double lambda = 0.5 * (moments[0] + moments[2]) + std::sqrt(half * half + moments[1] * moments[1]);
    const Point2d fromXy(moments[1], lambda - moments[0]), fromYy(lambda - moments[2], moments[1]);
    Point2d dir = fromXy.dot(fromXy) > fromYy.dot(fromYy) ? fromXy : fromYy;
    const double dirNorm = norm(dir);
    dir = dirNorm > 0 ? dir * (1.0 / dirNorm) : u1;
    if (dir.dot(u1) < 0)
        dir = -dir;

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

// Whether the gap between two segments along the line they fuse into (from the end of the
// projection of one on it to the start of the other's; none when they overlap) is on the mask.
bool gapInMask(const Mat& mask, const Vec4f& base, const Vec4f& seg)
{
    const Vec4f fused = fuseSegments(base, seg);
    const Point2d origin = startOf(fused), u = unitDirection(fused);
    const auto along = [&](const Point2d& p) { return (p - origin).dot(u); };
    const double a0 = std::min(along(startOf(base)), along(endOf(base))), a1 = std::max(along(startOf(base)), along(endOf(base)));
    const double b0 = std::min(along(startOf(seg)), along(endOf(seg))), b1 = std::max(along(startOf(seg)), along(endOf(seg)));
    const double from = std::min(a1, b1), to = std::max(a0, b0);
    return from >= to || inMask(mask, origin + u * from, origin + u * to);
}

// Whether seg may fuse into base: inside the perpendicular gate, closer than Dth, and scoring
// at least the threshold (the score is returned). Without the distance condition, direction and
// length alone (0.6 with the paper's weights) would join collinear pieces any distance apart.
// With a mask, the gap between the two along their fused line must also be on it. baseLength and
// segLength are their lengths.
bool passes(const Vec4f& base, const Vec4f& seg, double baseLength, double segLength, const MergingParams& params,
            const Mat& mask, double& score)
{
    if (perpendicularOffset(base, seg) > params.maxPerpendicularOffset)
        return false;
    const SimilarityTerms terms = similarityTermsOfLengths(base, seg, baseLength, segLength, params.proximityRatio);
    if (terms.proximity <= 0)
        return false;
    score = similarityScore(terms, params);
    return score >= params.mergeThreshold && (mask.empty() || gapInMask(mask, base, seg));
}

// Lanes of the sweep: 8 times the perpendicular gate, at least 8 px (narrower lanes cost more
// look-ups than they save on YorkUrban and on the synthetic sets).
double laneWidth(const MergingParams& params)
{
    return std::max(8.0 * params.maxPerpendicularOffset, 8.0);
}

// How far apart (as projections) a base of length baseLength and a segment at most maxOther
// long can be and still score at least cutoff. Dmin is at least the gap between the
// projections, must stay below Dth <= ratio * (baseLength + maxOther) / 2, and bounds Sp;
// Sd <= 1, and Sl <= min(1, maxOther / baseLength).
// This bound is derived from similarityTerms() and similarityScore() below: a change of the
// score's formula must change it (test LSDAdvance_MergingSweep compares the sweep with the
// all-pairs rule).
struct Reach
{
    Reach(double baseLength, double maxOther, const MergingParams& p)
        : params(p), maxDistance(p.proximityRatio * 0.5 * (baseLength + maxOther)),
          lengthBound(baseLength > 0 ? std::min(1.0, maxOther / baseLength) : 1.0)
    {}
    double operator()(double cutoff) const
    {
        double reach = maxDistance;
        if (params.proximityWeight > 0)
            reach = std::min(reach, maxDistance * (1.0 - (cutoff - 1e-9 - params.directionWeight -
                                                          params.lengthWeight * lengthBound) /
                                                             params.proximityWeight));
        return withSlack(reach);
    }

    const MergingParams& params;
    double maxDistance, lengthBound;
};

// The perpendicular gate of passes() with the base's normal computed once: a cheap first test
// for the many parallel pieces of a textured group, which overlap the base's projection but lie
// off its line. Lets through everything passes() might accept (rounding slack included).
class LineGate
{
public:
    LineGate(const Vec4f& base, double maxOffset) : origin(base[0], base[1]), limit(withSlack(maxOffset))
    {
        const Point2d d(base[2] - base[0], base[3] - base[1]);
        const double len = std::sqrt(d.dot(d));
        normal = len > 0 ? Point2d(-d.y / len, d.x / len) : Point2d(0, 0);
        open = !(len > 0);
        baseEnd = along(Point2d(base[2], base[3]));
    }
    bool mayPass(const Vec4f& s) const
    {
        return open || mayPass(Point2d(s[0], s[1]), Point2d(s[2], s[3]));
    }
    // The same for a segment that is not a point (as a base, open) from a to b.
    bool mayPass(const Point2d& a, const Point2d& b) const
    {
        return std::abs(normal.dot(a - origin)) <= limit && std::abs(normal.dot(b - origin)) <= limit;
    }
    // The gap between the projections of the base and of the segment from a to b on the base's
    // direction (0 for a point as base): no more than the distance between the two.
    double gapAlong(const Point2d& a, const Point2d& b) const
    {
        const double ta = along(a), tb = along(b);
        return std::max(std::max(std::min(ta, tb) - baseEnd, -std::max(ta, tb)), 0.0);
    }
    // Calls visit(j) for each j of [from, to) whose segment, (x0[j], y0[j]) to (x1[j], y1[j]),
    // may pass (a point as base lets every segment through).
    template <class Visit>
    void visitMayPass(const double* x0, const double* y0, const double* x1, const double* y1, int from, int to,
                      Visit visit) const
    {
        int j = from;
#if CV_SIMD128_64F
        // Two at a time, with mayPass()'s operations lane by lane.
        const v_float64x2 nx = v_setall_f64(normal.x), ny = v_setall_f64(normal.y);
        const v_float64x2 ox = v_setall_f64(origin.x), oy = v_setall_f64(origin.y), bound = v_setall_f64(limit);
        for (; j + 2 <= to; j += 2)
        {
            const v_float64x2 a = v_abs(nx * (v_load(x0 + j) - ox) + ny * (v_load(y0 + j) - oy));
            const v_float64x2 b = v_abs(nx * (v_load(x1 + j) - ox) + ny * (v_load(y1 + j) - oy));
            const int near = v_signmask((a <= bound) & (b <= bound));
            if (near & 1)
                visit(j);
            if (near & 2)
                visit(j + 1);
        }
#endif
        for (; j < to; j++)
            if (open || mayPass(Point2d(x0[j], y0[j]), Point2d(x1[j], y1[j])))
                visit(j);
    }

private:
    double along(const Point2d& p) const { return normal.y * (p.x - origin.x) - normal.x * (p.y - origin.y); }

    Point2d origin, normal;
    double limit, baseEnd;
    bool open;
};

// The paper's rule, in place: ws.geometry holds the group's segments, ws.consumed marks those
// fused into a baseline. Rounds: score every pending segment against the current baselines,
// fuse in decreasing score order (rechecking against the baseline as grown so far), until no
// fusion happens; a piece too far from its baseline in one round may join once its neighbour
// has. Only the segments a grown baseline can reach, and those whose fusion failed, are scored
// again: the others' best baseline cannot have changed.
void mergeIntoBaselines(GroupWorkspace& ws, const MergingParams& params, const Mat& mask)
{
    std::vector<Vec4f>& geometry = ws.geometry;
    const int n = (int)geometry.size();
    double maxLength = 0;
    int longest = 0;
    for (int i = 0; i < n; i++)
    {
        ws.length[i] = segmentLength(geometry[i]);
        if (ws.length[i] > maxLength)
        {
            maxLength = ws.length[i];
            longest = i;
        }
    }
    ws.baselines.clear();
    ws.pending.clear();
    double maxPending = 0;
    for (int i = 0; i < n; i++)
    {
        const bool baseline = ws.length[i] >= params.baselineRatio * maxLength;
        (baseline ? ws.baselines : ws.pending).push_back(i);
        if (!baseline)
            maxPending = std::max(maxPending, ws.length[i]);
    }
    if (ws.baselines.empty() || ws.pending.empty())
        return;

    ProjectionSweep& sweep = ws.sweep;
    sweep.build(geometry, ws.pending, unitDirection(geometry[longest]), laneWidth(params));
    ws.dirty.assign(n, 0);
    ws.isChanged.assign(n, 0);
    for (int s : ws.pending)
        ws.dirty[s] = 1;
    for (;;)
    {
        // The baselines by the start of their projection, as grown so far.
        ws.baselineStarts.clear();
        double maxBaselineLength = 0, maxBaselineExtent = 0;
        for (int b : ws.baselines)
        {
            const Vec2d span = sweep.project(geometry[b]);
            ws.baselineStarts.push_back(std::make_pair(span[0], b));
            maxBaselineLength = std::max(maxBaselineLength, ws.length[b]);
            maxBaselineExtent = std::max(maxBaselineExtent, span[1] - span[0]);
        }
        std::sort(ws.baselineStarts.begin(), ws.baselineStarts.end());

        ws.candidates.clear();
        for (int s : ws.pending)
        {
            if (!ws.dirty[s])
                continue;
            ws.dirty[s] = 0;
            // Best baseline, ties to the smaller index: baselines whose projection comes within
            // Dth <= reach of the segment's.
            MergeCandidate best = { -1.0, s, -1 };
            const Vec2d span = sweep.project(geometry[s]);
            const double reach = withSlack(params.proximityRatio * 0.5 * (maxBaselineLength + ws.length[s]));
            auto it = std::lower_bound(ws.baselineStarts.begin(), ws.baselineStarts.end(),
                                       std::make_pair(span[0] - reach - maxBaselineExtent, -1));
            double score;
            for (; it != ws.baselineStarts.end() && it->first <= span[1] + reach; ++it)
            {
                const int b = it->second;
                if (passes(geometry[b], geometry[s], ws.length[b], ws.length[s], params, mask, score) &&
                    (score > best.score || (score == best.score && b < best.baseline)))
                    best = { score, s, b };
            }
            if (best.baseline >= 0)
                ws.candidates.push_back(best);
        }
        if (ws.candidates.empty())
            return;
        std::sort(ws.candidates.begin(), ws.candidates.end(), [](const MergeCandidate& a, const MergeCandidate& b) {
            return a.score > b.score || (a.score == b.score && a.segment < b.segment);
        });
        ws.changed.clear();
        double score;
        for (const MergeCandidate& c : ws.candidates)
        {
            if (!passes(geometry[c.baseline], geometry[c.segment], ws.length[c.baseline], ws.length[c.segment], params,
                        mask, score))
                continue;
            geometry[c.baseline] = fuseSegmentsOfLengths(geometry[c.baseline], geometry[c.segment],
                                                         ws.length[c.baseline], ws.length[c.segment]);
            ws.length[c.baseline] = segmentLength(geometry[c.baseline]);
            ws.consumed[c.segment] = 1;
            ws.fusedInto[c.segment] = c.baseline;
            sweep.remove(c.segment);
            if (!ws.isChanged[c.baseline])
            {
                ws.isChanged[c.baseline] = 1;
                ws.changed.push_back(c.baseline);
            }
        }
        if (ws.changed.empty())
            return;
        ws.pending.erase(std::remove_if(ws.pending.begin(), ws.pending.end(),
                                        [&](int s) { return ws.consumed[s] != 0; }),
                         ws.pending.end());
        for (const MergeCandidate& c : ws.candidates)
            ws.dirty[c.segment] = !ws.consumed[c.segment];
        for (int b : ws.changed)
        {
            ws.isChanged[b] = 0;
            const Vec2d span = sweep.project(geometry[b]);
            const double reach = withSlack(params.proximityRatio * 0.5 * (ws.length[b] + maxPending));
            const double low = span[0] - reach - withSlack(maxPending), high = span[1] + reach;
            int firstLane, lastLane;
            sweep.lanesNear(geometry[b], low, high + withSlack(maxPending), params.maxPerpendicularOffset,
                            firstLane, lastLane);
            for (int lane = firstLane; lane <= lastLane; lane++)
                for (int p = sweep.filedFrom(sweep.lowerBound(lane, low));
                     p < sweep.laneEnd(lane) && sweep.start(p) <= high; p = sweep.next(p))
                    if (sweep.end(p) >= span[0] - reach)
                        ws.dirty[sweep.id(p)] = 1;
        }
    }
}

// Every segment, from the longest down, absorbs the best-scoring shorter segment of its group
// again and again until none passes; equal lengths go by index. Unlike the paper's rule, two
// long collinear pieces of one edge can join. In a large group the shorter segments are visited
// outwards from the base's projection and the visit stops where no segment can reach the best
// score so far; in a smaller one each is tested against the base's line and projection.
void mergeLongestFirst(GroupWorkspace& ws, const MergingParams& params, const Mat& mask)
{
    std::vector<Vec4f>& geometry = ws.geometry;
    const int n = (int)geometry.size();
    ws.byLength.resize(n);
    ws.ids.resize(n);
    for (int i = 0; i < n; i++)
    {
        ws.length[i] = segmentLength(geometry[i]);
        ws.byLength[i] = std::make_pair(-ws.length[i], i);
        ws.ids[i] = i;
    }
    // Longest first, equal lengths by index (a stable sort, without its temporary buffer; the
    // keys beside the indices, not behind them).
    std::sort(ws.byLength.begin(), ws.byLength.end());
    ws.order.resize(n);
    ws.rank.resize(n);
    for (int c = 0; c < 4; c++)
        ws.ranked[c].resize(n);
    for (int k = 0; k < n; k++)
    {
        ws.order[k] = ws.byLength[k].second;
        const Vec4f& s = geometry[ws.order[k]];
        ws.rank[ws.order[k]] = k;
        for (int c = 0; c < 4; c++)
            ws.ranked[c][k] = s[c];
    }

    // Filed: the segments that may still fuse into the current base (shorter, not consumed). A
    // smaller group is compared pair by pair instead, which costs less than filing it.
    ProjectionSweep& sweep = ws.sweep;
    const bool sweeping = n >= kSweptGroupSize;
    if (sweeping)
        sweep.build(geometry, ws.ids, unitDirection(geometry[ws.order[0]]), laneWidth(params));
    for (int k = 0; k < n; k++)
    {
        const int base = ws.order[k];
        if (ws.consumed[base])
            continue;
        if (sweeping)
            sweep.remove(base);
        const double maxOther = k + 1 < n ? ws.length[ws.order[k + 1]] : 0.0;
        for (;;)
        {
            const Vec4f& b = geometry[base];
            const Reach reach(ws.length[base], maxOther, params);
            int best = -1;
            double bestScore = -1, score;
            double radius = reach(params.mergeThreshold);
            const LineGate gate(b, params.maxPerpendicularOffset);
            // seg's geometry is s (the sweep's copy of it when filed).
            auto consider = [&](int seg, const Vec4f& s) {
                if (gate.mayPass(s) && passes(b, s, ws.length[base], ws.length[seg], params, mask, score) &&
                    (score > bestScore || (score == bestScore && ws.rank[seg] < ws.rank[best])))
                {
                    best = seg;
                    bestScore = score;
                    radius = reach(score);
                }
            };
            if (!sweeping)
            {
                // Every shorter segment of the group near the base's line whose projection comes
                // within the radius.
                gate.visitMayPass(ws.ranked[0].data(), ws.ranked[1].data(), ws.ranked[2].data(), ws.ranked[3].data(), k + 1, n,
                                  [&](int j) {
                                      const int seg = ws.order[j];
                                      if (!ws.consumed[seg] &&
                                          gate.gapAlong(Point2d(ws.ranked[0][j], ws.ranked[1][j]),
                                                        Point2d(ws.ranked[2][j], ws.ranked[3][j])) <= radius)
                                          consider(seg, geometry[seg]);
                                  });
            }
            else
            {
                // In the lanes the base's line crosses: ahead of the base's projection, then
                // overlapping or behind it.
                const Vec2d span = sweep.project(b);
                const double maxExtent = withSlack(maxOther);
                int firstLane, lastLane;
                sweep.lanesNear(b, span[0] - radius - maxExtent, span[1] + radius + maxExtent,
                                params.maxPerpendicularOffset, firstLane, lastLane);
                for (int lane = firstLane; lane <= lastLane; lane++)
                {
                    const int ahead = sweep.lowerBound(lane, span[1]);
                    for (int p = sweep.filedFrom(ahead); p < sweep.laneEnd(lane) && sweep.start(p) - span[1] <= radius;
                         p = sweep.next(p))
                        consider(sweep.id(p), sweep.segment(p));
                    for (int p = sweep.filedBefore(ahead);
                         p >= sweep.laneBegin(lane) && sweep.start(p) + maxExtent >= span[0] - radius;
                         p = sweep.previous(p))
                        if (span[0] - sweep.end(p) <= radius)
                            consider(sweep.id(p), sweep.segment(p));
                }
            }
            if (best < 0)
                break;
            geometry[base] = fuseSegmentsOfLengths(geometry[base], geometry[best], ws.length[base], ws.length[best]);
            ws.length[base] = segmentLength(geometry[base]);
            ws.consumed[best] = 1;
            ws.fusedInto[best] = base;
            if (sweeping)
                sweep.remove(best);
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
    return similarityTermsOfLengths(baseline, other, segmentLength(baseline), segmentLength(other), proximityRatio);
}

// Reach (above) bounds this score from the gap between two projections: change both together.
double similarityScore(const SimilarityTerms& t, const MergingParams& p)
{
    return p.directionWeight * t.direction + p.proximityWeight * t.proximity +
           p.lengthWeight * t.length;
}

Vec4f fuseSegments(const Vec4f& baseline, const Vec4f& other)
{
    return fuseSegmentsOfLengths(baseline, other, segmentLength(baseline), segmentLength(other));
}

namespace {

// Members per task of stage 3, at least: most groups hold one segment, and a task of a few
// costs the pool more than their merging.
constexpr int kMembersPerTask = 64;

// Merges group g alone: its survivors go to ws.placed from the place of its first member on,
// and each member's mergedInto to the place of the survivor it is part of.
void mergeGroup(const std::vector<Vec4f>& segments, const SegmentGroups& groups, int g,
                const MergingParams& params, const Mat& mask, GroupWorkspace& ws,
                std::vector<Vec4f>& placed, int& survivors, std::vector<int>& mergedInto)
{
    const int begin = groups.offsets[g], end = groups.offsets[g + 1];
    if (end - begin == 1)
    {
        for (int k = begin; k < end; k++)
        {
            mergedInto[groups.members[k]] = k;
            placed[k] = segments[groups.members[k]];
        }
        survivors = end - begin;
        return;
    }
    const int n = end - begin;
    ws.geometry.clear();
    for (int k = begin; k < end; k++)
        ws.geometry.push_back(segments[groups.members[k]]);
    ws.consumed.assign(n, 0);
    ws.fusedInto.assign(n, -1);
    ws.length.resize(n);
    if (params.mergeStrategy == LSDAdvance::MERGE_BASELINES)
        mergeIntoBaselines(ws, params, mask);
    else
        mergeLongestFirst(ws, params, mask);
    ws.outputOf.assign(n, -1);
    survivors = 0;
    for (int k = 0; k < n; k++)
        if (!ws.consumed[k])
        {
            ws.outputOf[k] = begin + survivors;
            placed[begin + survivors++] = ws.geometry[k];
        }
    // A consumed segment is part of what it was fused into, and so on until a survivor.
    for (int k = 0; k < n; k++)
    {
        int owner = k;
        while (ws.consumed[owner])
            owner = ws.fusedInto[owner];
        mergedInto[groups.members[begin + k]] = ws.outputOf[owner];
    }
}

} // namespace

void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                 const MergingParams& params, std::vector<Vec4f>& merged, std::vector<int>& mergedInto,
                 MergeWorkspace& ws, const Mat& mask)
{
    CV_Assert(params.mergeStrategy != LSDAdvance::MERGE_NONE);
    merged.clear();
    merged.reserve(segments.size());
    mergedInto.assign(segments.size(), -1);
    const int count = groups.count();
    ws.tasks.byWeight(count, kMembersPerTask, [&](int g) { return groups.offsets[g + 1] - groups.offsets[g]; });
    if (ws.taskWorkspaces.size() < (size_t)ws.tasks.count())
        ws.taskWorkspaces.resize(ws.tasks.count());
    ws.placed.resize(groups.members.size());
    ws.survivors.resize(count);
    runTasks(ws.tasks, [&](int task, const Range& taskGroups) {
        for (int g = taskGroups.start; g < taskGroups.end; g++)
            mergeGroup(segments, groups, g, params, mask, ws.taskWorkspaces[task], ws.placed, ws.survivors[g], mergedInto);
    });

    // The survivors in group order; the places mergedInto holds become their indices there.
    ws.outputIndex.resize(groups.members.size());
    for (int g = 0; g < count; g++)
        for (int k = groups.offsets[g]; k < groups.offsets[g] + ws.survivors[g]; k++)
        {
            ws.outputIndex[k] = (int)merged.size();
            merged.push_back(ws.placed[k]);
        }
    for (int& m : mergedInto)
        if (m >= 0)
            m = ws.outputIndex[m];
}

void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                 const MergingParams& params, std::vector<Vec4f>& merged, const Mat& mask)
{
    MergeWorkspace workspace;
    std::vector<int> mergedInto;
    mergeGroups(segments, groups, params, merged, mergedInto, workspace, mask);
}

MergeStage::MergeStage() : mergingBuffers(makePtr<MergeWorkspace>()) {}

MergeStage::~MergeStage() = default;

void MergeStage::apply(const std::vector<Vec4f>& in, const GroupingParams& grouping, const MergingParams& merging,
                       const Mat& mask, std::vector<Vec4f>& merged, LSDAdvanceStats& stats)
{
    isGrouped = merging.mergeStrategy != LSDAdvance::MERGE_NONE;
    if (!isGrouped)
    {
        merged = in;
        into.resize(in.size());
        for (size_t i = 0; i < in.size(); i++)
            into[i] = (int)i;
        stats.mergedSegments = (int)in.size();
        return;
    }
    int64 t = getTickCount();
    groupSegments(in, grouping, segmentGroups, groupingBuffers);
    stats.mergeGroups = mergeGroupCount(segmentGroups);
    stats.groupingMs = elapsedMs(t);
    t = getTickCount();
    mergeGroups(in, segmentGroups, merging, merged, into, *mergingBuffers, mask);
    stats.mergedSegments = (int)merged.size();
    stats.mergingMs = elapsedMs(t);
}

void MergeStage::labels(std::vector<int>& groupLabels) const
{
    if (isGrouped)
        lsda::groupLabels(segmentGroups, groupLabels);
    else
        groupLabels.clear();
}

}}} // namespace cv::ximgproc::lsda
