// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance::getLastStageOutputs: each output is what the stage's own function gives on the
// previous stage's output, for both stage orders and with stages switched off.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

struct StageOutputs
{
    std::vector<Vec4f> base, filtered, merged;
    std::vector<int> labels;
};

StageOutputs stageOutputsOf(const LSDAdvance& detector)
{
    StageOutputs o;
    detector.getLastStageOutputs(o.base, o.filtered, o.labels, o.merged);
    return o;
}

bool bitIdentical(const std::vector<Vec4f>& a, const std::vector<Vec4f>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec4f)) == 0);
}

const Mat& buildingImage()
{
    static const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    return img;
}

// The segments stage 2 received: the base segments or stage 1's output, by the stage order.
const std::vector<Vec4f>& stage2Input(const LSDAdvance& d, const StageOutputs& o)
{
    return d.getStageOrder() == LSDAdvance::FILTER_THEN_MERGE ? o.filtered : o.base;
}

// Stage 1's input: the base segments or stage 3's output, by the stage order.
const std::vector<Vec4f>& stage1Input(const LSDAdvance& d, const StageOutputs& o)
{
    return d.getStageOrder() == LSDAdvance::FILTER_THEN_MERGE ? o.base : o.merged;
}

// What detect() returns for the last stage's output: the segments clipped to the image.
std::vector<Vec4f> clippedTo(const std::vector<Vec4f>& segments, const Size& size)
{
    std::vector<Vec4f> clipped;
    std::vector<int> keptFrom;
    lsda::clipToImage(segments, size, clipped, keptFrom);
    return clipped;
}

// Runs a short sequence (so that inter-frame alpha acts) and checks the last frame's outputs
// with `check` after every frame, for both stage orders, with and without strong segments.
void forEachFrameOfBothOrders(
    const std::function<void(const LSDAdvance&, const Mat& frame, const std::vector<Vec4f>& lines)>& check)
{
    const Mat& img = buildingImage();
    ASSERT_FALSE(img.empty());
    const Mat frames[] = { img, img(Rect(0, 0, img.cols * 3 / 4, img.rows)), img(Rect(0, 0, img.cols / 2, img.rows)) };
    for (int order : { (int)LSDAdvance::FILTER_THEN_MERGE, (int)LSDAdvance::MERGE_THEN_FILTER })
        for (bool keepStrong : { false, true })
        {
            SCOPED_TRACE(cv::format("order %d, keepStrongSegments %d", order, (int)keepStrong));
            Ptr<LSDAdvance> detector = createLSDAdvance();
            detector->setStageOrder(order);
            detector->setKeepStrongSegments(keepStrong);
            for (const Mat& frame : frames)
            {
                std::vector<Vec4f> lines;
                detector->detect(frame, lines);
                check(*detector, frame, lines);
            }
        }
}

TEST(LSDAdvance_StageOutputs, base_segments_are_what_the_base_alone_returns)
{
    const Mat& img = buildingImage();
    ASSERT_FALSE(img.empty());
    for (const int base : { LSDAdvance::BASE_FAST_LSD, LSDAdvance::BASE_LSD })
    {
        SCOPED_TRACE(base);
        Ptr<LSDAdvance> d = createLSDAdvance();
        d->setBaseDetector(base);
        std::vector<Vec4f> lines, alone;
        d->detect(img, lines);
        lsda::createBaseDetector(base, LSDAdvance::LSDParams(), LSDAdvance::FLDParams(), EdgeDrawing::Params())
            ->detect(img, alone);
        const StageOutputs o = stageOutputsOf(*d);
        ASSERT_GT(alone.size(), 100u);
        EXPECT_TRUE(bitIdentical(alone, o.base));
    }
}

TEST(LSDAdvance_StageOutputs, filtered_segments_are_the_long_or_strong_ones_with_the_reported_thresholds)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat& frame, const std::vector<Vec4f>&) {
        const StageOutputs o = stageOutputsOf(d);
        const LSDAdvanceStats stats = d.getLastStats();
        ASSERT_GT(stats.minLength, 0.0);
        const std::vector<Vec4f>& input = stage1Input(d, o);
        std::vector<Vec4f> expected, longOnes;
        lsda::keepLongOrStrong(input, std::vector<float>(), stats.minLength, 0.0, longOnes);
        if (d.getKeepStrongSegments())
        {
            std::vector<float> baseResponses, responses;
            lsda::lineResponses(frame, o.base, baseResponses);
            lsda::lineResponses(frame, input, responses);
            EXPECT_NEAR(stats.alpha * lsda::adaptiveMinResponse(baseResponses, d.getLengthThresholdScale(), d.getLengthThresholdRule()),
                        stats.minResponse, 1e-6 * stats.minResponse);
            lsda::keepLongOrStrong(input, responses, stats.minLength, stats.minResponse, expected);
            EXPECT_GT(expected.size(), longOnes.size());  // short strong segments were kept
        }
        else
        {
            EXPECT_EQ(0.0, stats.minResponse);
            expected = longOnes;
        }
        EXPECT_LT(expected.size(), input.size());  // the filter dropped something
        EXPECT_TRUE(bitIdentical(expected, o.filtered));
    });
}

TEST(LSDAdvance_StageOutputs, group_labels_partition_the_stage2_input_as_groupSegments_does)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat&, const std::vector<Vec4f>&) {
        const StageOutputs o = stageOutputsOf(d);
        const std::vector<Vec4f>& input = stage2Input(d, o);
        ASSERT_EQ(input.size(), o.labels.size());
        lsda::SegmentGroups groups;
        lsda::groupSegments(input, lsda::GroupingParams(d.getParams()), groups);
        // Every member of a group has its group's label: -1 for a group of one, otherwise a
        // label no other group has.
        std::set<int> used;
        for (int g = 0; g < groups.count(); g++)
        {
            const int first = groups.members[groups.offsets[g]], size = groups.offsets[g + 1] - groups.offsets[g];
            const int label = o.labels[first];
            for (int k = groups.offsets[g]; k < groups.offsets[g + 1]; k++)
                ASSERT_EQ(label, o.labels[groups.members[k]]) << "group " << g;
            if (size == 1)
                EXPECT_EQ(-1, label) << "group " << g;
            else
                EXPECT_TRUE(label >= 0 && used.insert(label).second) << "group " << g << ", label " << label;
        }
        // Numbered 0, 1, 2, ... in the order of their first segment.
        int next = 0;
        for (int label : o.labels)
            if (label >= 0 && label == next)
                next++;
            else
                ASSERT_LT(label, next);
        ASSERT_GT(next, 10);
        EXPECT_EQ((int)used.size(), next);
        EXPECT_EQ(d.getLastStats().mergeGroups, next);
    });
}

TEST(LSDAdvance_StageOutputs, merged_segments_are_mergeGroups_of_the_stage2_input)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat&, const std::vector<Vec4f>&) {
        const StageOutputs o = stageOutputsOf(d);
        const std::vector<Vec4f>& input = stage2Input(d, o);
        lsda::SegmentGroups groups;
        lsda::groupSegments(input, lsda::GroupingParams(d.getParams()), groups);
        std::vector<Vec4f> expected;
        lsda::mergeGroups(input, groups, lsda::MergingParams(d.getParams()), expected);
        EXPECT_LT(expected.size(), input.size());  // something fused
        EXPECT_TRUE(bitIdentical(expected, o.merged));
    });
}

TEST(LSDAdvance_StageOutputs, the_last_stage_output_is_detect_lines)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat& frame, const std::vector<Vec4f>& lines) {
        const StageOutputs o = stageOutputsOf(d);
        // The same set: the selection (off) orders the lines by response.
        EXPECT_TRUE(bitIdentical(asSet(lines), asSet(clippedTo(d.getStageOrder() == LSDAdvance::FILTER_THEN_MERGE
                                                                   ? o.merged
                                                                   : o.filtered,
                                                               frame.size()))));
    });
}

TEST(LSDAdvance_StageOutputs, responses_are_those_of_detect_lines)
{
    // With strong segments, a response computed by stage 1 goes on with its segment while no stage
    // changes it; a fused or clipped segment is sampled again. Either way, each line's own.
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat& frame, const std::vector<Vec4f>& lines) {
        std::vector<float> responses, expected;
        d.getLastResponses(responses);
        lsda::lineResponses(frame, lines, expected);
        EXPECT_EQ(expected, responses);
    });
}

TEST(LSDAdvance_StageOutputs, counts_match_getLastStats)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat&, const std::vector<Vec4f>& lines) {
        const StageOutputs o = stageOutputsOf(d);
        const LSDAdvanceStats stats = d.getLastStats();
        EXPECT_EQ(stats.baseSegments, (int)o.base.size());
        EXPECT_EQ(stats.filteredSegments, (int)o.filtered.size());
        EXPECT_EQ(stats.mergedSegments, (int)o.merged.size());
        EXPECT_EQ(stats.outputSegments, (int)lines.size());
        const int groupsWithTwoOrMore = o.labels.empty() ? 0 : *std::max_element(o.labels.begin(), o.labels.end()) + 1;
        EXPECT_EQ(stats.mergeGroups, groupsWithTwoOrMore);
    });
}

TEST(LSDAdvance_StageOutputs, stages_that_are_off_pass_their_input_on_and_give_no_labels)
{
    const Mat& img = buildingImage();
    ASSERT_FALSE(img.empty());
    for (int order : { (int)LSDAdvance::FILTER_THEN_MERGE, (int)LSDAdvance::MERGE_THEN_FILTER })
    {
        SCOPED_TRACE(order);
        Ptr<LSDAdvance> d = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
        d->setStageOrder(order);
        d->setMergeStrategy(LSDAdvance::MERGE_NONE);
        std::vector<Vec4f> lines;
        d->detect(img, lines);
        const StageOutputs o = stageOutputsOf(*d);
        ASSERT_GT(o.base.size(), 100u);
        EXPECT_TRUE(bitIdentical(o.base, o.filtered));
        EXPECT_TRUE(bitIdentical(o.base, o.merged));
        EXPECT_TRUE(bitIdentical(asSet(clippedTo(o.base, img.size())), asSet(lines)));
        EXPECT_TRUE(o.labels.empty());

        // Merging on again: labels come back, one per base segment with MERGE_THEN_FILTER.
        d->setMergeStrategy(LSDAdvance::MERGE_LONGEST_FIRST);
        d->detect(img, lines);
        const StageOutputs merged = stageOutputsOf(*d);
        EXPECT_EQ(stage2Input(*d, merged).size(), merged.labels.size());
        EXPECT_TRUE(bitIdentical(stage1Input(*d, merged), merged.filtered));
    }
}

TEST(LSDAdvance_StageOutputs, are_empty_before_the_first_call)
{
    Ptr<LSDAdvance> d = createLSDAdvance();
    Mat base(3, 1, CV_32FC4), filtered = base.clone(), labels(3, 1, CV_32S), merged = base.clone();
    d->getLastStageOutputs(base, filtered, labels, merged);
    EXPECT_TRUE(base.empty());
    EXPECT_TRUE(filtered.empty());
    EXPECT_TRUE(labels.empty());
    EXPECT_TRUE(merged.empty());
}

TEST(LSDAdvance_StageOutputs, output_types_are_CV_32FC4_and_CV_32S_columns)
{
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->detect(buildingImage(), lines);
    Mat base, filtered, labels, merged;
    d->getLastStageOutputs(base, filtered, labels, merged);
    for (const Mat* m : { &base, &filtered, &merged })
    {
        EXPECT_EQ(CV_32FC4, m->type());
        EXPECT_EQ(1, m->cols);
    }
    EXPECT_EQ(CV_32SC1, labels.type());
    EXPECT_EQ(1, labels.cols);
    EXPECT_EQ(base.rows, labels.rows);  // MERGE_THEN_FILTER: stage 2 takes the base segments
}

TEST(LSDAdvance_StageOutputs, processSegments_reports_its_input_as_base_segments)
{
    // Two collinear pieces that fuse and one short segment far away that the filter drops.
    const std::vector<Vec4f> segments = { segmentAt(0, 0, 0, 100), segmentAt(102, 0, 0, 100),
                                          segmentAt(0, 200, 90, 3), segmentAt(300, 0, 90, 80) };
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->processSegments(segments, lines);
    const StageOutputs o = stageOutputsOf(*d);
    EXPECT_TRUE(bitIdentical(segments, o.base));
    EXPECT_EQ(std::vector<int>({ 0, 0, -1, -1 }), o.labels);
    EXPECT_EQ(3u, o.merged.size());
    EXPECT_TRUE(bitIdentical(lines, o.filtered));
    EXPECT_EQ(2u, lines.size());
}

TEST(LSDAdvance_StageOutputs, a_rejected_call_keeps_the_previous_outputs)
{
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->detect(buildingImage(), lines);
    const StageOutputs before = stageOutputsOf(*d);
    const std::vector<Vec4f> bad = { Vec4f(0, 0, std::numeric_limits<float>::quiet_NaN(), 10) };
    EXPECT_THROW(d->processSegments(bad, lines), cv::Exception);
    EXPECT_THROW(d->detect(Mat(10, 10, CV_32FC1, Scalar(0)), lines), cv::Exception);
    const StageOutputs after = stageOutputsOf(*d);
    EXPECT_TRUE(bitIdentical(before.base, after.base));
    EXPECT_TRUE(bitIdentical(before.filtered, after.filtered));
    EXPECT_TRUE(bitIdentical(before.merged, after.merged));
    EXPECT_EQ(before.labels, after.labels);
}

// The sources of each returned line, as std::vector<std::vector<int> >.
std::vector<std::vector<int> > sourcesOf(const LSDAdvance& d)
{
    std::vector<std::vector<int> > sources;
    d.getLastSources(sources);
    return sources;
}

TEST(LSDAdvance_StageOutputs, sources_partition_the_base_segments_that_reach_the_output)
{
    forEachFrameOfBothOrders([](const LSDAdvance& d, const Mat& frame, const std::vector<Vec4f>& lines) {
        const StageOutputs o = stageOutputsOf(d);
        const std::vector<std::vector<int> > sources = sourcesOf(d);
        ASSERT_EQ(lines.size(), sources.size());
        std::vector<int> used(o.base.size(), 0);
        size_t fused = 0;
        for (size_t j = 0; j < sources.size(); j++)
        {
            ASSERT_FALSE(sources[j].empty()) << j;
            EXPECT_TRUE(std::is_sorted(sources[j].begin(), sources[j].end()));
            for (int i : sources[j])
            {
                ASSERT_GE(i, 0);
                ASSERT_LT(i, (int)o.base.size());
                used[i]++;
            }
            fused += sources[j].size() > 1;
        }
        EXPECT_EQ(0, std::count_if(used.begin(), used.end(), [](int n) { return n > 1; }));
        EXPECT_GT(fused, 10u);
        // A line made of one base segment is that segment (clipped when it reached past the image).
        for (size_t j = 0; j < sources.size(); j++)
            if (sources[j].size() == 1)
            {
                Vec4f clipped;
                ASSERT_TRUE(lsda::clipToDomain(o.base[sources[j][0]], frame.size(), clipped));
                EXPECT_EQ(clipped, lines[j]);
            }
    });
}

TEST(LSDAdvance_StageOutputs, sources_of_a_fused_edge_are_its_pieces)
{
    // Bright bars whose top edges are collinear pieces of one line: merging joins them into one
    // line, made of exactly the base pieces along that line.
    Mat img(240, 640, CV_8UC1, Scalar(40));
    for (int x = 40; x < 580; x += 108)  // top edges 6 px apart, closer than endpointDistance
        rectangle(img, Point(x, 100), Point(x + 103, 239), Scalar(200), FILLED);
    for (int order : { (int)LSDAdvance::FILTER_THEN_MERGE, (int)LSDAdvance::MERGE_THEN_FILTER })
    {
        SCOPED_TRACE(order);
        Ptr<LSDAdvance> d = createLSDAdvance();
        d->setStageOrder(order);
        std::vector<Vec4f> lines;
        d->detect(img, lines);
        const StageOutputs o = stageOutputsOf(*d);
        const std::vector<std::vector<int> > sources = sourcesOf(*d);
        const auto onTop = [](const Vec4f& s) { return std::abs(s[1] - 99.5f) < 1.5f && std::abs(s[3] - 99.5f) < 1.5f; };
        std::vector<int> pieces;
        for (size_t i = 0; i < o.base.size(); i++)
            if (onTop(o.base[i]))
                pieces.push_back((int)i);
        ASSERT_GE(pieces.size(), 5u);
        int topLines = 0;
        for (size_t j = 0; j < lines.size(); j++)
            if (onTop(lines[j]) && lsda::segmentLength(lines[j]) > 400)
            {
                topLines++;
                EXPECT_EQ(pieces, sources[j]);
            }
        EXPECT_EQ(1, topLines);
    }
}

TEST(LSDAdvance_StageOutputs, sources_are_each_segment_itself_when_no_stage_runs)
{
    std::vector<Vec4f> segments = { Vec4f(0, 0, 50, 0), Vec4f(0, 10, 0, 60), Vec4f(100, 100, 140, 130) };
    Ptr<LSDAdvance> d = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    d->setMergeStrategy(LSDAdvance::MERGE_NONE);
    std::vector<Vec4f> lines;
    d->processSegments(segments, lines);
    const std::vector<std::vector<int> > expected = { { 0 }, { 1 }, { 2 } };
    EXPECT_EQ(expected, sourcesOf(*d));
    // Clipped away: the third segment lies outside a 90 x 90 image.
    d->processSegments(segments, lines, Size(90, 90));
    const std::vector<std::vector<int> > inside = { { 0 }, { 1 } };
    EXPECT_EQ(inside, sourcesOf(*d));
    EXPECT_EQ(2u, lines.size());
    EXPECT_TRUE(sourcesOf(*createLSDAdvance()).empty());
}

TEST(LSDAdvance_StageOutputs, drawSegments_draws_like_LineSegmentDetector)
{
    const Mat& img = buildingImage();
    Ptr<LSDAdvance> d = createLSDAdvance();
    std::vector<Vec4f> lines;
    d->detect(img, lines);
    Mat ours = img.clone(), lsds = img.clone();
    d->drawSegments(ours, lines);
    createLineSegmentDetector()->drawSegments(lsds, lines);
    ASSERT_EQ(CV_8UC3, ours.type());
    EXPECT_EQ(0, cvtest::norm(ours, lsds, NORM_INF));
    Mat colour;
    cvtColor(img, colour, COLOR_GRAY2BGR);
    d->drawSegments(colour, lines);
    EXPECT_EQ(0, cvtest::norm(colour, lsds, NORM_INF));
    for (const Mat& bad : { Mat(), Mat(10, 10, CV_8UC2), Mat(10, 10, CV_32FC1), Mat(10, 10, CV_8UC4) })
    {
        Mat image = bad.clone();
        EXPECT_THROW(d->drawSegments(image, lines), cv::Exception) << typeToString(bad.type());
    }
    // Every layout detect() writes, float or int, as LineSegmentDetector draws it.
    std::vector<Vec4i> rounded;
    d->detect(img, rounded);
    const Mat ints(rounded);
    const std::vector<std::pair<const char*, Mat> > layouts = {
        { "N x 4 CV_32FC1", Mat(lines).reshape(1, (int)lines.size()) }, { "N x 1 CV_32SC4", ints },
        { "N x 4 CV_32SC1", ints.reshape(1, ints.rows) }, { "1 x N CV_32FC4", Mat(lines).t() } };
    for (const auto& layout : layouts)
    {
        Mat drawn = img.clone(), expected = img.clone();
        d->drawSegments(drawn, layout.second);
        createLineSegmentDetector()->drawSegments(expected, layout.second);
        ASSERT_EQ(CV_8UC3, drawn.type()) << layout.first;
        EXPECT_EQ(0, cvtest::norm(drawn, expected, NORM_INF)) << layout.first;
    }
    Mat drawn = img.clone(), expected = img.clone();
    d->drawSegments(drawn, rounded);
    createLineSegmentDetector()->drawSegments(expected, rounded);
    EXPECT_EQ(0, cvtest::norm(drawn, expected, NORM_INF)) << "std::vector<Vec4i>";
    for (const Mat& bad : { Mat(3, 5, CV_32FC1), Mat(3, 2, CV_32FC4), Mat(3, 1, CV_64FC4), Mat(3, 4, CV_8UC1) })
    {
        Mat image = img.clone();
        EXPECT_THROW(d->drawSegments(image, bad), cv::Exception) << typeToString(bad.type()) << " " << bad.size();
        EXPECT_EQ(CV_8UC1, image.type());  // refused before the image is converted
    }
}

}} // namespace
