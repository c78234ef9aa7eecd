// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stages 1-3 alone on seeded synthetic segment sets of 1k to 100k segments, to show how the cost
// of each stage grows with the number of segments (doc/performance.md).

#include "perf_precomp.hpp"
#include "../src/segment_merging.hpp"

namespace opencv_test { namespace {

using namespace cv::ximgproc;

// A recorded frame of n segments at the density of a YorkUrban frame (about 900 segments on
// 640x480, one per 340 px^2): 60 % are pieces of straight edges (4-40 px, 0-5 px apart, 0.5 px
// of jitter; a third of the edges have an opposite-polarity twin 2 px beside them, like the two
// sides of a thin bar), 40 % short clutter at random angles.
std::vector<Vec4f> recordedSegments(int n)
{
    RNG rng(n);
    const double side = std::sqrt(340.0 * n);
    std::vector<Vec4f> segments;
    segments.reserve(n);
    const int pieces = n * 6 / 10;
    while ((int)segments.size() < pieces)
    {
        const Point2d start(rng.uniform(0.0, side), rng.uniform(0.0, side));
        const double angle = rng.uniform(0.0, 2 * CV_PI);
        const Point2d u(std::cos(angle), std::sin(angle)), normal(-u.y, u.x);
        const double edge = rng.uniform(40.0, 400.0);
        const bool twin = rng.uniform(0, 3) == 0;
        for (double t = 0; t < edge && (int)segments.size() < pieces;)
        {
            const double piece = rng.uniform(4.0, 40.0);
            const Point2d off = normal * rng.uniform(-0.5, 0.5);
            const Point2d a = start + u * t + off, b = start + u * (t + piece) + off;
            segments.push_back(Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y));
            if (twin && (int)segments.size() < pieces)
            {
                const Point2d shift = normal * 2.0;
                segments.push_back(Vec4f((float)(b.x + shift.x), (float)(b.y + shift.y),
                                         (float)(a.x + shift.x), (float)(a.y + shift.y)));
            }
            t += piece + rng.uniform(0.0, 5.0);
        }
    }
    while ((int)segments.size() < n)
    {
        const Point2d a(rng.uniform(0.0, side), rng.uniform(0.0, side));
        const double angle = rng.uniform(0.0, 2 * CV_PI), length = rng.uniform(2.0, 30.0);
        segments.push_back(Vec4f((float)a.x, (float)a.y, (float)(a.x + length * std::cos(angle)),
                                 (float)(a.y + length * std::sin(angle))));
    }
    return segments;
}

// One edge broken into n collinear pieces 1 px apart: a single merge group of n segments.
std::vector<Vec4f> oneEdgeInPieces(int n)
{
    RNG rng(n);
    std::vector<Vec4f> segments;
    double x = 0;
    for (int i = 0; i < n; i++)
    {
        const double piece = rng.uniform(3.0, 12.0);
        const float y = (float)(50 + rng.uniform(-0.3, 0.3));
        segments.push_back(Vec4f((float)x, y, (float)(x + piece), y));
        x += piece + 1.0;
    }
    return segments;
}

enum Strategy { LONGEST_FIRST, BASELINES };
CV_ENUM(StrategyType, LONGEST_FIRST, BASELINES)

lsda::MergingParams mergeParams(int strategy)
{
    lsda::MergingParams p;
    p.mergeStrategy = strategy == BASELINES ? LSDAdvance::MERGE_BASELINES : LSDAdvance::MERGE_LONGEST_FIRST;
    return p;
}

#define SEGMENT_COUNTS testing::Values(1000, 5000, 20000, 100000)

typedef perf::TestBaseWithParam<int> Stage_Segments;

PERF_TEST_P(Stage_Segments, lengthFilter, SEGMENT_COUNTS)
{
    const std::vector<Vec4f> segments = recordedSegments(GetParam());
    std::vector<Vec4f> kept;
    TEST_CYCLE()
    {
        const double minLength = lsda::adaptiveMinLength(segments, 1.0, LSDAdvance::LENGTH_THRESHOLD_CAPPED);
        lsda::keepLongOrStrong(segments, std::vector<float>(), minLength, 0.0, kept);
    }
    EXPECT_LT(kept.size(), segments.size());
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Stage_Segments, grouping, SEGMENT_COUNTS)
{
    const std::vector<Vec4f> segments = recordedSegments(GetParam());
    lsda::SegmentGroups groups;
    lsda::GroupingWorkspace workspace;
    TEST_CYCLE() lsda::groupSegments(segments, lsda::GroupingParams(), groups, workspace);
    EXPECT_LT(groups.count(), (int)segments.size());
    SANITY_CHECK_NOTHING();
}

typedef perf::TestBaseWithParam<tuple<int, StrategyType> > Stage_Segments_Strategy;

PERF_TEST_P(Stage_Segments_Strategy, merging, testing::Combine(SEGMENT_COUNTS, StrategyType::all()))
{
    const std::vector<Vec4f> segments = recordedSegments(get<0>(GetParam()));
    const lsda::MergingParams params = mergeParams(get<1>(GetParam()));
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    std::vector<Vec4f> merged;
    lsda::MergeWorkspace workspace;
    std::vector<int> mergedInto;
    TEST_CYCLE() lsda::mergeGroups(segments, groups, params, merged, mergedInto, workspace);
    EXPECT_LT(merged.size(), segments.size());
    SANITY_CHECK_NOTHING();
}

// Stages 1-3 as LSDAdvance runs them (defaults: grouping, merging, then the length filter).
PERF_TEST_P(Stage_Segments, allStages, SEGMENT_COUNTS)
{
    const std::vector<Vec4f> segments = recordedSegments(GetParam());
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines;
    TEST_CYCLE() detector->processSegments(segments, lines);
    EXPECT_LT(lines.size(), segments.size());
    SANITY_CHECK_NOTHING();
}

// The worst case of a group: thousands of connected collinear pieces.
PERF_TEST_P(Stage_Segments_Strategy, mergingOneGroup,
            testing::Combine(testing::Values(1000, 5000, 20000), StrategyType::all()))
{
    const std::vector<Vec4f> segments = oneEdgeInPieces(get<0>(GetParam()));
    const lsda::MergingParams params = mergeParams(get<1>(GetParam()));
    lsda::SegmentGroups groups;
    lsda::groupSegments(segments, lsda::GroupingParams(), groups);
    ASSERT_EQ(1, groups.count());
    std::vector<Vec4f> merged;
    lsda::MergeWorkspace workspace;
    std::vector<int> mergedInto;
    TEST_CYCLE() lsda::mergeGroups(segments, groups, params, merged, mergedInto, workspace);
    EXPECT_LT(merged.size(), segments.size());
    SANITY_CHECK_NOTHING();
}

}} // namespace
