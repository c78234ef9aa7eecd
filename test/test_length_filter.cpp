// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Horizontal segments with the given lengths.
std::vector<Vec4f> segmentsOfLengths(const std::vector<double>& lengths)
{
    std::vector<Vec4f> segments;
    for (size_t i = 0; i < lengths.size(); i++)
        segments.push_back(segmentAt(10, 10 + 3.0 * i, 0, lengths[i]));
    return segments;
}

// Mean and population standard deviation, computed independently of the module.
void meanAndStd(const std::vector<double>& v, double& mean, double& stddev)
{
    mean = std::accumulate(v.begin(), v.end(), 0.0) / v.size();
    double ss = 0;
    for (double x : v)
        ss += (x - mean) * (x - mean);
    stddev = std::sqrt(ss / v.size());
}

TEST(LSDAdvance_LengthFilter, minLength_is_std_times_alpha_when_std_below_mean)
{
    const std::vector<double> lengths = { 10, 20, 30, 40 };
    double mean, stddev;
    meanAndStd(lengths, mean, stddev);
    ASSERT_LT(stddev, mean);
    EXPECT_NEAR(lsda::adaptiveMinLength(segmentsOfLengths(lengths), 1.0), stddev, 1e-4);
    EXPECT_NEAR(lsda::adaptiveMinLength(segmentsOfLengths(lengths), 0.85), 0.85 * stddev, 1e-4);
}

TEST(LSDAdvance_LengthFilter, minLength_is_two_mean_minus_std_when_std_above_mean)
{
    const std::vector<double> lengths = { 1, 1, 1, 1, 100 };
    double mean, stddev;
    meanAndStd(lengths, mean, stddev);
    ASSERT_GT(stddev, mean);
    ASSERT_LT(stddev, 2 * mean);
    EXPECT_NEAR(lsda::adaptiveMinLength(segmentsOfLengths(lengths), 1.2), (2 * mean - stddev) * 1.2, 1e-4);
}

TEST(LSDAdvance_LengthFilter, minLength_clamps_to_zero_when_std_above_twice_mean)
{
    std::vector<double> lengths(9, 1.0);
    lengths.push_back(1000);
    double mean, stddev;
    meanAndStd(lengths, mean, stddev);
    ASSERT_GT(stddev, 2 * mean);
    EXPECT_EQ(0.0, lsda::adaptiveMinLength(segmentsOfLengths(lengths), 1.0));
}

TEST(LSDAdvance_LengthFilter, capped_minLength_is_the_paper_value_up_to_std_equal_mean_then_mean)
{
    const std::vector<double> narrow = { 10, 20, 30, 40 };
    double mean, stddev;
    meanAndStd(narrow, mean, stddev);
    EXPECT_NEAR(lsda::adaptiveMinLength(segmentsOfLengths(narrow), 0.9),
                lsda::adaptiveMinLength(segmentsOfLengths(narrow), 0.9, LSDAdvance::LENGTH_THRESHOLD_CAPPED), 1e-9);
    // A few long segments among many short ones: std > 2 mean, the paper's threshold is 0.
    std::vector<double> heavy(9, 1.0);
    heavy.push_back(1000);
    meanAndStd(heavy, mean, stddev);
    ASSERT_GT(stddev, 2 * mean);
    EXPECT_NEAR(1.1 * mean, lsda::adaptiveMinLength(segmentsOfLengths(heavy), 1.1, LSDAdvance::LENGTH_THRESHOLD_CAPPED), 1e-3);
    EXPECT_EQ(0.0, lsda::adaptiveMinLength(std::vector<Vec4f>(), 1.0, LSDAdvance::LENGTH_THRESHOLD_CAPPED));
}

TEST(LSDAdvance_LengthFilter, minLength_is_zero_without_segments)
{
    EXPECT_EQ(0.0, lsda::adaptiveMinLength(std::vector<Vec4f>(), 1.0));
}

TEST(LSDAdvance_LengthFilter, minLength_is_zero_for_zero_length_segments)
{
    const std::vector<Vec4f> points(5, Vec4f(3, 4, 3, 4));
    EXPECT_EQ(0.0, lsda::adaptiveMinLength(points, 1.0));
    std::vector<Vec4f> kept;
    lsda::keepLongOrStrong(points, std::vector<float>(), 0.0, 0.0, kept);
    EXPECT_EQ(points.size(), kept.size());
}

TEST(LSDAdvance_LengthFilter, drops_only_segments_shorter_than_minLength_and_keeps_order)
{
    const std::vector<Vec4f> segments = segmentsOfLengths({ 5, 30, 12, 12.5, 40 });
    std::vector<Vec4f> kept;
    lsda::keepLongOrStrong(segments, std::vector<float>(), 12.0, 0.0, kept);
    ASSERT_EQ(4u, kept.size());
    EXPECT_EQ(segments[1], kept[0]);
    EXPECT_EQ(segments[2], kept[1]);  // exactly minLength is kept
    EXPECT_EQ(segments[3], kept[2]);
    EXPECT_EQ(segments[4], kept[3]);
}

TEST(LSDAdvance_InterFrameAlpha, is_one_inside_the_dead_band_including_its_edges)
{
    EXPECT_EQ(1.0, lsda::interFrameAlpha(100, 100));
    EXPECT_EQ(1.0, lsda::interFrameAlpha(90, 100));   // r = -0.1
    EXPECT_EQ(1.0, lsda::interFrameAlpha(110, 100));  // r = +0.1
}

TEST(LSDAdvance_InterFrameAlpha, falls_below_one_just_under_minus_ten_percent)
{
    // r = -0.11: alpha = 1 - 0.2 * 0.89; the rule jumps at r = -0.1 as the paper prints it.
    EXPECT_NEAR(1.0 - 0.2 * 0.89, lsda::interFrameAlpha(89, 100), 1e-12);
    // r = -1 (no segment kept last frame): 1 - 0.2 * 0 = 1.
    EXPECT_NEAR(1.0, lsda::interFrameAlpha(0, 100), 1e-12);
    EXPECT_NEAR(1.0 - 0.2 * 0.5, lsda::interFrameAlpha(50, 100), 1e-12);
}

TEST(LSDAdvance_InterFrameAlpha, grows_above_ten_percent_and_is_capped)
{
    EXPECT_NEAR(1.0 + 0.1 * (0.5 - 0.1), lsda::interFrameAlpha(150, 100), 1e-12);
    EXPECT_NEAR(1.2, lsda::interFrameAlpha(1000, 100), 1e-12);   // r = 9
    EXPECT_NEAR(1.2, lsda::interFrameAlpha(310, 100), 1e-12);    // r = 2.1, the cap's edge
    EXPECT_LT(lsda::interFrameAlpha(300, 100), 1.2);             // r = 2.0
}

TEST(LSDAdvance_InterFrameAlpha, is_one_when_the_older_count_is_zero)
{
    EXPECT_EQ(1.0, lsda::interFrameAlpha(0, 0));
    EXPECT_EQ(1.0, lsda::interFrameAlpha(500, 0));
}

TEST(LSDAdvance_InterFrameAlpha, stays_in_its_documented_range_for_all_ratios)
{
    for (int previous = 0; previous <= 400; previous += 7)
    {
        SCOPED_TRACE(previous);
        const double alpha = lsda::interFrameAlpha(previous, 100);
        EXPECT_GT(alpha, 0.0);
        EXPECT_LE(alpha, 1.2);
    }
}

TEST(LSDAdvance_InterFrameAlpha, continuous_rule_has_no_jump_at_minus_ten_percent)
{
    EXPECT_EQ(1.0, lsda::continuousInterFrameAlpha(90, 100));
    EXPECT_NEAR(1.0 - 0.2 * 0.01, lsda::continuousInterFrameAlpha(89, 100), 1e-12);
    EXPECT_NEAR(1.0 - 0.2 * 0.4, lsda::continuousInterFrameAlpha(50, 100), 1e-12);
    EXPECT_NEAR(0.82, lsda::continuousInterFrameAlpha(0, 100), 1e-12);
    EXPECT_EQ(lsda::interFrameAlpha(150, 100), lsda::continuousInterFrameAlpha(150, 100));
    EXPECT_EQ(1.0, lsda::continuousInterFrameAlpha(7, 0));
    for (int previous = 0; previous <= 400; previous++)
    {
        SCOPED_TRACE(previous);
        EXPECT_LE(lsda::continuousInterFrameAlpha(previous, 100), lsda::continuousInterFrameAlpha(previous + 1, 100));
    }
}

TEST(LSDAdvance_InterFrameAlpha, count_tracking_opposes_the_frame_own_deviation)
{
    // Recent mean 100: 120 provisional -> r = 0.2 -> 1.1; 90 -> 0.95; far off -> clamped.
    EXPECT_NEAR(1.1, lsda::countTrackingAlpha(120, 110, 90), 1e-12);
    EXPECT_NEAR(0.95, lsda::countTrackingAlpha(90, 100, 100), 1e-12);
    EXPECT_NEAR(1.2, lsda::countTrackingAlpha(500, 100, 100), 1e-12);
    EXPECT_NEAR(0.8, lsda::countTrackingAlpha(0, 100, 100), 1e-12);
    EXPECT_EQ(1.0, lsda::countTrackingAlpha(100, 100, 100));
    EXPECT_EQ(1.0, lsda::countTrackingAlpha(50, 0, 0));
}

TEST(LSDAdvance_LengthFilter, keeps_long_or_strong_segments_in_order_and_the_response_threshold_follows_the_rule)
{
    const std::vector<Vec4f> segments = segmentsOfLengths({ 5, 30, 8, 12, 50 });
    const std::vector<float> responses = { 0.5f, 0.0625f, 0.125f, 0.25f, 0.0f };
    std::vector<Vec4f> kept;
    lsda::keepLongOrStrong(segments, responses, 20.0, 0.25, kept);
    // 5 px strong, 30 px long, 12 px strong (at the threshold), 50 px long; 8 px neither.
    const std::vector<Vec4f> expected = { segments[0], segments[1], segments[3], segments[4] };
    EXPECT_EQ(expected, kept);
    EXPECT_EQ(4, lsda::countLongOrStrong(segments, responses, 20.0, 0.25));
    // Without responses it is the length filter.
    lsda::keepLongOrStrong(segments, std::vector<float>(), 20.0, 0.01, kept);
    const std::vector<Vec4f> longOnes = { segments[1], segments[4] };
    EXPECT_EQ(longOnes, kept);
    EXPECT_EQ(2, lsda::countLongOrStrong(segments, std::vector<float>(), 20.0, 0.01));
    EXPECT_THROW(lsda::keepLongOrStrong(segments, std::vector<float>(2, 1.f), 20.0, 0.01, kept), cv::Exception);

    // The thresholds of both rules, on responses as on lengths.
    const std::vector<double> values = { 0.5, 0.0625, 0.125, 0.25, 0.0 };
    double mean, stddev;
    meanAndStd(values, mean, stddev);
    EXPECT_NEAR(0.9 * std::min(mean, stddev), lsda::adaptiveMinResponse(responses, 0.9, LSDAdvance::LENGTH_THRESHOLD_CAPPED), 1e-8);
    EXPECT_NEAR(std::max(0.0, (1 - std::abs(mean - stddev) / mean) * mean),
                lsda::adaptiveMinResponse(responses, 1.0, LSDAdvance::LENGTH_THRESHOLD_PAPER), 1e-8);
    EXPECT_EQ(0.0, lsda::adaptiveMinResponse(std::vector<float>(), 1.0, LSDAdvance::LENGTH_THRESHOLD_CAPPED));
}

TEST(LSDAdvance_LengthFilter, decides_as_segmentLength_does_at_an_ulp_from_the_threshold)
{
    // Most segments are decided from their squared length; at their length, and an ulp or a hair
    // either side of it, the decision is still segmentLength() >= minLength.
    RNG rng(5);
    for (int k = 0; k < 2000; k++)
    {
        const std::vector<Vec4f> segment = { Vec4f(rng.uniform(-50.f, 700.f), rng.uniform(-50.f, 500.f),
                                                   rng.uniform(-50.f, 700.f), rng.uniform(-50.f, 500.f)) };
        const double length = lsda::segmentLength(segment[0]);
        for (const double minLength : { length, std::nextafter(length, 0.0), std::nextafter(length, 1e9),
                                        length * (1 - 1e-12), length * (1 + 1e-12) })
        {
            SCOPED_TRACE(cv::format("segment %d, length %.17g, minLength %.17g", k, length, minLength));
            EXPECT_EQ(length >= minLength ? 1 : 0, lsda::countLongOrStrong(segment, std::vector<float>(), minLength, 0.0));
        }
    }
}

TEST(LSDAdvance_LengthFilter, without_responses_counts_segments_not_shorter_than_the_length)
{
    EXPECT_EQ(3, lsda::countLongOrStrong(segmentsOfLengths({ 5, 12, 12.5, 40 }), std::vector<float>(), 12.0, 0.0));
    EXPECT_EQ(0, lsda::countLongOrStrong(std::vector<Vec4f>(), std::vector<float>(), 1.0, 0.0));
}

}} // namespace
