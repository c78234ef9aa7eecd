// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "opencv2/core/utils/filesystem.hpp"

#include <cstdio>
#include <fstream>

namespace opencv_test { namespace {

// Most structural cases use the ground truth g = (0, 0) -> (100, 0) and offset 0, so that the
// numbers are read directly in g's frame; the offset itself is tested separately.
const Vec4f kG(0, 0, 100, 0);

StructuralMatchParams noOffset()
{
    StructuralMatchParams p;
    p.offset = 0;
    return p;
}

StructuralScore scoreOf(const std::vector<Vec4f>& detections, const std::vector<Vec4f>& groundTruth,
                        const StructuralMatchParams& params = noOffset())
{
    return evaluateStructural(detections, groundTruth, params);
}

StructuralScore scoreOf(const Vec4f& detection, const Vec4f& groundTruth,
                        const StructuralMatchParams& params = noOffset())
{
    return scoreOf(std::vector<Vec4f>(1, detection), std::vector<Vec4f>(1, groundTruth), params);
}

// A segment in the data set's continuous coordinates expressed in OpenCV's pixel-centre
// convention: the default offset (+0.5) brings it back exactly onto s.
Vec4f toPixelCentres(const Vec4f& s)
{
    return s - Vec4f::all(0.5f);
}

// A segment of the given length centred on (cx, cy) with the given directed angle (degrees).
Vec4f centredAt(double cx, double cy, double angleDeg, double length)
{
    const double a = angleDeg * CV_PI / 180.0, h = 0.5 * length;
    return Vec4f((float)(cx - h * std::cos(a)), (float)(cy - h * std::sin(a)),
                 (float)(cx + h * std::cos(a)), (float)(cy + h * std::sin(a)));
}

void expectScore(const StructuralScore& s, double precision, double recall, int found, double tolerance = 1e-5)
{
    EXPECT_NEAR(precision, s.precision, tolerance);
    EXPECT_NEAR(recall, s.recall, tolerance);
    EXPECT_EQ(found, s.found);
}

void writeText(const String& path, const std::string& text)
{
    std::ofstream out(path.c_str(), std::ios::binary);
    ASSERT_TRUE(out.good()) << path;
    out << text;
}

// A fresh folder under the temporary directory, removed with its content at scope exit.
struct TempFolder
{
    String path;
    TempFolder() : path(cv::tempfile("_lsda_eval"))
    {
        CV_Assert(!path.empty());
        CV_Assert(cv::utils::fs::createDirectories(path));
    }
    ~TempFolder()
    {
        try { cv::utils::fs::remove_all(path); }
        catch (...) {}
    }
    String operator/(const String& name) const { return cv::utils::fs::join(path, name); }
};

// ---------------------------------------------------------------- structural protocol

TEST(LSDAdvance_Evaluation, exact_hit_has_precision_and_recall_one_with_and_without_offset)
{
    // Offset 0: the detection is g itself.
    StructuralScore s = scoreOf(kG, kG);
    expectScore(s, 1.0, 1.0, 1);
    EXPECT_EQ(1, s.groundTruthCount);
    EXPECT_NEAR(100.0, s.detectedLength, 1e-9);
    EXPECT_NEAR(100.0, s.matchedLength, 1e-9);
    EXPECT_NEAR(100.0, s.coveredLength, 1e-9);
    EXPECT_NEAR(100.0, s.groundTruthLength, 1e-9);

    // Default offset 0.5: a detection 0.5 px up-left in pixel-centre coordinates lands on g.
    const Vec4f g(10.5f, 20.5f, 110.5f, 20.5f);
    s = scoreOf(toPixelCentres(g), g, StructuralMatchParams());
    expectScore(s, 1.0, 1.0, 1);
    EXPECT_NEAR(100.0, s.matchedLength, 1e-9);
}

TEST(LSDAdvance_Evaluation, candidate_centre_must_be_within_max_distance_of_the_line)
{
    // Parallel to g, 1.1 px away: not a candidate (1.1 > 1).
    expectScore(scoreOf(Vec4f(0, 1.1f, 100, 1.1f), kG), 0.0, 0.0, 0);
    expectScore(scoreOf(Vec4f(0, -1.1f, 100, -1.1f), kG), 0.0, 0.0, 0);
    // 0.9 px away (either side): a candidate covering all of g, whose whole length is matched.
    expectScore(scoreOf(Vec4f(0, 0.9f, 100, 0.9f), kG), 1.0, 1.0, 1);
    expectScore(scoreOf(Vec4f(0, -0.9f, 100, -0.9f), kG), 1.0, 1.0, 1);
    // Same with the default offset: y = 0.9 in continuous coordinates is 0.4 in pixel centres.
    const Vec4f g(0.5f, 10.5f, 100.5f, 10.5f);
    expectScore(scoreOf(toPixelCentres(Vec4f(0.5f, 11.4f, 100.5f, 11.4f)), g, StructuralMatchParams()),
                1.0, 1.0, 1);
    expectScore(scoreOf(toPixelCentres(Vec4f(0.5f, 11.6f, 100.5f, 11.6f)), g, StructuralMatchParams()),
                0.0, 0.0, 0);
}

TEST(LSDAdvance_Evaluation, distance_is_taken_at_the_centre_not_at_the_endpoints)
{
    // 4 deg, length 100, centred on g: the endpoints are 50 sin(4 deg) = 3.49 px off the line,
    // but the centre is on it.
    const Vec4f d = centredAt(50, 0, 4, 100);
    ASSERT_GT(std::abs(d[1]), 3.0f);
    EXPECT_EQ(1, scoreOf(d, kG).found);
    // The same detection moved 1.5 px sideways: centre 1.5 px off, although one end crosses g.
    const Vec4f moved = d + Vec4f(0, 1.5f, 0, 1.5f);
    EXPECT_EQ(0, scoreOf(moved, kG).found);
}

TEST(LSDAdvance_Evaluation, candidate_angle_must_be_within_max_angle)
{
    // 6 deg, centred on g: not a candidate.
    expectScore(scoreOf(centredAt(50, 0, 6, 100), kG), 0.0, 0.0, 0);
    expectScore(scoreOf(centredAt(50, 0, -6, 100), kG), 0.0, 0.0, 0);
    // 4 deg: projected on g it spans [50 - 50 cos 4, 50 + 50 cos 4] = [0.122, 99.878], all inside g:
    // covered = matched = 100 cos(4 deg) = 99.756 -> recall = precision = cos(4 deg).
    const double c4 = std::cos(4 * CV_PI / 180);
    for (double angle : { 4.0, -4.0, 176.0, 184.0 })  // the angle is undirected
    {
        SCOPED_TRACE(cv::format("angle %g", angle));
        const StructuralScore s = scoreOf(centredAt(50, 0, angle, 100), kG);
        expectScore(s, c4, c4, 1);
        EXPECT_NEAR(100 * c4, s.coveredLength, 1e-4);
    }
}

TEST(LSDAdvance_Evaluation, ground_truth_is_found_only_when_covered_at_least_75_percent)
{
    // 70% of g: not found, and its length is not matched.
    StructuralScore s = scoreOf(Vec4f(0, 0, 70, 0), kG);
    expectScore(s, 0.0, 0.0, 0);
    EXPECT_EQ(0.0, s.matchedLength);
    EXPECT_EQ(0.0, s.coveredLength);
    EXPECT_NEAR(70.0, s.detectedLength, 1e-9);

    // 80% of g: found, recall 80 / 100, precision 80 / 80.
    s = scoreOf(Vec4f(10, 0, 90, 0), kG);
    expectScore(s, 1.0, 0.8, 1);
    EXPECT_NEAR(80.0, s.coveredLength, 1e-9);

    // Exactly 75%: the threshold is inclusive.
    expectScore(scoreOf(Vec4f(25, 0, 100, 0), kG), 1.0, 0.75, 1);
}

TEST(LSDAdvance_Evaluation, fragments_are_found_through_the_union_of_their_projections)
{
    // Three pieces covering [0, 30], [40, 70] and [80, 100] of g (gaps of 10): union 80 >= 75.
    // The last one runs 10 px past g's end: it counts 20 (clipped) of its 30.
    // recall = 80 / 100; precision = (30 + 30 + 20) / (30 + 30 + 30) = 8 / 9.
    const std::vector<Vec4f> pieces = { Vec4f(0, 0, 30, 0), Vec4f(40, 0, 70, 0), Vec4f(80, 0, 110, 0) };
    StructuralScore s = scoreOf(pieces, std::vector<Vec4f>(1, kG));
    expectScore(s, 8.0 / 9.0, 0.8, 1);
    EXPECT_NEAR(80.0, s.coveredLength, 1e-9);
    EXPECT_NEAR(80.0, s.matchedLength, 1e-9);
    EXPECT_NEAR(90.0, s.detectedLength, 1e-9);

    // An unrelated vertical detection of length 10 only adds to the detected length:
    // precision = 80 / 100.
    std::vector<Vec4f> withClutter = pieces;
    withClutter.push_back(Vec4f(200, 0, 200, 10));
    expectScore(scoreOf(withClutter, std::vector<Vec4f>(1, kG)), 0.8, 0.8, 1);

    // Without the middle piece the union is 50 < 75: not found, nothing matched.
    const std::vector<Vec4f> twoPieces = { pieces[0], pieces[2] };
    s = scoreOf(twoPieces, std::vector<Vec4f>(1, kG));
    expectScore(s, 0.0, 0.0, 0);
    EXPECT_EQ(0.0, s.matchedLength);
}

TEST(LSDAdvance_Evaluation, overlapping_fragments_count_their_union_for_recall)
{
    // [0, 60] and [30, 90]: union 90 (the sum would be 120).
    // recall = 90 / 100; precision = (60 + 60) / 120 = 1.
    const std::vector<Vec4f> pieces = { Vec4f(0, 0, 60, 0), Vec4f(30, 0, 90, 0) };
    const StructuralScore s = scoreOf(pieces, std::vector<Vec4f>(1, kG));
    expectScore(s, 1.0, 0.9, 1);
    EXPECT_NEAR(90.0, s.coveredLength, 1e-9);
    EXPECT_NEAR(120.0, s.matchedLength, 1e-9);

    // A piece nested in another adds nothing to the union: [0, 80] and [20, 40]: recall 0.8.
    const std::vector<Vec4f> nested = { Vec4f(0, 0, 80, 0), Vec4f(20, 0, 40, 0) };
    expectScore(scoreOf(nested, std::vector<Vec4f>(1, kG)), 1.0, 0.8, 1);
}

TEST(LSDAdvance_Evaluation, duplicated_detections_each_count_as_matched)
{
    // Documented rule: two identical detections on g both count.
    // recall = 100 / 100 (union); precision = (100 + 100) / 200.
    const std::vector<Vec4f> twice(2, kG);
    const StructuralScore s = scoreOf(twice, std::vector<Vec4f>(1, kG));
    expectScore(s, 1.0, 1.0, 1);
    EXPECT_NEAR(200.0, s.matchedLength, 1e-9);
    EXPECT_NEAR(200.0, s.detectedLength, 1e-9);
    EXPECT_NEAR(100.0, s.coveredLength, 1e-9);
}

TEST(LSDAdvance_Evaluation, detection_shared_by_two_ground_truths_counts_at_most_its_length)
{
    // g1 at y = 0 and g2 at y = 0.5 (overlapping ground truth); d at y = 0.25 is a candidate of
    // both: its clipped lengths sum to 200 but it counts min(200, 100) = 100.
    const std::vector<Vec4f> gt = { kG, Vec4f(0, 0.5f, 100, 0.5f) };
    const std::vector<Vec4f> d(1, Vec4f(0, 0.25f, 100, 0.25f));
    StructuralScore s = scoreOf(d, gt);
    expectScore(s, 1.0, 1.0, 2);
    EXPECT_NEAR(100.0, s.matchedLength, 1e-9);
    EXPECT_LE(s.precision, 1.0);

    // Partial case: d covers [0, 80] of both: clipped sum 160, counted 80 -> precision 1;
    // recall = (80 + 80) / 200.
    const std::vector<Vec4f> partial(1, Vec4f(0, 0.25f, 80, 0.25f));
    s = scoreOf(partial, gt);
    expectScore(s, 1.0, 0.8, 2);
    EXPECT_NEAR(80.0, s.matchedLength, 1e-9);

    // The same ground truth listed twice behaves the same.
    s = scoreOf(std::vector<Vec4f>(1, kG), std::vector<Vec4f>(2, kG));
    expectScore(s, 1.0, 1.0, 2);
}

TEST(LSDAdvance_Evaluation, detection_longer_than_ground_truth_is_clipped_to_it)
{
    // d = [-50, 150] (centre on g): clipped to [0, 100] -> precision = 100 / 200, recall 1.
    expectScore(scoreOf(Vec4f(-50, 0, 150, 0), kG), 0.5, 1.0, 1);
    // d = [0, 300], centre (150, 0) beyond g's end but on its supporting line: candidate,
    // clipped to 100 -> precision = len(g) / len(d) = 1 / 3.
    expectScore(scoreOf(Vec4f(0, 0, 300, 0), kG), 1.0 / 3.0, 1.0, 1);
    // A detection on g's line but entirely outside g covers nothing.
    expectScore(scoreOf(Vec4f(110, 0, 200, 0), kG), 0.0, 0.0, 0);
}

TEST(LSDAdvance_Evaluation, reversed_directions_score_the_same)
{
    // A non-trivial case on a slightly tilted g: a 3 deg piece sticking out of g's start and a
    // fragment 0.56 px off the line; union about [0, 95].
    const std::vector<Vec4f> dets = { centredAt(20, 0.3, 3, 70), Vec4f(50, -0.2f, 95, -0.2f) };
    const Vec4f g(0, 0, 100, 0.5f);
    const StructuralScore ref = scoreOf(dets, std::vector<Vec4f>(1, g));
    ASSERT_EQ(1, ref.found);
    for (int flips = 1; flips < 8; flips++)
    {
        SCOPED_TRACE(cv::format("flips %d", flips));
        std::vector<Vec4f> d = dets;
        Vec4f gt = g;
        for (int k = 0; k < 2; k++)
            if (flips & (1 << k))
                d[k] = Vec4f(d[k][2], d[k][3], d[k][0], d[k][1]);
        if (flips & 4)
            gt = Vec4f(g[2], g[3], g[0], g[1]);
        const StructuralScore s = scoreOf(d, std::vector<Vec4f>(1, gt));
        EXPECT_EQ(ref.found, s.found);
        EXPECT_NEAR(ref.precision, s.precision, 1e-5);
        EXPECT_NEAR(ref.recall, s.recall, 1e-5);
        EXPECT_NEAR(ref.matchedLength, s.matchedLength, 1e-4);
        EXPECT_NEAR(ref.coveredLength, s.coveredLength, 1e-4);
    }
}

TEST(LSDAdvance_Evaluation, zero_length_ground_truth_is_ignored)
{
    const std::vector<Vec4f> gt = { Vec4f(5, 5, 5, 5), kG, Vec4f(50, 0, 50, 0) };
    const StructuralScore s = scoreOf(std::vector<Vec4f>(1, kG), gt);
    EXPECT_EQ(1, s.groundTruthCount);
    EXPECT_NEAR(100.0, s.groundTruthLength, 1e-9);
    expectScore(s, 1.0, 1.0, 1);
}

TEST(LSDAdvance_Evaluation, empty_inputs_give_zero_scores)
{
    const std::vector<Vec4f> none, one(1, kG);
    StructuralScore s = scoreOf(none, one);
    expectScore(s, 0.0, 0.0, 0);
    EXPECT_EQ(1, s.groundTruthCount);
    EXPECT_EQ(0.0, s.detectedLength);

    s = scoreOf(one, none);
    expectScore(s, 0.0, 0.0, 0);
    EXPECT_EQ(0, s.groundTruthCount);
    EXPECT_NEAR(100.0, s.detectedLength, 1e-9);

    s = scoreOf(none, none);
    expectScore(s, 0.0, 0.0, 0);

    // An empty Mat is accepted like an empty vector.
    s = evaluateStructural(Mat(), one);
    expectScore(s, 0.0, 0.0, 0);

    // Only zero-length detections: nothing detected.
    s = scoreOf(std::vector<Vec4f>(1, Vec4f(50, 0, 50, 0)), one);
    expectScore(s, 0.0, 0.0, 0);
    EXPECT_EQ(0.0, s.detectedLength);
}

TEST(LSDAdvance_Evaluation, accepts_row_column_and_roi_layouts)
{
    const std::vector<Vec4f> d = { Vec4f(0, 0, 60, 0), Vec4f(30, 0, 90, 0) }, gt(1, kG);
    const StructuralScore ref = scoreOf(d, gt);
    const Mat column(d, true), row = Mat(d, true).reshape(4, 1);
    ASSERT_EQ(1, row.rows);
    expectScore(evaluateStructural(column, gt, noOffset()), ref.precision, ref.recall, ref.found);
    expectScore(evaluateStructural(row, gt, noOffset()), ref.precision, ref.recall, ref.found);
    // A non-continuous column of a wider array.
    Mat wide(2, 3, CV_32FC4, Scalar::all(7));
    column.copyTo(wide.col(1));
    ASSERT_FALSE(wide.col(1).isContinuous());
    expectScore(evaluateStructural(wide.col(1), gt, noOffset()), ref.precision, ref.recall, ref.found);
}

TEST(LSDAdvance_Evaluation, bad_input_type_throws)
{
    const std::vector<Vec4f> gt(1, kG);
    const Mat flat = (Mat_<float>(1, 4) << 0, 0, 100, 0);  // CV_32FC1
    EXPECT_THROW(evaluateStructural(flat, gt), cv::Exception);
    EXPECT_THROW(evaluateStructural(gt, flat), cv::Exception);
    EXPECT_THROW(evaluateStructural(Mat(2, 4, CV_32FC1, Scalar(0)), gt), cv::Exception);
    EXPECT_THROW(evaluateStructural(std::vector<Vec4d>(1, Vec4d(0, 0, 100, 0)), gt), cv::Exception);
    EXPECT_THROW(evaluateStructural(Mat(2, 2, CV_32FC4, Scalar::all(1)), gt), cv::Exception);
}

TEST(LSDAdvance_Evaluation, bad_parameters_throw)
{
    const std::vector<Vec4f> one(1, kG);
    std::vector<StructuralMatchParams> bad;
    StructuralMatchParams p;
    p.maxDistance = std::numeric_limits<double>::quiet_NaN(); bad.push_back(p); p = StructuralMatchParams();
    p.maxDistance = -1; bad.push_back(p); p = StructuralMatchParams();
    p.maxDistance = std::numeric_limits<double>::infinity(); bad.push_back(p); p = StructuralMatchParams();
    p.maxAngle = 90.5; bad.push_back(p); p = StructuralMatchParams();
    p.maxAngle = -1; bad.push_back(p); p = StructuralMatchParams();
    p.maxAngle = std::numeric_limits<double>::quiet_NaN(); bad.push_back(p); p = StructuralMatchParams();
    p.minCoverage = 0; bad.push_back(p); p = StructuralMatchParams();
    p.minCoverage = 1.01; bad.push_back(p); p = StructuralMatchParams();
    p.minCoverage = std::numeric_limits<double>::quiet_NaN(); bad.push_back(p); p = StructuralMatchParams();
    p.offset = std::numeric_limits<double>::quiet_NaN(); bad.push_back(p); p = StructuralMatchParams();
    for (size_t i = 0; i < bad.size(); i++)
    {
        SCOPED_TRACE(cv::format("case %d: %g %g %g %g", (int)i, bad[i].maxDistance, bad[i].maxAngle,
                                bad[i].minCoverage, bad[i].offset));
        EXPECT_THROW(evaluateStructural(one, one, bad[i]), cv::Exception);
        // The parameters are checked even without anything to score.
        EXPECT_THROW(evaluateStructural(std::vector<Vec4f>(), std::vector<Vec4f>(), bad[i]), cv::Exception);
    }
    // The limits themselves are valid.
    p = StructuralMatchParams();
    p.maxDistance = 0; p.maxAngle = 90; p.minCoverage = 1;
    EXPECT_NO_THROW(evaluateStructural(one, one, p));
    p.maxAngle = 0;
    EXPECT_NO_THROW(evaluateStructural(one, one, p));
}

TEST(LSDAdvance_Evaluation, offset_is_added_to_the_detections)
{
    // d = (0, 10) -> (100, 10) in pixel centres.
    const Vec4f d(0, 10, 100, 10);
    StructuralMatchParams half, zero = noOffset();
    ASSERT_EQ(0.5, half.offset);
    // g at y = 11.1 (x spanning [0.5, 100.5]): with the offset d sits at y = 10.5, 0.6 px from g
    // (found, exact cover); without it d is 1.1 px away (not a candidate).
    const Vec4f above(0.5f, 11.1f, 100.5f, 11.1f);
    expectScore(scoreOf(d, above, half), 1.0, 1.0, 1);
    expectScore(scoreOf(d, above, zero), 0.0, 0.0, 0);
    // g at y = 9.4: the other way round, 0.6 px without the offset and 1.1 px with it.
    const Vec4f below(0, 9.4f, 100, 9.4f);
    expectScore(scoreOf(d, below, zero), 1.0, 1.0, 1);
    expectScore(scoreOf(d, below, half), 0.0, 0.0, 0);
    // The offset moves x too: g = [0.5, 100.5] at y = 10.5 is covered exactly with offset 0.5;
    // with offset -0.5, d spans [-0.5, 99.5] on the line y = 9.5 (1 px away, still a candidate):
    // clipped to [0.5, 99.5] -> recall 0.99, precision 0.99.
    const Vec4f onLine(0.5f, 10.5f, 100.5f, 10.5f);
    StructuralMatchParams minusHalf;
    minusHalf.offset = -0.5;
    expectScore(scoreOf(d, onLine, half), 1.0, 1.0, 1);
    expectScore(scoreOf(d, onLine, minusHalf), 0.99, 0.99, 1);
}

TEST(LSDAdvance_Evaluation, max_distance_changes_the_outcome)
{
    const Vec4f d(0, 1.1f, 100, 1.1f);
    StructuralMatchParams p = noOffset();
    EXPECT_EQ(0, scoreOf(d, kG, p).found);
    p.maxDistance = 1.2;
    expectScore(scoreOf(d, kG, p), 1.0, 1.0, 1);
    p.maxDistance = 0.5;
    EXPECT_EQ(0, scoreOf(Vec4f(0, 0.9f, 100, 0.9f), kG, p).found);
    EXPECT_EQ(1, scoreOf(Vec4f(0, 0.4f, 100, 0.4f), kG, p).found);
}

TEST(LSDAdvance_Evaluation, max_angle_changes_the_outcome)
{
    StructuralMatchParams p = noOffset();
    const Vec4f six = centredAt(50, 0, 6, 100), four = centredAt(50, 0, 4, 100);
    EXPECT_EQ(0, scoreOf(six, kG, p).found);
    EXPECT_EQ(1, scoreOf(four, kG, p).found);
    p.maxAngle = 7;
    const double c6 = std::cos(6 * CV_PI / 180);
    expectScore(scoreOf(six, kG, p), c6, c6, 1);
    p.maxAngle = 3;
    EXPECT_EQ(0, scoreOf(four, kG, p).found);
    // Any direction passes at 90 deg: a perpendicular detection crossing g projects on a point
    // (nothing covered) and is not found, but a 60 deg one of length 200 projects on [0, 100].
    p.maxAngle = 90;
    EXPECT_EQ(0, scoreOf(centredAt(50, 0, 90, 100), kG, p).found);
    expectScore(scoreOf(centredAt(50, 0, 60, 200), kG, p), 0.5, 1.0, 1);
}

TEST(LSDAdvance_Evaluation, min_coverage_changes_the_outcome)
{
    StructuralMatchParams p = noOffset();
    const Vec4f seventy(0, 0, 70, 0), eighty(10, 0, 90, 0);
    EXPECT_EQ(0, scoreOf(seventy, kG, p).found);
    EXPECT_EQ(1, scoreOf(eighty, kG, p).found);
    p.minCoverage = 0.65;
    expectScore(scoreOf(seventy, kG, p), 1.0, 0.7, 1);
    p.minCoverage = 0.85;
    expectScore(scoreOf(eighty, kG, p), 0.0, 0.0, 0);
    p.minCoverage = 1;
    EXPECT_EQ(1, scoreOf(kG, kG, p).found);
}

TEST(LSDAdvance_Evaluation, scores_sum_over_several_ground_truths)
{
    // g1 = [0, 100] on y = 0 covered 80% (found); g2 = (0, 50) -> (0, 150) (length 100) covered
    // 50% (not found); g3 of length 50 found exactly.
    // recall = (80 + 0 + 50) / 250 = 0.52; precision = (80 + 0 + 50) / (80 + 50 + 50) = 130 / 180.
    const std::vector<Vec4f> gt = { kG, Vec4f(0, 50, 0, 150), Vec4f(200, 200, 230, 240) };
    const std::vector<Vec4f> d = { Vec4f(10, 0, 90, 0), Vec4f(0, 100, 0, 150), Vec4f(230, 240, 200, 200) };
    const StructuralScore s = scoreOf(d, gt);
    expectScore(s, 130.0 / 180.0, 0.52, 2);
    EXPECT_EQ(3, s.groundTruthCount);
    EXPECT_NEAR(250.0, s.groundTruthLength, 1e-9);
}

// ---------------------------------------------------------------- summary numbers

TEST(LSDAdvance_Evaluation, f_score_is_the_harmonic_mean)
{
    EXPECT_NEAR(0.5, fScore(0.5, 0.5), 1e-12);
    EXPECT_EQ(0.0, fScore(0, 0));
    EXPECT_NEAR(2.0 / 3.0, fScore(1, 0.5), 1e-12);
    EXPECT_NEAR(2.0 / 3.0, fScore(0.5, 1), 1e-12);
    EXPECT_EQ(0.0, fScore(0, 0.7));
    EXPECT_NEAR(1.0, fScore(1, 1), 1e-12);
}

TEST(LSDAdvance_Evaluation, long_segment_share_counts_segments_at_least_min_length)
{
    // Lengths 100, 60 (3-4-5: exactly the threshold, inclusive), 59.9 and 10.
    const std::vector<Vec4f> lines = { Vec4f(0, 0, 100, 0), Vec4f(0, 0, 36, 48), Vec4f(0, 0, 0, 59.9f),
                                       Vec4f(5, 5, 15, 5) };
    // The test_precomp helper shares the name: call the module's function explicitly.
    EXPECT_NEAR(2.0 / 4.0, line_evaluation::longSegmentShare(lines), 1e-12);
    EXPECT_NEAR(2.0 / 4.0, line_evaluation::longSegmentShare(lines, 60.0), 1e-12);
    EXPECT_NEAR(3.0 / 4.0, line_evaluation::longSegmentShare(lines, 50.0), 1e-12);
    EXPECT_NEAR(1.0, line_evaluation::longSegmentShare(lines, 0.0), 1e-12);
    EXPECT_NEAR(0.0, line_evaluation::longSegmentShare(lines, 200.0), 1e-12);
    EXPECT_NEAR(1.0 / 4.0, line_evaluation::longSegmentShare(Mat(lines, true), 61.0), 1e-12);
    EXPECT_EQ(0.0, line_evaluation::longSegmentShare(std::vector<Vec4f>()));
    EXPECT_EQ(0.0, line_evaluation::longSegmentShare(Mat()));
    EXPECT_THROW(line_evaluation::longSegmentShare(Mat(1, 4, CV_32FC1, Scalar(1))), cv::Exception);
}

// ---------------------------------------------------------------- segment files

TEST(LSDAdvance_Evaluation, segments_round_trip_through_text_with_three_decimals)
{
    const String path = cv::tempfile(".txt");
    const std::vector<Vec4f> lines = { Vec4f(1.23456f, 2, 3.0004f, -4.5f), Vec4f(0, 0, 639.9996f, 479.25f),
                                       Vec4f(-0.0004f, 1e3f, 12.3456f, 7) };
    writeSegments(path, lines);
    std::vector<Vec4f> back = readSegments(path);
    ASSERT_EQ(lines.size(), back.size());
    for (size_t i = 0; i < lines.size(); i++)
    {
        SCOPED_TRACE(cv::format("segment %d", (int)i));
        for (int k = 0; k < 4; k++)
            EXPECT_NEAR(lines[i][k], back[i][k], 5e-4 + 1e-6);
    }
    // Rounded to 3 decimals: 1.23456 -> 1.235, 3.0004 -> 3.000, 639.9996 -> 640.000.
    EXPECT_FLOAT_EQ(1.235f, back[0][0]);
    EXPECT_FLOAT_EQ(3.0f, back[0][2]);
    EXPECT_FLOAT_EQ(640.0f, back[1][2]);
    EXPECT_FLOAT_EQ(12.346f, back[2][2]);

    // Writing what was read gives the same file.
    const String again = cv::tempfile(".txt");
    writeSegments(again, Mat(back, true));
    EXPECT_EQ(lines.size(), readSegments(again).size());
    std::ifstream a(path.c_str()), b(again.c_str());
    const std::string textA((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
    const std::string textB((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
    EXPECT_EQ(textA, textB);
    EXPECT_EQ(0u, textA.find("1.235 2.000 3.000 -4.500\n")) << textA;

    // No segments: an empty file, read back as none.
    writeSegments(path, std::vector<Vec4f>());
    EXPECT_TRUE(readSegments(path).empty());
    std::remove(path.c_str());
    std::remove(again.c_str());
}

TEST(LSDAdvance_Evaluation, read_segments_skips_blank_lines_and_comments_and_accepts_commas)
{
    const String path = cv::tempfile(".txt");
    writeText(path, "# x1 y1 x2 y2\n"
                    "\n"
                    "   # an indented comment\n"
                    "1, 2, 3, 4\n"
                    "   \t\n"
                    "5 6 7 8\r\n"
                    "\t9,10 ,11,   12.5\n"
                    "-1e1 0.25 +3 4");  // no final newline
    const std::vector<Vec4f> s = readSegments(path);
    ASSERT_EQ(4u, s.size());
    EXPECT_EQ(Vec4f(1, 2, 3, 4), s[0]);
    EXPECT_EQ(Vec4f(5, 6, 7, 8), s[1]);
    EXPECT_EQ(Vec4f(9, 10, 11, 12.5f), s[2]);
    EXPECT_EQ(Vec4f(-10, 0.25f, 3, 4), s[3]);

    writeText(path, "# only comments\n\n");
    EXPECT_TRUE(readSegments(path).empty());
    std::remove(path.c_str());
}

TEST(LSDAdvance_Evaluation, read_segments_throws_on_a_malformed_row_or_missing_file)
{
    const String path = cv::tempfile(".txt");
    const char* bad[] = {
        "1 2 3 4\n1 2 3\n",       // 3 numbers
        "1 2 3 4 5\n",            // 5 numbers
        "1 2 three 4\n",          // a word
        "segment 1 2 3 4\n",      // a leading word
        "1 2 3 4 # comment\n",    // comments only on their own line
        "1 2 3 4x\n",             // trailing garbage on a number
        "1 2 nan 4\n",            // not finite
        "1 inf 3 4\n",            // not finite
        "P0: 1 2 3 4\n",          // labels belong to calib.txt only
    };
    for (const char* text : bad)
    {
        SCOPED_TRACE(text);
        writeText(path, text);
        EXPECT_THROW(readSegments(path), cv::Exception);
    }
    std::remove(path.c_str());
    EXPECT_THROW(readSegments(path), cv::Exception);
}

TEST(LSDAdvance_Evaluation, write_segments_rejects_bad_input)
{
    const String path = cv::tempfile(".txt");
    EXPECT_THROW(writeSegments(path, Mat(1, 4, CV_32FC1, Scalar(1))), cv::Exception);
    // An unwritable path.
    EXPECT_THROW(writeSegments(cv::utils::fs::join(path, "no/such/dir.txt"), std::vector<Vec4f>(1, kG)),
                 cv::Exception);
    std::remove(path.c_str());
}

// ---------------------------------------------------------------- YorkUrban loader

// images/A.jpg, images/B.jpg and gt/A_gt.txt (1 segment), gt/B_gt.txt (2 segments).
void makeYorkUrban(const TempFolder& root)
{
    ASSERT_TRUE(cv::utils::fs::createDirectories(root / "images"));
    ASSERT_TRUE(cv::utils::fs::createDirectories(root / "gt"));
    const Mat image(8, 8, CV_8UC3, Scalar(10, 20, 30));
    // Written in reverse order: the loader sorts by name.
    ASSERT_TRUE(cv::imwrite(cv::utils::fs::join(root / "images", "B.jpg"), image));
    ASSERT_TRUE(cv::imwrite(cv::utils::fs::join(root / "images", "A.jpg"), image));
    writeText(cv::utils::fs::join(root / "gt", "B_gt.txt"), "1 1 5 1\n2.5 2 2.5 7\n");
    writeText(cv::utils::fs::join(root / "gt", "A_gt.txt"), "0 0 7 7\n");
}

TEST(LSDAdvance_Evaluation, york_urban_loads_images_in_name_order_without_a_list)
{
    TempFolder root;
    makeYorkUrban(root);
    const std::vector<LabelledImage> items = loadYorkUrban(root.path);
    ASSERT_EQ(2u, items.size());
    EXPECT_EQ(cv::utils::fs::join(root / "images", "A.jpg"), items[0].imagePath);
    EXPECT_EQ(cv::utils::fs::join(root / "images", "B.jpg"), items[1].imagePath);
    ASSERT_EQ(1u, items[0].groundTruth.size());
    EXPECT_EQ(Vec4f(0, 0, 7, 7), items[0].groundTruth[0]);
    ASSERT_EQ(2u, items[1].groundTruth.size());
    EXPECT_EQ(Vec4f(1, 1, 5, 1), items[1].groundTruth[0]);
    EXPECT_EQ(Vec4f(2.5f, 2, 2.5f, 7), items[1].groundTruth[1]);
    EXPECT_FALSE(cv::imread(items[0].imagePath).empty());
}

TEST(LSDAdvance_Evaluation, york_urban_respects_the_order_of_list_txt)
{
    TempFolder root;
    makeYorkUrban(root);
    writeText(root / "list.txt", "B\nA\n");
    std::vector<LabelledImage> items = loadYorkUrban(root.path);
    ASSERT_EQ(2u, items.size());
    EXPECT_EQ(cv::utils::fs::join(root / "images", "B.jpg"), items[0].imagePath);
    EXPECT_EQ(2u, items[0].groundTruth.size());
    EXPECT_EQ(cv::utils::fs::join(root / "images", "A.jpg"), items[1].imagePath);
    EXPECT_EQ(1u, items[1].groundTruth.size());

    // Only the listed images are loaded.
    writeText(root / "list.txt", "B\n");
    items = loadYorkUrban(root.path);
    ASSERT_EQ(1u, items.size());
    EXPECT_EQ(cv::utils::fs::join(root / "images", "B.jpg"), items[0].imagePath);

    // A listed image that does not exist.
    writeText(root / "list.txt", "A\nC\n");
    EXPECT_THROW(loadYorkUrban(root.path), cv::Exception);
}

TEST(LSDAdvance_Evaluation, york_urban_throws_on_missing_ground_truth_or_folder)
{
    TempFolder root;
    makeYorkUrban(root);
    ASSERT_NO_THROW(loadYorkUrban(root.path));
    ASSERT_TRUE(cv::utils::fs::exists(cv::utils::fs::join(root / "gt", "B_gt.txt")));
    ASSERT_EQ(0, std::remove(cv::utils::fs::join(root / "gt", "B_gt.txt").c_str()));
    EXPECT_THROW(loadYorkUrban(root.path), cv::Exception);
    writeText(root / "list.txt", "A\n");
    EXPECT_NO_THROW(loadYorkUrban(root.path));  // B is not listed any more

    EXPECT_THROW(loadYorkUrban(root / "missing"), cv::Exception);
    // A folder without gt/.
    TempFolder noGt;
    ASSERT_TRUE(cv::utils::fs::createDirectories(noGt / "images"));
    EXPECT_THROW(loadYorkUrban(noGt.path), cv::Exception);
}

// Regression: without list.txt the loader once listed every image type but opened NAME.jpg.
TEST(LSDAdvance_Evaluation, york_urban_without_list_ignores_images_that_are_not_jpg)
{
    TempFolder root;
    makeYorkUrban(root);
    ASSERT_TRUE(cv::imwrite(cv::utils::fs::join(root / "images", "thumbnail.png"), Mat(4, 4, CV_8UC1, Scalar(1))));
    std::vector<LabelledImage> items;
    ASSERT_NO_THROW(items = loadYorkUrban(root.path));
    ASSERT_EQ(2u, items.size());
    EXPECT_EQ(cv::utils::fs::join(root / "images", "A.jpg"), items[0].imagePath);
    EXPECT_EQ(cv::utils::fs::join(root / "images", "B.jpg"), items[1].imagePath);
}

// ---------------------------------------------------------------- sequence loader

const double kP0[12] = { 718.856, 0, 607.1928, 0, 0, 718.856, 185.2157, 0, 0, 0, 1, 0 };
const double kP1[12] = { 718.856, 0, 607.1928, -386.1448, 0, 718.856, 185.2157, 0, 0, 0, 1, 0 };

std::string row12(const double* v)
{
    std::string s;
    for (int i = 0; i < 12; i++)
        s += cv::format(i ? " %.10g" : "%.10g", v[i]);
    return s;
}

// Frame k's pose: identity rotation, translation (0.1 k, -0.2 k, 1.5 k).
double poseValue(int frame, int index)
{
    const double identity[12] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0 };
    if (index == 3) return 0.1 * frame;
    if (index == 7) return -0.2 * frame;
    if (index == 11) return 1.5 * frame;
    return identity[index];
}

std::string posesText(int frames)
{
    std::string s;
    for (int k = 0; k < frames; k++)
    {
        double v[12];
        for (int i = 0; i < 12; i++)
            v[i] = poseValue(k, i);
        s += row12(v) + "\n";
    }
    return s;
}

void writeFrames(const String& dir, int frames)
{
    ASSERT_TRUE(cv::utils::fs::createDirectories(dir));
    const Mat image(6, 10, CV_8UC1, Scalar(128));
    for (int k = frames - 1; k >= 0; k--)  // written in reverse order: the loader sorts by name
        ASSERT_TRUE(cv::imwrite(cv::utils::fs::join(dir, cv::format("%06d.png", k)), image));
}

void expectMatrix(const double* expected, const Mat& m)
{
    ASSERT_EQ(CV_64FC1, m.type());
    ASSERT_EQ(Size(4, 3), m.size());
    for (int i = 0; i < 12; i++)
        EXPECT_DOUBLE_EQ(expected[i], m.at<double>(i / 4, i % 4)) << "entry " << i;
}

TEST(LSDAdvance_Evaluation, sequence_loads_frames_calibration_and_poses)
{
    for (int prefixed = 0; prefixed < 2; prefixed++)
    {
        SCOPED_TRACE(prefixed ? "calib.txt with P0:/P1: prefixes" : "calib.txt without prefixes");
        TempFolder root;
        writeFrames(root / "image_l", 3);
        writeText(root / "calib.txt", prefixed ? "P0: " + row12(kP0) + "\nP1: " + row12(kP1) + "\n"
                                               : row12(kP0) + "\n" + row12(kP1) + "\n");
        writeText(root / "poses.txt", posesText(3));

        const SequenceData seq = loadSequence(root.path);
        ASSERT_EQ(3u, seq.imagePaths.size());
        for (int k = 0; k < 3; k++)
            EXPECT_EQ(cv::utils::fs::join(root / "image_l", cv::format("%06d.png", k)), seq.imagePaths[k]);
        expectMatrix(kP0, seq.P0);
        expectMatrix(kP1, seq.P1);
        ASSERT_EQ(3u, seq.poses.size());
        for (int k = 0; k < 3; k++)
        {
            SCOPED_TRACE(cv::format("pose %d", k));
            double v[12];
            for (int i = 0; i < 12; i++)
                v[i] = poseValue(k, i);
            expectMatrix(v, seq.poses[k]);
        }
    }
}

TEST(LSDAdvance_Evaluation, sequence_calibration_and_poses_are_optional)
{
    TempFolder root;
    writeFrames(root / "image_0", 2);
    SequenceData seq = loadSequence(root.path);
    EXPECT_EQ(2u, seq.imagePaths.size());
    EXPECT_TRUE(seq.P0.empty());
    EXPECT_TRUE(seq.P1.empty());
    EXPECT_TRUE(seq.poses.empty());

    // A single calibration row: P1 stays empty.
    writeText(root / "calib.txt", "P0: " + row12(kP0) + "\n");
    seq = loadSequence(root.path);
    expectMatrix(kP0, seq.P0);
    EXPECT_TRUE(seq.P1.empty());

    // A calibration row that is not 3x4.
    writeText(root / "calib.txt", "P0: 1 2 3\n");
    EXPECT_THROW(loadSequence(root.path), cv::Exception);
}

TEST(LSDAdvance_Evaluation, sequence_throws_on_pose_count_mismatch_or_no_image)
{
    TempFolder root;
    writeFrames(root / "image_l", 3);
    writeText(root / "poses.txt", posesText(2));
    EXPECT_THROW(loadSequence(root.path), cv::Exception);
    writeText(root / "poses.txt", posesText(4));
    EXPECT_THROW(loadSequence(root.path), cv::Exception);
    writeText(root / "poses.txt", posesText(3));
    EXPECT_NO_THROW(loadSequence(root.path));
    // A pose row of 11 numbers.
    writeText(root / "poses.txt", posesText(2) + "1 0 0 0 0 1 0 0 0 0 1\n");
    EXPECT_THROW(loadSequence(root.path), cv::Exception);

    TempFolder empty;
    EXPECT_THROW(loadSequence(empty.path), cv::Exception);
    ASSERT_TRUE(cv::utils::fs::createDirectories(empty / "image_l"));
    writeText(empty / "calib.txt", row12(kP0) + "\n");
    EXPECT_THROW(loadSequence(empty.path), cv::Exception);
    EXPECT_THROW(loadSequence(empty / "missing"), cv::Exception);
}

TEST(LSDAdvance_Evaluation, sequence_loads_the_right_frames_of_a_stereo_pair)
{
    TempFolder root;
    writeFrames(root / "image_l", 3);
    SequenceData seq = loadSequence(root.path);
    EXPECT_TRUE(seq.rightImagePaths.empty());
    writeFrames(root / "image_r", 3);
    seq = loadSequence(root.path);
    ASSERT_EQ(3u, seq.rightImagePaths.size());
    for (int k = 0; k < 3; k++)
        EXPECT_EQ(cv::utils::fs::join(root / "image_r", cv::format("%06d.png", k)), seq.rightImagePaths[k]);
    // A right folder without one of the left frames: an error that names the missing image.
    ASSERT_EQ(0, std::remove((root / "image_r" + "/000001.png").c_str()));
    try
    {
        loadSequence(root.path);
        ADD_FAILURE() << "expected an exception";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.msg.find("000001.png")) << e.msg;
    }
}

TEST(LSDAdvance_Evaluation, kitti_sequence_has_its_right_frames)
{
    const SequenceData seq = loadSequence(dataFolder("kitti_seq1"));
    ASSERT_EQ(51u, seq.imagePaths.size());
    ASSERT_EQ(51u, seq.rightImagePaths.size());
    const Mat left = imread(seq.imagePaths[7], IMREAD_GRAYSCALE), right = imread(seq.rightImagePaths[7], IMREAD_GRAYSCALE);
    EXPECT_EQ(left.size(), right.size());
    EXPECT_GT(cvtest::norm(left, right, NORM_L1), 0);
}

// ---------------------------------------------------------------- multi-view loader

// A Strecha-style camera file of a camera at centre C, turned by `yawDeg` about the vertical axis.
std::string cameraText(double yawDeg, const Vec3d& C, const std::string& distortion = "0 0 0")
{
    const double a = yawDeg * CV_PI / 180.0;
    return cv::format("1000 0 320\n0 1000 240\n0 0 1\n%s\n%.9f 0 %.9f\n0 1 0\n%.9f 0 %.9f\n%g %g %g\n640 480\n",
                      distortion.c_str(), std::cos(a), std::sin(a), -std::sin(a), std::cos(a), C[0], C[1], C[2]);
}

void writeView(const TempFolder& root, const std::string& name, const std::string& camera)
{
    ASSERT_TRUE(cv::utils::fs::createDirectories(root / "images"));
    ASSERT_TRUE(cv::utils::fs::createDirectories(root / "gt_dense_cameras"));
    ASSERT_TRUE(cv::imwrite(root / "images" + "/" + name, Mat(4, 4, CV_8UC1, Scalar(9))));
    writeText(root / "gt_dense_cameras" + "/" + name + ".camera", camera);
}

TEST(LSDAdvance_Evaluation, multi_view_loads_views_cameras_and_poses_in_name_order)
{
    TempFolder root;
    writeView(root, "0001.jpg", cameraText(10, Vec3d(1, 2, 3)));
    writeView(root, "0000.jpg", cameraText(0, Vec3d(0, 0, 0)));
    const MultiViewData data = loadMultiView(root.path);
    ASSERT_EQ(2u, data.imagePaths.size());
    EXPECT_EQ(root / "images" + "/0000.jpg", data.imagePaths[0]);
    EXPECT_EQ(root / "images" + "/0001.jpg", data.imagePaths[1]);
    ASSERT_EQ(2u, data.poses.size());
    EXPECT_EQ(Size(4, 3), data.poses[1].size());
    EXPECT_DOUBLE_EQ(3.0, data.poses[1].at<double>(2, 3));
    EXPECT_NEAR(std::cos(10 * CV_PI / 180), data.poses[1].at<double>(0, 0), 1e-9);
    EXPECT_DOUBLE_EQ(1000.0, data.cameraMatrices[0].at<double>(0, 0));
    EXPECT_EQ(Size(640, 480), data.imageSizes[1]);
}

TEST(LSDAdvance_Evaluation, multi_view_throws_on_malformed_cameras_or_missing_images)
{
    const struct
    {
        const char* what;
        std::string camera;
    } bad[] = { { "a distortion", cameraText(0, Vec3d(0, 0, 0), "0.1 0 0") },
                { "R not a rotation", "1000 0 320\n0 1000 240\n0 0 1\n0 0 0\n1 0 0\n0 2 0\n0 0 1\n0 0 0\n640 480\n" },
                { "a missing row", "1000 0 320\n0 1000 240\n0 0 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n" },
                { "K with a negative focal length", "-1000 0 320\n0 1000 240\n0 0 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n640 480\n" },
                { "a word for a number", "1000 0 320\n0 1000 240\n0 0 1\n0 0 0\n1 0 0\n0 1 zero\n0 0 1\n0 0 0\n640 480\n" } };
    for (const auto& item : bad)
    {
        SCOPED_TRACE(item.what);
        TempFolder root;
        writeView(root, "0000.jpg", item.camera);
        EXPECT_THROW(loadMultiView(root.path), cv::Exception);
    }
    TempFolder missingImage;
    writeView(missingImage, "0000.jpg", cameraText(0, Vec3d(0, 0, 0)));
    writeText(missingImage / "gt_dense_cameras" + "/0001.jpg.camera", cameraText(0, Vec3d(1, 0, 0)));
    EXPECT_THROW(loadMultiView(missingImage.path), cv::Exception);
    TempFolder empty;
    EXPECT_THROW(loadMultiView(empty.path), cv::Exception);
}

TEST(LSDAdvance_Evaluation, strecha_fountain_cameras_project_consistently)
{
    const MultiViewData data = loadMultiView(dataFolder("strecha_fountain_p11"));
    ASSERT_EQ(11u, data.imagePaths.size());
    for (size_t v = 0; v < data.poses.size(); v++)
    {
        SCOPED_TRACE(data.imagePaths[v]);
        EXPECT_EQ(Size(3072, 2048), data.imageSizes[v]);
        // Consecutive views 1.4 to 2.1 m apart.
        if (v > 0)
        {
            const double step = cv::norm(data.poses[v].col(3), data.poses[v - 1].col(3));
            EXPECT_GT(step, 1.0);
            EXPECT_LT(step, 2.5);
        }
    }
}

TEST(LSDAdvance_Evaluation, sequence_folder_may_hold_the_images_directly)
{
    TempFolder root;
    writeFrames(root.path, 3);
    writeText(root / "calib.txt", row12(kP0) + "\n");
    writeText(root / "poses.txt", posesText(3));
    const SequenceData seq = loadSequence(root.path);
    ASSERT_EQ(3u, seq.imagePaths.size());
    EXPECT_EQ(cv::utils::fs::join(root.path, "000000.png"), seq.imagePaths[0]);
    EXPECT_EQ(cv::utils::fs::join(root.path, "000002.png"), seq.imagePaths[2]);
    expectMatrix(kP0, seq.P0);
    EXPECT_EQ(3u, seq.poses.size());
}

}} // namespace opencv_test::
