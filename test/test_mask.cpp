// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The mask of detect() and processSegments() (the header's "Mask"): on every base no returned
// line passes over masked-out pixels, BASE_FAST_LSD grows no region over them, the cut keeps the
// pieces on the mask, stage 3 fuses nothing across it, and an all-set mask is no mask.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

const int kBases[] = { LSDAdvance::BASE_LSD, LSDAdvance::BASE_FLD, LSDAdvance::BASE_EDLINES, LSDAdvance::BASE_FAST_LSD };

Mat building()
{
    static const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

Ptr<LSDAdvance> onBase(int base, LSDAdvance::Preset preset = LSDAdvance::PRESET_MOST_ACCURATE)
{
    Ptr<LSDAdvance> d = createLSDAdvance(preset);
    d->setBaseDetector(base);
    return d;
}

// Whether a line passes over the masked-out pixels of `grown` (the mask grown by the tolerance):
// sampled every 0.25 px, each sample reading the pixel nearest to it.
bool crossesMask(const Mat& grown, const Vec4f& l)
{
    const Point2d a(l[0], l[1]), b(l[2], l[3]);
    const int steps = std::max(1, (int)std::ceil(4 * cv::norm(b - a)));
    for (int k = 0; k <= steps; k++)
    {
        const Point2d p = a + (b - a) * ((double)k / steps);
        const int x = std::min(std::max(cvRound(p.x), 0), grown.cols - 1);
        const int y = std::min(std::max(cvRound(p.y), 0), grown.rows - 1);
        if (!grown.at<uchar>(y, x))
            return true;
    }
    return false;
}

// How many lines pass over masked-out pixels farther than `tolerance` px from the mask.
int countCrossing(const Mat& mask, const std::vector<Vec4f>& lines, int tolerance)
{
    Mat grown;
    dilate(mask, grown, getStructuringElement(MORPH_RECT, Size(2 * tolerance + 1, 2 * tolerance + 1)));
    int n = 0;
    for (const Vec4f& l : lines)
        n += crossesMask(grown, l);
    return n;
}

// Three holes over the facade, and a band along the bottom and the right (a car's hood, a robot's body).
Mat maskWithHoles(Size size)
{
    Mat mask(size, CV_8UC1, Scalar(255));
    rectangle(mask, Rect(60, 60, 90, 70), Scalar(0), FILLED);
    rectangle(mask, Rect(250, 150, 120, 40), Scalar(0), FILLED);
    rectangle(mask, Rect(400, 300, 30, 200), Scalar(0), FILLED);
    return mask;
}

Mat maskAtBorder(Size size)
{
    Mat mask(size, CV_8UC1, Scalar(255));
    mask.rowRange(size.height - 80, size.height).setTo(0);
    mask.colRange(size.width - 50, size.width).setTo(0);
    return mask;
}

void expectLinesOffMask(const Mat& mask, LSDAdvance::Preset preset)
{
    const Mat img = building();
    for (int base : kBases)
    {
        SCOPED_TRACE(cv::format("base %d, preset %d", base, (int)preset));
        std::vector<Vec4f> all, masked;
        onBase(base, preset)->detect(img, all);
        onBase(base, preset)->detect(img, masked, mask);
        ASSERT_GT(countCrossing(mask, all, 1), 10) << "the mask must cover lines of the image";
        EXPECT_EQ(0, countCrossing(mask, masked, 1));
        EXPECT_GT(masked.size(), all.size() / 3) << "the lines off the mask remain";
    }
}

TEST(LSDAdvance_Mask, no_line_of_any_base_passes_over_holes)
{
    expectLinesOffMask(maskWithHoles(building().size()), LSDAdvance::PRESET_MOST_ACCURATE);
}

TEST(LSDAdvance_Mask, no_line_of_any_base_passes_over_a_band_at_the_border)
{
    expectLinesOffMask(maskAtBorder(building().size()), LSDAdvance::PRESET_MOST_ACCURATE);
}

TEST(LSDAdvance_Mask, no_line_passes_over_the_mask_at_the_base_scale_0_8)
{
    expectLinesOffMask(maskWithHoles(building().size()), LSDAdvance::PRESET_FASTEST);
}

TEST(LSDAdvance_Mask, all_zero_mask_gives_no_line_on_every_base_and_preset)
{
    const Mat img = building();
    for (int base : kBases)
        for (LSDAdvance::Preset preset : { LSDAdvance::PRESET_MOST_ACCURATE, LSDAdvance::PRESET_FASTEST })
        {
            std::vector<Vec4f> lines(1);
            ASSERT_NO_THROW(onBase(base, preset)->detect(img, lines, Mat::zeros(img.size(), CV_8UC1)));
            EXPECT_TRUE(lines.empty()) << "base " << base << ", preset " << preset;
        }
}

TEST(LSDAdvance_Mask, all_set_mask_gives_bit_identical_lines_and_stage_outputs)
{
    const Mat img = building();
    const Mat full(img.size(), CV_8UC1, Scalar(1));
    for (int base : kBases)
        for (LSDAdvance::Preset preset : { LSDAdvance::PRESET_MOST_ACCURATE, LSDAdvance::PRESET_FASTEST, LSDAdvance::PRESET_PAPER })
        {
            SCOPED_TRACE(cv::format("base %d, preset %d", base, (int)preset));
            Ptr<LSDAdvance> a = onBase(base, preset), b = onBase(base, preset);
            std::vector<Vec4f> expected, lines, expectedBase, masklessBase;
            a->detect(img, expected);
            b->detect(img, lines, full);
            ASSERT_FALSE(expected.empty());
            EXPECT_EQ(0, cvtest::norm(Mat(expected).reshape(1), Mat(lines).reshape(1), NORM_INF));
            EXPECT_EQ(expected.size(), lines.size());
            a->getLastStageOutputs(expectedBase, noArray(), noArray(), noArray());
            b->getLastStageOutputs(masklessBase, noArray(), noArray(), noArray());
            EXPECT_EQ(expectedBase, masklessBase);
        }
}

TEST(LSDAdvance_Mask, fast_lsd_grows_no_region_over_masked_pixels_before_any_cut)
{
    // FastLsd itself, without the cut: its segments stay off the holes up to the reach of a
    // rectangle past its region, and the lines the holes cut come out in pieces.
    const Mat img = building();
    const Mat mask = maskWithHoles(img.size());
    for (double scale : { 1.0, 0.8 })
    {
        LSDAdvance::LSDParams p;
        p.scale = scale;
        std::vector<Vec4f> all, masked;
        lsda::FastLsd(p).detect(img, all);
        lsda::FastLsd(p).detect(img, masked, mask);
        // A fitted rectangle's ends lie on its centre line, up to 2 px at the analysis scale
        // beside its region's pixels, and the sub-sampled mask is 1 px coarser.
        const int reach = (int)std::ceil(2.0 / scale) + 1;
        ASSERT_GT(countCrossing(mask, all, reach), 10) << scale;
        EXPECT_EQ(0, countCrossing(mask, masked, reach)) << scale;
        EXPECT_GT(masked.size(), all.size() / 2) << scale;
    }
}

TEST(LSDAdvance_Mask, cut_keeps_the_pieces_on_the_mask_in_the_segment_orientation)
{
    Mat mask(40, 80, CV_8UC1, Scalar(255));
    mask.colRange(30, 35).setTo(0);
    mask.at<uchar>(20, 50) = 0;  // one pixel: a piece from 51 on
    std::vector<Vec4f> segments = { Vec4f(10, 20, 60, 20), Vec4f(60, 10, 10, 10), Vec4f(5.5f, 5.25f, 25.5f, 8.75f) };
    std::vector<Vec4f> pieces;
    lsda::cutAtMask(mask, segments, pieces);
    const std::vector<Vec4f> expected = { Vec4f(10, 20, 29, 20), Vec4f(35, 20, 49, 20), Vec4f(51, 20, 60, 20),
                                          Vec4f(60, 10, 35, 10), Vec4f(29, 10, 10, 10),
                                          Vec4f(5.5f, 5.25f, 25.5f, 8.75f) };  // wholly on the mask: unchanged
    EXPECT_EQ(expected, segments);

    // A run of one sample is no piece; a segment wholly off the mask has none.
    Mat sparse(40, 80, CV_8UC1, Scalar(0));
    sparse.at<uchar>(20, 40) = 255;
    segments = { Vec4f(10, 20, 60, 20), Vec4f(10, 5, 60, 5) };
    lsda::cutAtMask(sparse, segments, pieces);
    EXPECT_TRUE(segments.empty());
}

// Two collinear pieces 8 px apart on y = 50, which fuse without a mask (the second shorter than
// a baseline of MERGE_BASELINES).
const std::vector<Vec4f> kCollinearPieces = { Vec4f(20, 50, 120, 50), Vec4f(128, 50, 188, 50) };

Mat maskWithStrip(int x0, int x1)
{
    Mat mask(100, 260, CV_8UC1, Scalar(255));
    mask.colRange(x0, x1).setTo(0);
    return mask;
}

TEST(LSDAdvance_Mask, merging_fuses_no_pieces_across_a_masked_gap)
{
    lsda::SegmentGroups groups;
    groups.members = { 0, 1 };
    groups.offsets = { 0, 2 };
    for (int strategy : { LSDAdvance::MERGE_LONGEST_FIRST, LSDAdvance::MERGE_BASELINES })
    {
        LSDAdvance::Params p;
        p.mergeStrategy = strategy;
        const lsda::MergingParams params(p);
        std::vector<Vec4f> merged;
        lsda::mergeGroups(kCollinearPieces, groups, params, merged);
        ASSERT_EQ(1u, merged.size()) << strategy;
        lsda::mergeGroups(kCollinearPieces, groups, params, merged, maskWithStrip(122, 126));
        EXPECT_EQ(kCollinearPieces, merged) << strategy;
        // A mask with a strip away from the gap changes nothing.
        lsda::mergeGroups(kCollinearPieces, groups, params, merged, maskWithStrip(240, 250));
        EXPECT_EQ(1u, merged.size()) << strategy;
    }
}

TEST(LSDAdvance_Mask, processSegments_cuts_at_the_mask_and_fuses_nothing_across_it)
{
    Ptr<LSDAdvance> d = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    std::vector<Vec4f> lines;
    d->processSegments(kCollinearPieces, lines);
    ASSERT_EQ(1u, lines.size());
    d->processSegments(kCollinearPieces, lines, Size(), maskWithStrip(122, 126));
    EXPECT_EQ(kCollinearPieces, lines);
    // A strip across a piece cuts it; the two parts fuse no more.
    d->processSegments(std::vector<Vec4f>{ Vec4f(20, 50, 228, 50) }, lines, Size(260, 100), maskWithStrip(100, 104));
    EXPECT_EQ((std::vector<Vec4f>{ Vec4f(104, 50, 228, 50), Vec4f(20, 50, 99, 50) }), lines);  // longest first
}

TEST(LSDAdvance_Mask, every_base_keeps_lines_apart_across_a_masked_strip)
{
    // A bright rectangle whose top and bottom edges a 6 px strip of the mask crosses: each base
    // finds their parts on both sides, which fuse when processed again without the mask.
    Mat img(240, 320, CV_8UC1, Scalar(40));
    rectangle(img, Point(30, 60), Point(289, 179), Scalar(200), FILLED);
    Mat mask(img.size(), CV_8UC1, Scalar(255));
    mask.colRange(157, 163).setTo(0);
    for (int base : kBases)
    {
        SCOPED_TRACE(cv::format("base %d", base));
        Ptr<LSDAdvance> d = onBase(base);
        std::vector<Vec4f> lines, cut, fused;
        d->detect(img, lines, mask);
        EXPECT_EQ(0, countCrossing(mask, lines, 1));
        int left = 0, right = 0;
        for (const Vec4f& l : lines)
            if (std::abs(l[1] - l[3]) < 2 && std::abs(l[2] - l[0]) > 60)
                (std::max(l[0], l[2]) < 160 ? left : right)++;
        EXPECT_GE(left, 2);
        EXPECT_GE(right, 2);
        d->getLastStageOutputs(cut, noArray(), noArray(), noArray());
        d->processSegments(cut, fused, img.size());
        EXPECT_GT(countCrossing(mask, fused, 1), 0) << "without the mask, stage 3 fuses across the strip";
    }
}

TEST(LSDAdvance_Mask, keylines_of_a_mask_are_those_of_its_lines)
{
    const Mat img = building();
    const Mat mask = maskWithHoles(img.size());
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->detect(img, lines, mask);
    std::vector<line_descriptor::KeyLine> keylines, expected;
    d->detect(img, keylines, mask);
    ASSERT_EQ(lines.size(), keylines.size());
    linesToKeyLines(lines, img.size(), expected);
    for (size_t i = 0; i < lines.size(); i++)
    {
        EXPECT_EQ(expected[i].startPointX, keylines[i].startPointX);
        EXPECT_EQ(expected[i].endPointY, keylines[i].endPointY);
    }
}

TEST(LSDAdvance_Mask, wrong_mask_type_or_size_is_rejected_naming_both)
{
    const Mat img = building();
    const Mat bad[] = { Mat(img.size(), CV_8UC3, Scalar::all(255)), Mat(img.size(), CV_16UC1, Scalar(255)),
                        Mat(img.size(), CV_32FC1, Scalar(1)), Mat(img.rows, img.cols + 1, CV_8UC1, Scalar(255)),
                        Mat(img.cols, img.rows, CV_8UC1, Scalar(255)) };
    for (const Mat& mask : bad)
    {
        Ptr<LSDAdvance> d = createLSDAdvance();
        std::vector<Vec4f> lines;
        try
        {
            d->detect(img, lines, mask);
            ADD_FAILURE() << "accepted " << typeToString(mask.type()) << " " << mask.size();
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.err.find("CV_8UC1 of the image's size")) << e.err;
            EXPECT_NE(std::string::npos, e.err.find(typeToString(mask.type()))) << e.err;
            EXPECT_NE(std::string::npos, e.err.find(cv::format("%dx%d", mask.cols, mask.rows))) << e.err;
        }
        EXPECT_THROW(d->processSegments(kCollinearPieces, lines, img.size(), mask), cv::Exception);
    }
}

TEST(LSDAdvance_StageOutputs, noArray_for_some_outputs_fills_only_the_others)
{
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->detect(building(), lines);
    std::vector<Vec4f> base, filtered, merged, onlyFiltered, onlyMerged;
    std::vector<int> labels, onlyLabels;
    d->getLastStageOutputs(base, filtered, labels, merged);
    ASSERT_FALSE(labels.empty());
    ASSERT_NO_THROW(d->getLastStageOutputs(noArray(), onlyFiltered, noArray(), noArray()));
    EXPECT_EQ(filtered, onlyFiltered);
    ASSERT_NO_THROW(d->getLastStageOutputs(noArray(), noArray(), onlyLabels, onlyMerged));
    EXPECT_EQ(labels, onlyLabels);
    EXPECT_EQ(merged, onlyMerged);
    ASSERT_NO_THROW(d->getLastStageOutputs(noArray(), noArray(), noArray(), noArray()));
}

}} // namespace
