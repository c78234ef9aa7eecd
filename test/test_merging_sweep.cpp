// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 3 visits only the segments whose projections come near a segment's (ProjectionSweep).
// These tests compare it with the rule written out over every pair of a group.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

struct MergeCandidate
{
    double score;
    int segment, baseline;  // indices into the group
};

bool passesReference(const Vec4f& base, const Vec4f& seg, const lsda::MergingParams& p, double& score)
{
    if (lsda::perpendicularOffset(base, seg) > p.maxPerpendicularOffset)
        return false;
    const lsda::SimilarityTerms t = lsda::similarityTerms(base, seg, p.proximityRatio);
    if (t.proximity <= 0)
        return false;
    score = lsda::similarityScore(t, p);
    return score >= p.mergeThreshold;
}

// MERGE_LONGEST_FIRST over every pair: from the longest down, absorb the best-scoring shorter
// segment (ties: the earlier in length order) until none passes.
void longestFirstReference(std::vector<Vec4f>& g, std::vector<char>& consumed, const lsda::MergingParams& p)
{
    const int n = (int)g.size();
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> len(n);
    for (int i = 0; i < n; i++)
        len[i] = lsda::segmentLength(g[i]);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return len[a] > len[b]; });
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
                if (!consumed[order[j]] && passesReference(g[base], g[order[j]], p, score) && score > bestScore)
                {
                    best = order[j];
                    bestScore = score;
                }
            if (best < 0)
                break;
            g[base] = lsda::fuseSegments(g[base], g[best]);
            consumed[best] = 1;
        }
    }
}

// MERGE_BASELINES over every pair: rounds of best-baseline candidates, fused best first.
void baselinesReference(std::vector<Vec4f>& g, std::vector<char>& consumed, const lsda::MergingParams& p)
{
    const int n = (int)g.size();
    double maxLength = 0;
    for (const Vec4f& s : g)
        maxLength = std::max(maxLength, lsda::segmentLength(s));
    std::vector<int> baselines, pending;
    for (int i = 0; i < n; i++)
        (lsda::segmentLength(g[i]) >= p.baselineRatio * maxLength ? baselines : pending).push_back(i);
    if (baselines.empty() || pending.empty())
        return;
    for (;;)
    {
        std::vector<MergeCandidate> candidates;
        for (int s : pending)
        {
            MergeCandidate best = { -1.0, s, -1 };
            double score;
            for (int b : baselines)
                if (passesReference(g[b], g[s], p, score) && score > best.score)
                    best = { score, s, b };
            if (best.baseline >= 0)
                candidates.push_back(best);
        }
        if (candidates.empty())
            return;
        std::sort(candidates.begin(), candidates.end(), [](const MergeCandidate& a, const MergeCandidate& b) {
            return a.score > b.score || (a.score == b.score && a.segment < b.segment);
        });
        bool fused = false;
        double score;
        for (const MergeCandidate& c : candidates)
            if (passesReference(g[c.baseline], g[c.segment], p, score))
            {
                g[c.baseline] = lsda::fuseSegments(g[c.baseline], g[c.segment]);
                consumed[c.segment] = 1;
                fused = true;
            }
        if (!fused)
            return;
        pending.erase(std::remove_if(pending.begin(), pending.end(), [&](int s) { return consumed[s] != 0; }),
                      pending.end());
    }
}

std::vector<Vec4f> mergeReference(const std::vector<Vec4f>& segments, const lsda::SegmentGroups& groups,
                                  const lsda::MergingParams& p)
{
    std::vector<Vec4f> merged;
    for (int gi = 0; gi < groups.count(); gi++)
    {
        std::vector<Vec4f> g;
        for (int k = groups.offsets[gi]; k < groups.offsets[gi + 1]; k++)
            g.push_back(segments[groups.members[k]]);
        std::vector<char> consumed(g.size(), 0);
        if (g.size() > 1 && p.mergeStrategy == LSDAdvance::MERGE_BASELINES)
            baselinesReference(g, consumed, p);
        else if (g.size() > 1 && p.mergeStrategy == LSDAdvance::MERGE_LONGEST_FIRST)
            longestFirstReference(g, consumed, p);
        for (size_t k = 0; k < g.size(); k++)
            if (!consumed[k])
                merged.push_back(g[k]);
    }
    return merged;
}

// Chains of collinear pieces of mixed lengths and orientations, parallel chains 2 px beside
// them, a few pieces reversed, zero-length pieces, and clutter.
std::vector<Vec4f> fragmentedLines(RNG& rng, int lines, double extent)
{
    std::vector<Vec4f> segments;
    for (int l = 0; l < lines; l++)
    {
        const Point2d start(rng.uniform(0.0, extent), rng.uniform(0.0, extent));
        const double angle = rng.uniform(0.0, 2 * CV_PI);
        const Point2d u(std::cos(angle), std::sin(angle)), normal(-u.y, u.x);
        const double length = rng.uniform(50.0, 600.0);
        const bool twin = rng.uniform(0, 3) == 0;
        for (double t = 0; t < length;)
        {
            const double piece = rng.uniform(0, 8) == 0 ? 0.0 : rng.uniform(2.0, 60.0);
            const Point2d off = normal * rng.uniform(-0.6, 0.6);
            const Point2d a = start + u * t + off, b = start + u * (t + piece) + off;
            const bool reversed = rng.uniform(0, 10) == 0;
            segments.push_back(reversed ? Vec4f((float)b.x, (float)b.y, (float)a.x, (float)a.y)
                                        : Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y));
            if (twin)
                segments.push_back(Vec4f((float)(b.x + 2 * normal.x), (float)(b.y + 2 * normal.y),
                                         (float)(a.x + 2 * normal.x), (float)(a.y + 2 * normal.y)));
            t += piece + rng.uniform(0.0, 6.0);
        }
    }
    for (int c = 0; c < lines * 5; c++)
        segments.push_back(segmentAt(rng.uniform(0.0, extent), rng.uniform(0.0, extent), rng.uniform(0.0, 360.0),
                                     rng.uniform(1.0, 20.0)));
    return segments;
}

typedef testing::TestWithParam<tuple<int, double, double> > LSDAdvance_MergingSweepParams;

TEST_P(LSDAdvance_MergingSweepParams, equals_the_all_pairs_rule)
{
    const int strategy = get<0>(GetParam());
    lsda::MergingParams p;
    p.mergeStrategy = strategy;
    p.proximityRatio = get<1>(GetParam());
    p.mergeThreshold = get<2>(GetParam());
    for (int seed = 1; seed <= 6; seed++)
    {
        SCOPED_TRACE(seed);
        RNG rng(seed);
        const std::vector<Vec4f> segments = fragmentedLines(rng, 40, 500.0);
        lsda::SegmentGroups groups;
        lsda::groupSegments(segments, lsda::GroupingParams(), groups);
        std::vector<Vec4f> merged;
        lsda::mergeGroups(segments, groups, p, merged);
        const std::vector<Vec4f> expected = mergeReference(segments, groups, p);
        ASSERT_EQ(expected.size(), merged.size());
        EXPECT_EQ(expected, merged);
        EXPECT_LT(merged.size(), segments.size());
    }
}

INSTANTIATE_TEST_CASE_P(/**/, LSDAdvance_MergingSweepParams,
                        testing::Combine(testing::Values((int)LSDAdvance::MERGE_LONGEST_FIRST,
                                                         (int)LSDAdvance::MERGE_BASELINES),
                                         testing::Values(0.1, 1.0, 10.0), testing::Values(0.0, 0.6, 0.75)));

TEST(LSDAdvance_MergingSweep, weights_without_proximity_equal_the_all_pairs_rule)
{
    // With proximityWeight 0 the score cannot bound the distance: only Dth can.
    lsda::MergingParams p;
    p.proximityWeight = 0;
    p.mergeThreshold = 0.5;
    RNG rng(11);
    const std::vector<Vec4f> segments = fragmentedLines(rng, 30, 400.0);
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    for (int s : { LSDAdvance::MERGE_LONGEST_FIRST, LSDAdvance::MERGE_BASELINES })
    {
        p.mergeStrategy = s;
        std::vector<Vec4f> merged;
        lsda::mergeGroups(segments, groups, p, merged);
        EXPECT_EQ(mergeReference(segments, groups, p), merged);
    }
}

// MERGE_LONGEST_FIRST compares every pair of a smaller group and files a larger one in the sweep:
// one group of parallel chains 3 px apart (a textured facade), pieces of mixed lengths, a few
// reversed or of zero length, beside twins 2 px away, against the rule.
TEST(LSDAdvance_MergingSweep, a_group_large_enough_for_the_sweep_equals_the_all_pairs_rule)
{
    RNG rng(17);
    std::vector<Vec4f> segments;
    const Point2d u(std::cos(0.5), std::sin(0.5)), normal(-u.y, u.x);
    for (int chain = 0; chain < 16; chain++)
        for (double t = rng.uniform(0.0, 20.0); t < 300.0;)
        {
            const double piece = rng.uniform(0, 8) == 0 ? 0.0 : rng.uniform(2.0, 30.0);
            const Point2d off = normal * (3.0 * chain + rng.uniform(-0.6, 0.6));
            const Point2d a = u * t + off, b = u * (t + piece) + off;
            const bool reversed = rng.uniform(0, 10) == 0;
            segments.push_back(reversed ? Vec4f((float)b.x, (float)b.y, (float)a.x, (float)a.y)
                                        : Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y));
            if (rng.uniform(0, 4) == 0)
                segments.push_back(Vec4f((float)(a.x + 2 * normal.x), (float)(a.y + 2 * normal.y),
                                         (float)(b.x + 2 * normal.x), (float)(b.y + 2 * normal.y)));
            t += piece + rng.uniform(0.0, 6.0);
        }
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    int largest = 0;
    for (int g = 0; g < groups.count(); g++)
        largest = std::max(largest, groups.offsets[g + 1] - groups.offsets[g]);
    ASSERT_GE(largest, lsda::kSweptGroupSize);
    lsda::MergingParams p;
    p.mergeStrategy = LSDAdvance::MERGE_LONGEST_FIRST;
    for (double ratio : { 0.1, 1.0 })
        for (double threshold : { 0.0, 0.6 })
        {
            SCOPED_TRACE(cv::format("proximityRatio %g, mergeThreshold %g", ratio, threshold));
            p.proximityRatio = ratio;
            p.mergeThreshold = threshold;
            std::vector<Vec4f> merged;
            lsda::mergeGroups(segments, groups, p, merged);
            EXPECT_EQ(mergeReference(segments, groups, p), merged);
            EXPECT_LT(merged.size(), segments.size());
        }
}

TEST(LSDAdvance_MergingSweep, one_group_of_thousands_of_collinear_pieces_becomes_one_segment)
{
    // 4000 pieces of one edge, 1 px apart: a single group. Longest first absorbs them one by one;
    // every pair would be 16 million scores per absorption round.
    std::vector<Vec4f> segments;
    RNG rng(3);
    for (double x = 0; segments.size() < 4000;)
    {
        const double piece = rng.uniform(3.0, 12.0);
        segments.push_back(Vec4f((float)x, 50.f, (float)(x + piece), 50.f));
        x += piece + 1.0;
    }
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    ASSERT_EQ(1, groups.count());
    lsda::MergingParams p;
    std::vector<Vec4f> merged;
    lsda::mergeGroups(segments, groups, p, merged);
    ASSERT_EQ(1u, merged.size());
    EXPECT_NEAR(0.0, merged[0][0], 1e-2);
    EXPECT_NEAR(segments.back()[2], merged[0][2], 1e-2);
    EXPECT_NEAR(50.0, merged[0][1], 1e-3);
}

}} // namespace
