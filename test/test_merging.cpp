// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Groups with the default parameters, then merges with the given ones.
std::vector<Vec4f> groupAndMerge(const std::vector<Vec4f>& segments, const lsda::MergingParams& params,
                                 bool neighbourBins = true)
{
    lsda::GroupingParams grouping;
    grouping.angleBinning = neighbourBins ? LSDAdvance::ANGLE_BINS_NEIGHBOURS : LSDAdvance::ANGLE_BINS_STRICT;
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, grouping, groups);
    std::vector<Vec4f> merged;
    lsda::mergeGroups(segments, groups, params, merged);
    return merged;
}

// The scores worked out in these tests use the paper's proximity ratio, 0.1.
lsda::MergingParams paperParams()
{
    lsda::MergingParams p;
    p.mergeStrategy = LSDAdvance::MERGE_BASELINES;
    p.proximityRatio = 0.1;
    return p;
}

lsda::MergingParams longestFirstParams()
{
    lsda::MergingParams p;
    p.mergeStrategy = LSDAdvance::MERGE_LONGEST_FIRST;
    p.proximityRatio = 0.1;
    return p;
}

void expectSegmentNear(const Vec4f& expected, const Vec4f& actual, double tolerance)
{
    for (int i = 0; i < 4; i++)
        EXPECT_NEAR(expected[i], actual[i], tolerance) << "coordinate " << i << " of " << actual;
}

TEST(LSDAdvance_Similarity, distance_is_the_smallest_endpoint_to_segment_distance)
{
    EXPECT_NEAR(5.0, lsda::segmentDistance(Vec4f(0, 0, 100, 0), Vec4f(105, 0, 150, 0)), 1e-9);
    // An endpoint above the middle of the other segment: perpendicular distance.
    EXPECT_NEAR(3.0, lsda::segmentDistance(Vec4f(0, 0, 100, 0), Vec4f(50, 3, 50, 40)), 1e-9);
    EXPECT_NEAR(5.0, lsda::segmentDistance(Vec4f(0, 0, 100, 0), Vec4f(103, 4, 140, 4)), 1e-9);
}

TEST(LSDAdvance_Similarity, perpendicular_offset_is_measured_to_the_supporting_line)
{
    EXPECT_NEAR(2.0, lsda::perpendicularOffset(Vec4f(0, 0, 100, 0), Vec4f(150, 2, 200, 2)), 1e-9);
    EXPECT_NEAR(3.0, lsda::perpendicularOffset(Vec4f(0, 0, 100, 0), Vec4f(150, -1, 200, 3)), 1e-9);
}

TEST(LSDAdvance_Similarity, direction_term_is_the_clipped_directed_cosine)
{
    const Vec4f base(0, 0, 100, 0);
    EXPECT_NEAR(1.0, lsda::similarityTerms(base, segmentAt(110, 0, 0, 50), 0.1).direction, 1e-6);
    EXPECT_NEAR(0.5, lsda::similarityTerms(base, segmentAt(110, 0, 60, 50), 0.1).direction, 1e-6);
    // Opposite polarity (the other side of a thin bar) scores 0, not 1.
    EXPECT_NEAR(0.0, lsda::similarityTerms(base, segmentAt(160, 0, 180, 50), 0.1).direction, 1e-6);
    EXPECT_NEAR(0.0, lsda::similarityTerms(base, segmentAt(110, 0, 120, 50), 0.1).direction, 1e-6);
}

TEST(LSDAdvance_Similarity, proximity_term_falls_linearly_to_zero_at_the_threshold)
{
    const Vec4f base(0, 0, 100, 0);
    // Lengths 100 and 60: Dth = 0.1 * 80 = 8 px.
    EXPECT_NEAR(1.0 - 2.0 / 8.0, lsda::similarityTerms(base, Vec4f(102, 0, 162, 0), 0.1).proximity, 1e-6);
    EXPECT_NEAR(1.0 - 6.0 / 8.0, lsda::similarityTerms(base, Vec4f(106, 0, 166, 0), 0.1).proximity, 1e-6);
    EXPECT_NEAR(0.0, lsda::similarityTerms(base, Vec4f(109, 0, 169, 0), 0.1).proximity, 1e-6);
    // proximityRatio 0.2 doubles Dth.
    EXPECT_NEAR(1.0 - 6.0 / 16.0, lsda::similarityTerms(base, Vec4f(106, 0, 166, 0), 0.2).proximity, 1e-6);
}

TEST(LSDAdvance_Similarity, length_term_is_one_minus_the_relative_difference)
{
    const Vec4f base(0, 0, 100, 0);
    EXPECT_NEAR(0.6, lsda::similarityTerms(base, Vec4f(102, 0, 162, 0), 0.1).length, 1e-6);
    EXPECT_NEAR(1.0, lsda::similarityTerms(base, Vec4f(102, 0, 202, 0), 0.1).length, 1e-6);
    EXPECT_NEAR(0.5, lsda::similarityTerms(Vec4f(102, 0, 152, 0), base, 0.1).length, 1e-6);
}

TEST(LSDAdvance_Similarity, score_weights_the_three_terms)
{
    lsda::MergingParams p;
    const lsda::SimilarityTerms t = { 1.0, 0.5, 0.25 };
    EXPECT_NEAR(0.4 * 1.0 + 0.35 * 0.5 + 0.2 * 0.25, lsda::similarityScore(t, p), 1e-12);
    p.directionWeight = 0.1;
    p.proximityWeight = 0.2;
    p.lengthWeight = 0.7;
    EXPECT_NEAR(0.1 + 0.1 + 0.175, lsda::similarityScore(t, p), 1e-12);
}

TEST(LSDAdvance_Fusion, collinear_pieces_fuse_into_their_span)
{
    const Vec4f fused = lsda::fuseSegments(Vec4f(0, 0, 100, 0), Vec4f(105, 0, 155, 0));
    expectSegmentNear(Vec4f(0, 0, 155, 0), fused, 1e-4);
}

TEST(LSDAdvance_Fusion, line_passes_through_the_length_weighted_centre)
{
    // Base along y = 0 (length 100, centre x 50), piece along y = 0.6 (length 50, centre x 135):
    // the centre (235 / 3, 0.2) is on the fused line, which spans x 0 to 160.
    const Vec4f fused = lsda::fuseSegments(Vec4f(0, 0, 100, 0), Vec4f(110, 0.6f, 160, 0.6f));
    const double t = (235.0 / 3.0 - fused[0]) / (fused[2] - fused[0]);
    EXPECT_NEAR(0.2, fused[1] + t * (fused[3] - fused[1]), 1e-4);
    EXPECT_NEAR(0.0, fused[0], 1e-2);
    EXPECT_NEAR(160.0, fused[2], 1e-2);
}

TEST(LSDAdvance_Fusion, parallel_runs_a_step_apart_fuse_along_the_least_squares_line)
{
    // Two runs of 8 px, the second 1 px below and 8 px on, as on an aliased edge of slope 1/8.
    // Their second moments about the centre (8, 0.5) as uniform masses: xx = 1024 / 3, xy = 32,
    // yy = 4, whose principal axis has the slope tan(atan2(64, 1012 / 3) / 2) = 0.0940; the mean
    // of their directions would be 0.
    const Vec4f fused = lsda::fuseSegments(Vec4f(0, 0, 8, 0), Vec4f(8, 1, 16, 1));
    EXPECT_NEAR(std::tan(0.5 * std::atan2(64.0, 1012.0 / 3.0)), (fused[3] - fused[1]) / (fused[2] - fused[0]), 1e-4);
    EXPECT_NEAR(0.5, 0.5 * (fused[1] + fused[3]), 1e-4);
}

TEST(LSDAdvance_Fusion, keeps_the_baseline_orientation)
{
    // The other piece is reversed; the result points like the baseline (+x).
    const Vec4f fused = lsda::fuseSegments(Vec4f(0, 0, 100, 0), Vec4f(150, 0, 110, 0));
    expectSegmentNear(Vec4f(0, 0, 150, 0), fused, 1e-4);
    const Vec4f reversed = lsda::fuseSegments(Vec4f(100, 0, 0, 0), Vec4f(110, 0, 150, 0));
    expectSegmentNear(Vec4f(150, 0, 0, 0), reversed, 1e-4);
}

TEST(LSDAdvance_Fusion, direction_has_no_0_180_wrap)
{
    // Directed angles 179.5 and 180.5 deg (undirected 179.5 and 0.5): a naive mean of the
    // undirected angles would give 90 deg; the fused line lies between the two.
    const Vec4f base = segmentAt(100, 50, 179.5, 100);
    const Vec4f piece = segmentAt(base[2] - 3, base[3], 180.5, 50);
    const Vec4f fused = lsda::fuseSegments(base, piece);
    double angle = std::atan2(fused[3] - fused[1], fused[2] - fused[0]) * 180.0 / CV_PI;
    angle += angle < 0 ? 360.0 : 0.0;
    EXPECT_GT(angle, 179.5);
    EXPECT_LT(angle, 180.5);
    EXPECT_LT(fused[2], fused[0]);  // still points like the baseline (-x)
}

TEST(LSDAdvance_MergingBaselines, long_edge_broken_into_collinear_pieces_becomes_one_segment)
{
    // Pieces of a line y = 20 + 0.1 x with 3 px gaps; only the longest is a baseline, the
    // others join it one after the other.
    const double angle = std::atan(0.1) * 180.0 / CV_PI;
    const double step = std::cos(std::atan(0.1));
    std::vector<Vec4f> segments;
    const double starts[] = { 0, 203, 300, 357 }, lengths[] = { 200, 94, 54, 117 };
    for (int i = 0; i < 4; i++)
        segments.push_back(segmentAt(starts[i] * step, 20 + 0.1 * starts[i] * step, angle, lengths[i]));
    const std::vector<Vec4f> merged = groupAndMerge(segments, paperParams());
    ASSERT_EQ(1u, merged.size());
    const Vec4f truth(segments[0][0], segments[0][1], segments[3][2], segments[3][3]);
    expectSegmentNear(truth, merged[0], 1.0);
}

TEST(LSDAdvance_MergingLongestFirst, the_runs_of_an_aliased_edge_become_one_segment)
{
    // What the base finds on a line drawn without anti-aliasing at slope 1/8: runs of 6 px along
    // x, each 1 px below the one before (issue 21's rotated rectangles). With the defaults they
    // fuse into one segment of the edge's slope; the mean of their directions kept the runs'
    // direction, 0, so that the third run fell outside the perpendicular gate.
    std::vector<Vec4f> runs;
    for (int k = 0; k < 10; k++)
        runs.push_back(Vec4f(8.f * k + 1, (float)k, 8.f * k + 7, (float)k));
    const std::vector<Vec4f> merged = groupAndMerge(runs, lsda::MergingParams());
    ASSERT_EQ(1u, merged.size());
    EXPECT_NEAR(1.0 / 8.0, (merged[0][3] - merged[0][1]) / (merged[0][2] - merged[0][0]), 0.005);
    EXPECT_NEAR(1.0, std::min(merged[0][0], merged[0][2]), 0.1);
    EXPECT_NEAR(79.0, std::max(merged[0][0], merged[0][2]), 0.1);
}

TEST(LSDAdvance_MergingBaselines, pieces_straddling_a_bin_edge_merge_with_neighbour_bins)
{
    const Vec4f base = segmentAt(0, 0, 9.95, 150);
    const Vec4f piece = segmentAt(base[2] + 2 * std::cos(0.1745), base[3] + 2 * std::sin(0.1745), 10.05, 60);
    EXPECT_EQ(1u, groupAndMerge({ base, piece }, paperParams(), true).size());
    EXPECT_EQ(2u, groupAndMerge({ base, piece }, paperParams(), false).size());
}

TEST(LSDAdvance_MergingBaselines, parallel_edges_2px_apart_stay_two)
{
    // Same polarity, overlapping, 2 px apart: close enough to score, stopped by the gate.
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 200, 0), Vec4f(195, 2, 265, 2) };
    lsda::MergingParams params = paperParams();
    ASSERT_GE(lsda::similarityScore(lsda::similarityTerms(segments[0], segments[1], params.proximityRatio), params),
              params.mergeThreshold);
    EXPECT_EQ(2u, groupAndMerge(segments, params).size());
    params.maxPerpendicularOffset = 2.5;
    EXPECT_EQ(1u, groupAndMerge(segments, params).size());
}

TEST(LSDAdvance_MergingBaselines, baselines_never_merge_with_each_other)
{
    // Two collinear pieces of equal length, 2 px apart: both are baselines.
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 100, 0), Vec4f(102, 0, 202, 0) };
    EXPECT_EQ(2u, groupAndMerge(segments, paperParams()).size());
    // With a piece of 85 px (>= 0.8 * 100) the same holds; with baselineRatio 0.9 it fuses.
    const std::vector<Vec4f> shorter = { Vec4f(0, 0, 100, 0), Vec4f(102, 0, 187, 0) };
    lsda::MergingParams params = paperParams();
    EXPECT_EQ(2u, groupAndMerge(shorter, params).size());
    params.baselineRatio = 0.9;
    EXPECT_EQ(1u, groupAndMerge(shorter, params).size());
}

// A piece of 50 px 3 px beyond a baseline of 100 px: Sd = 1, Sp = 1 - 3 / 7.5 = 0.6 (Dth = 0.1 *
// 75), Sl = 0.5, a score of 0.4 + 0.21 + 0.1 = 0.71 with the paper's weights. It fuses exactly when
// the score with the case's weights, proximity ratio and threshold reaches the threshold.
struct ScoreCase
{
    const char* name;
    double mergeThreshold, directionWeight, proximityWeight, lengthWeight, proximityRatio;
    size_t segments;  //!< after merging: 1 when the piece fuses
};

void PrintTo(const ScoreCase& c, std::ostream* out)
{
    *out << c.name;
}

typedef testing::TestWithParam<ScoreCase> LSDAdvance_MergingScore;

TEST_P(LSDAdvance_MergingScore, a_piece_fuses_when_its_score_reaches_the_threshold)
{
    const ScoreCase& c = GetParam();
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 100, 0), Vec4f(103, 0, 153, 0) };
    lsda::MergingParams params = paperParams();
    params.mergeThreshold = c.mergeThreshold;
    params.directionWeight = c.directionWeight;
    params.proximityWeight = c.proximityWeight;
    params.lengthWeight = c.lengthWeight;
    params.proximityRatio = c.proximityRatio;
    EXPECT_EQ(c.segments, groupAndMerge(segments, params).size());
}

INSTANTIATE_TEST_CASE_P(/**/, LSDAdvance_MergingScore, testing::Values(
    ScoreCase{ "threshold_0_70_below_0_71", 0.70, 0.4, 0.35, 0.2, 0.1, 1 },
    ScoreCase{ "threshold_0_72_above_0_71", 0.72, 0.4, 0.35, 0.2, 0.1, 2 },
    ScoreCase{ "threshold_0_8_above_0_71", 0.8, 0.4, 0.35, 0.2, 0.1, 2 },
    ScoreCase{ "direction_weight_0_8_gives_1_11", 0.8, 0.8, 0.35, 0.2, 0.1, 1 },
    ScoreCase{ "proximity_weight_0_7_gives_0_92", 0.8, 0.4, 0.7, 0.2, 0.1, 1 },
    ScoreCase{ "length_weight_0_6_gives_0_91", 0.8, 0.4, 0.35, 0.6, 0.1, 1 },
    ScoreCase{ "proximity_ratio_1_gives_0_84", 0.8, 0.4, 0.35, 0.2, 1.0, 1 }));

TEST(LSDAdvance_MergingBaselines, best_scores_fuse_first_into_their_best_baseline)
{
    // Two baselines, one piece closer to the second: it fuses there, not into the first.
    const std::vector<Vec4f> segments = {
        Vec4f(0, 0, 100, 0), Vec4f(180, 0.5f, 280, 0.5f), Vec4f(106, 0.25f, 176, 0.25f) };
    const std::vector<Vec4f> merged = groupAndMerge(segments, paperParams());
    ASSERT_EQ(2u, merged.size());
    expectSegmentNear(Vec4f(0, 0, 100, 0), merged[0], 1e-4);
    EXPECT_NEAR(106, merged[1][0], 0.1);
    EXPECT_NEAR(280, merged[1][2], 0.1);
}

TEST(LSDAdvance_MergingBaselines, single_segments_and_zero_length_segments_pass_through)
{
    const std::vector<Vec4f> segments = { Vec4f(5, 5, 5, 5), Vec4f(5, 5, 5, 5), Vec4f(300, 300, 400, 300) };
    const std::vector<Vec4f> merged = groupAndMerge(segments, paperParams());
    ASSERT_EQ(3u, merged.size());
    for (const Vec4f& s : merged)
        for (int i = 0; i < 4; i++)
            EXPECT_TRUE(std::isfinite(s[i]));
}

TEST(LSDAdvance_MergingLongestFirst, equal_collinear_pieces_join)
{
    // The paper's rule keeps these two apart (both are baselines); longest-first joins them.
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 100, 0), Vec4f(102, 0, 202, 0) };
    const std::vector<Vec4f> merged = groupAndMerge(segments, longestFirstParams());
    ASSERT_EQ(1u, merged.size());
    expectSegmentNear(Vec4f(0, 0, 202, 0), merged[0], 1e-3);
}

TEST(LSDAdvance_MergingLongestFirst, chain_of_pieces_joins_from_the_longest)
{
    // Pieces of y = 5 of lengths 60, 40, 80, 30 with 2 px gaps: the 80 px piece absorbs its
    // neighbours one by one, then the ones beyond them.
    const std::vector<Vec4f> segments = {
        Vec4f(0, 5, 60, 5), Vec4f(62, 5, 102, 5), Vec4f(104, 5, 184, 5), Vec4f(186, 5, 216, 5) };
    const std::vector<Vec4f> merged = groupAndMerge(segments, longestFirstParams());
    ASSERT_EQ(1u, merged.size());
    expectSegmentNear(Vec4f(0, 5, 216, 5), merged[0], 1e-3);
}

TEST(LSDAdvance_MergingLongestFirst, keeps_the_gate_the_threshold_and_polarity)
{
    lsda::MergingParams params = longestFirstParams();
    const std::vector<Vec4f> parallel = { Vec4f(0, 0, 200, 0), Vec4f(195, 2, 265, 2) };
    EXPECT_EQ(2u, groupAndMerge(parallel, params).size());
    // Opposite directions: the two sides of a thin bar.
    const std::vector<Vec4f> bar = { Vec4f(0, 0, 100, 0), Vec4f(204, 0.5f, 104, 0.5f) };
    EXPECT_EQ(2u, groupAndMerge(bar, params).size());
    const std::vector<Vec4f> gap = { Vec4f(0, 0, 100, 0), Vec4f(103, 0, 153, 0) };  // score 0.71
    params.mergeThreshold = 0.72;
    EXPECT_EQ(2u, groupAndMerge(gap, params).size());
    params.mergeThreshold = 0.70;
    EXPECT_EQ(1u, groupAndMerge(gap, params).size());
}

TEST(LSDAdvance_MergingLongestFirst, fused_segment_keeps_the_longest_piece_orientation)
{
    const std::vector<Vec4f> segments = { Vec4f(300, 0, 100, 0), Vec4f(95, 0, 45, 0) };
    const std::vector<Vec4f> merged = groupAndMerge(segments, longestFirstParams());
    ASSERT_EQ(1u, merged.size());
    expectSegmentNear(Vec4f(300, 0, 45, 0), merged[0], 1e-3);
}

TEST(LSDAdvance_MergingLongestFirst, pieces_farther_apart_than_Dth_never_fuse)
{
    // Direction and length alone score 0.4 + 0.2 = 0.6: without the distance condition, two
    // equal collinear pieces 45 px apart would fuse. A parallel segment 5 px off chains them
    // into one group.
    lsda::MergingParams params = longestFirstParams();
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 50, 0), Vec4f(95, 0, 145, 0), Vec4f(45, 5, 100, 5) };
    ASSERT_GE(params.directionWeight + params.lengthWeight, params.mergeThreshold);
    const std::vector<Vec4f> merged = groupAndMerge(segments, params);
    EXPECT_EQ(3u, merged.size());
}

TEST(LSDAdvance_Similarity, a_point_has_no_direction)
{
    EXPECT_EQ(0.0, lsda::similarityTerms(Vec4f(0, 0, 100, 0), Vec4f(105, 0, 105, 0), 0.1).direction);
    EXPECT_EQ(0.0, lsda::similarityTerms(Vec4f(5, 5, 5, 5), Vec4f(0, 0, 100, 0), 0.1).direction);
}

// MERGE_NONE is decided by stages 2 and 3 together (MergeStage): no groups, nothing fused.
TEST(LSDAdvance_MergingNone, returns_every_segment_unchanged)
{
    lsda::MergingParams params;
    params.mergeStrategy = LSDAdvance::MERGE_NONE;
    const std::vector<Vec4f> segments = { Vec4f(0, 0, 100, 0), Vec4f(102, 0, 202, 0), Vec4f(204, 0, 230, 0) };
    lsda::MergeStage stage;
    std::vector<Vec4f> merged;
    LSDAdvanceStats stats;
    stage.apply(segments, lsda::GroupingParams(), params, Mat(), merged, stats);
    EXPECT_EQ(segments, merged);
    EXPECT_EQ(std::vector<int>({ 0, 1, 2 }), stage.mergedInto());
    std::vector<int> labels(1, 7);
    stage.labels(labels);
    EXPECT_TRUE(labels.empty());
    EXPECT_EQ(0, stats.mergeGroups);
    EXPECT_EQ(3, stats.mergedSegments);
    params.mergeStrategy = LSDAdvance::MERGE_LONGEST_FIRST;
    stage.apply(segments, lsda::GroupingParams(), params, Mat(), merged, stats);
    EXPECT_EQ(1u, merged.size());
    stage.labels(labels);
    EXPECT_EQ(std::vector<int>({ 0, 0, 0 }), labels);
}

}} // namespace
