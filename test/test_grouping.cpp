// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Group index of every segment.
std::vector<int> groupIds(const std::vector<Vec4f>& segments, const lsda::GroupingParams& params)
{
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, params, groups);
    std::vector<int> id(segments.size(), -1);
    for (int g = 0; g < groups.count(); g++)
        for (int k = groups.offsets[g]; k < groups.offsets[g + 1]; k++)
            id[groups.members[k]] = g;
    return id;
}

lsda::GroupingParams groupingParams(bool neighbourBins, double endpointDistance = lsda::GroupingParams().endpointDistance)
{
    lsda::GroupingParams p;
    p.angleBinning = neighbourBins ? LSDAdvance::ANGLE_BINS_NEIGHBOURS : LSDAdvance::ANGLE_BINS_STRICT;
    p.endpointDistance = endpointDistance;
    return p;
}

TEST(LSDAdvance_Grouping, angleBin_is_undirected_and_cut_every_binWidth_degrees)
{
    EXPECT_EQ(0, lsda::angleBin(segmentAt(0, 0, 0.0, 50), 10));
    EXPECT_EQ(0, lsda::angleBin(segmentAt(0, 0, 9.9, 50), 10));
    EXPECT_EQ(1, lsda::angleBin(segmentAt(0, 0, 10.1, 50), 10));
    EXPECT_EQ(17, lsda::angleBin(segmentAt(0, 0, 179.9, 50), 10));
    EXPECT_EQ(0, lsda::angleBin(segmentAt(0, 0, 180.1, 50), 10));    // 0.1 deg undirected
    EXPECT_EQ(4, lsda::angleBin(segmentAt(0, 0, 45 + 180, 50), 10)); // reversed segment
    EXPECT_EQ(1, lsda::angleBin(segmentAt(0, 0, 100, 50), 90));
    EXPECT_EQ(2, lsda::angleBin(segmentAt(0, 0, 170, 50), 70));      // last, narrower bin
}

TEST(LSDAdvance_Grouping, endpoints_closer_than_the_distance_connect)
{
    const std::vector<Vec4f> segments = {
        segmentAt(0, 0, 0, 50),
        segmentAt(59, 0, 0, 50),    // 9 px gap: adjacent
        segmentAt(120, 0, 0, 50),   // 11 px gap from the previous one: not adjacent
    };
    const std::vector<int> id = groupIds(segments, groupingParams(true, 10.0));
    EXPECT_EQ(id[0], id[1]);
    EXPECT_NE(id[1], id[2]);
    const std::vector<int> wide = groupIds(segments, groupingParams(true, 12.0));
    EXPECT_EQ(wide[0], wide[2]);
}

// Endpoints spread far beyond an image take the hashed grid instead of the dense one: the same rule.
TEST(LSDAdvance_Grouping, endpoints_spread_far_apart_connect_by_the_same_rule)
{
    const std::vector<Vec4f> segments = {
        segmentAt(-9e6, -9e6, 0, 50),
        segmentAt(-9e6 + 59, -9e6, 0, 50),  // 9 px gap: adjacent
        segmentAt(9e6, 9e6, 0, 50),
        segmentAt(9e6 + 61, 9e6, 0, 50),    // 11 px gap: not adjacent
        segmentAt(9e6 - 8, 9e6 + 3, 0, 5),  // its end 3 px under the start of segment 2
    };
    const std::vector<int> id = groupIds(segments, groupingParams(true, 10.0));
    EXPECT_EQ(id[0], id[1]);
    EXPECT_NE(id[1], id[2]);
    EXPECT_NE(id[2], id[3]);
    EXPECT_EQ(id[2], id[4]);
}

TEST(LSDAdvance_Grouping, groups_are_connected_components)
{
    // a-b and b-c are adjacent, a-c are not: all three form one group.
    const std::vector<Vec4f> segments = {
        segmentAt(0, 0, 0, 50), segmentAt(55, 0, 0, 50), segmentAt(110, 0, 0, 50),
        segmentAt(0, 100, 0, 50),
    };
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, groupingParams(true), groups);
    ASSERT_EQ(2, groups.count());
    EXPECT_EQ(std::vector<int>({ 0, 1, 2, 3 }), groups.members);
    EXPECT_EQ(std::vector<int>({ 0, 3, 4 }), groups.offsets);
}

TEST(LSDAdvance_Grouping, different_angle_bins_do_not_connect)
{
    // A corner: two segments meet at their endpoints but are 90 deg apart.
    const std::vector<Vec4f> segments = { segmentAt(0, 0, 0, 50), segmentAt(50, 0, 90, 50) };
    const std::vector<int> id = groupIds(segments, groupingParams(true));
    EXPECT_NE(id[0], id[1]);
}

TEST(LSDAdvance_Grouping, pieces_straddling_a_bin_edge_connect_only_with_neighbour_bins)
{
    const Vec4f a = segmentAt(0, 0, 9.9, 60);
    const Vec4f b = segmentAt(a[2] + 2, a[3], 10.1, 60);
    const std::vector<Vec4f> segments = { a, b };
    ASSERT_NE(lsda::angleBin(a, 10), lsda::angleBin(b, 10));
    const std::vector<int> neighbours = groupIds(segments, groupingParams(true));
    EXPECT_EQ(neighbours[0], neighbours[1]);
    const std::vector<int> strict = groupIds(segments, groupingParams(false));
    EXPECT_NE(strict[0], strict[1]);
}

TEST(LSDAdvance_Grouping, pieces_straddling_the_0_180_wrap_connect_with_neighbour_bins)
{
    const Vec4f a = segmentAt(0, 50, 179.9, 60);   // pointing left, bin 17
    const Vec4f b = segmentAt(a[2] - 2, a[3], 180.1, 60);  // undirected 0.1 deg, bin 0
    ASSERT_EQ(17, lsda::angleBin(a, 10));
    ASSERT_EQ(0, lsda::angleBin(b, 10));
    const std::vector<int> neighbours = groupIds({ a, b }, groupingParams(true));
    EXPECT_EQ(neighbours[0], neighbours[1]);
    const std::vector<int> strict = groupIds({ a, b }, groupingParams(false));
    EXPECT_NE(strict[0], strict[1]);
}

// A label per segment by the rule over all pairs, equal for two segments when they are in one
// group: connected components by repeated relabelling.
std::vector<int> allPairsLabels(const std::vector<Vec4f>& segments, const lsda::GroupingParams& params)
{
    const int n = (int)segments.size();
    const int bins = (int)std::ceil(180.0 / params.angleBinWidth - 1e-9);
    std::vector<int> label(n), bin(n);
    for (int i = 0; i < n; i++)
    {
        label[i] = i;
        bin[i] = lsda::angleBin(segments[i], params.angleBinWidth);
    }
    for (bool changed = true; changed;)
    {
        changed = false;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
            {
                const int d = std::abs(bin[i] - bin[j]);
                if (i == j || !(d == 0 || (params.angleBinning == LSDAdvance::ANGLE_BINS_NEIGHBOURS && (d == 1 || d == bins - 1))))
                    continue;
                double best = DBL_MAX;
                for (int ei = 0; ei < 2; ei++)
                    for (int ej = 0; ej < 2; ej++)
                        best = std::min(best, (double)std::hypot(segments[i][2 * ei] - segments[j][2 * ej],
                                                         segments[i][2 * ei + 1] - segments[j][2 * ej + 1]));
                if (best < params.endpointDistance && label[j] != std::min(label[i], label[j]))
                {
                    label[j] = label[i] = std::min(label[i], label[j]);
                    changed = true;
                }
            }
    }
    return label;
}

TEST(LSDAdvance_Grouping, matches_an_all_pairs_reference_on_random_segments)
{
    RNG rng(20260521);
    for (int trial = 0; trial < 20; trial++)
    {
        SCOPED_TRACE(trial);
        std::vector<Vec4f> segments;
        for (int i = 0; i < 300; i++)
            segments.push_back(segmentAt(rng.uniform(0., 300.), rng.uniform(0., 300.),
                                         rng.uniform(0., 360.), rng.uniform(0., 40.)));
        lsda::GroupingParams params = groupingParams(trial % 2 == 0, rng.uniform(2., 20.));
        params.angleBinWidth = rng.uniform(5., 30.);

        const int n = (int)segments.size();
        const std::vector<int> label = allPairsLabels(segments, params);
        const std::vector<int> id = groupIds(segments, params);
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++)
                ASSERT_EQ(label[i] == label[j], id[i] == id[j]) << "segments " << i << ", " << j;
    }
}

// Endpoints are filed by angle bin and cell, each pair of neighbouring bins compared from one side
// (two bins are each other's neighbours on both sides, three all pair), in a dense grid or in a
// hash of the cells when the endpoints are spread far apart: every way against the rule.
TEST(LSDAdvance_Grouping, matches_the_all_pairs_reference_at_any_bin_count_dense_or_hashed)
{
    RNG rng(20260602);
    for (double binWidth : { 90.0, 60.0, 45.0, 7.0, 1.0 })
        for (bool neighbourBins : { true, false })
            for (bool spread : { false, true })
            {
                SCOPED_TRACE(cv::format("bin width %g, %s bins, %s", binWidth, neighbourBins ? "neighbour" : "strict",
                                        spread ? "spread" : "dense"));
                // Clusters of segments, around the origin or 2e6 px apart (spread: the hashed cells).
                std::vector<Vec4f> segments;
                for (int cluster = 0; cluster < 4; cluster++)
                {
                    const double cx = spread ? (cluster - 1.5) * 2e6 : 0.0, cy = spread ? (cluster % 2) * 2e6 : 0.0;
                    for (int i = 0; i < 60; i++)
                        segments.push_back(segmentAt(cx + rng.uniform(0., 120.), cy + rng.uniform(0., 120.),
                                                     rng.uniform(0., 360.), rng.uniform(0., 30.)));
                }
                lsda::GroupingParams params = groupingParams(neighbourBins, 12.0);
                params.angleBinWidth = binWidth;
                const std::vector<int> label = allPairsLabels(segments, params);
                const std::vector<int> id = groupIds(segments, params);
                for (size_t i = 0; i < segments.size(); i++)
                    for (size_t j = i + 1; j < segments.size(); j++)
                        ASSERT_EQ(label[i] == label[j], id[i] == id[j]) << "segments " << i << ", " << j;
            }
}

// angleBins() places a direction without atan2 only when it is clearly inside a bin: on and
// around every edge, on the axes and diagonals, reversed, and for points, it gives angleBin().
TEST(LSDAdvance_Grouping, angleBins_equal_angleBin_on_and_around_every_edge)
{
    RNG rng(5);
    std::vector<Point2d> edges;
    std::vector<int> bins;
    for (double binWidth : { 1.0, 4.5, 7.0, 10.0, 15.0, 45.0, 60.0, 70.0, 90.0 })
    {
        SCOPED_TRACE(binWidth);
        std::vector<Vec4f> segments;
        for (int k = 0; k * binWidth <= 360.0; k++)
            for (double offset : { 0.0, 1e-12, -1e-12, 1e-7, -1e-7, 1e-3, -1e-3 })
                for (double length : { 0.01, 1.0, 37.0, 1000.0 })
                    segments.push_back(segmentAt(rng.uniform(-500., 500.), rng.uniform(-500., 500.),
                                                 k * binWidth + offset, length));
        for (float d : { 1.f, 1e-3f, 1e3f })
            for (int dx = -1; dx <= 1; dx++)
                for (int dy = -1; dy <= 1; dy++)
                    segments.push_back(Vec4f(5, 7, 5 + dx * d, 7 + dy * d));  // axes, diagonals, a point
        for (int i = 0; i < 2000; i++)
            segments.push_back(segmentAt(rng.uniform(-500., 500.), rng.uniform(-500., 500.), rng.uniform(0., 360.),
                                         rng.uniform(0., 100.)));
        lsda::angleBins(segments, binWidth, bins, edges);
        ASSERT_EQ(segments.size(), bins.size());
        for (size_t i = 0; i < segments.size(); i++)
            ASSERT_EQ(lsda::angleBin(segments[i], binWidth), bins[i]) << segments[i];
    }
}

TEST(LSDAdvance_Grouping, every_segment_is_in_exactly_one_group)
{
    RNG rng(7);
    std::vector<Vec4f> segments;
    for (int i = 0; i < 1000; i++)
        segments.push_back(segmentAt(rng.uniform(0., 640.), rng.uniform(0., 480.),
                                     rng.uniform(0., 360.), rng.uniform(0., 60.)));
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, groupingParams(true), groups);
    std::vector<int> members = groups.members;
    std::sort(members.begin(), members.end());
    for (int i = 0; i < (int)segments.size(); i++)
        ASSERT_EQ(i, members[i]);
    ASSERT_EQ((int)segments.size(), groups.offsets.back());
    for (int g = 0; g < groups.count(); g++)
        ASSERT_LT(groups.offsets[g], groups.offsets[g + 1]);
}

TEST(LSDAdvance_Grouping, no_segments_give_no_groups)
{
    lsda::SegmentGroups groups;
    lsda::groupSegments(std::vector<Vec4f>(), groupingParams(true), groups);
    EXPECT_EQ(0, groups.count());
    EXPECT_TRUE(groups.members.empty());
}

}} // namespace
