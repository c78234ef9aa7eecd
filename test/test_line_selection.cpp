// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The selection after the clipping: the order of the output (strongest first in detect, longest
// first in processSegments), the minimum length and the budget, the responses of the last call,
// the frame count of a sequence, and the front-end preset.

#include "test_precomp.hpp"
#include "../src/parameters.hpp"

namespace opencv_test { namespace {

Mat building()
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

std::vector<Vec4f> longerThan(const std::vector<Vec4f>& lines, double minLength)
{
    std::vector<Vec4f> kept;
    for (const Vec4f& l : lines)
        if (lsda::segmentLength(l) >= minLength)
            kept.push_back(l);
    return kept;
}

TEST(LSDAdvance_Selection, min_length_is_the_larger_of_the_two_and_the_ratio_needs_the_image_size)
{
    LSDAdvance::Params p;
    EXPECT_EQ(0.0, lsda::selectionMinLength(lsda::SelectionParams(p), Size(640, 480)));
    p.minLineLength = 30;
    EXPECT_EQ(30.0, lsda::selectionMinLength(lsda::SelectionParams(p), Size(640, 480)));
    p.minLineLengthRatio = 0.125;  // 60 px of min(640, 480)
    EXPECT_EQ(60.0, lsda::selectionMinLength(lsda::SelectionParams(p), Size(640, 480)));
    EXPECT_EQ(30.0, lsda::selectionMinLength(lsda::SelectionParams(p), Size(640, 200)));
    EXPECT_EQ(30.0, lsda::selectionMinLength(lsda::SelectionParams(p), Size()));
}

TEST(LSDAdvance_Selection, strongestFirst_orders_by_decreasing_key_ties_by_index_and_cuts_to_the_budget)
{
    const std::vector<float> keys = { 0.5f, 2.f, 0.5f, 3.f, 1.f };
    std::vector<int> order = { 0, 1, 2, 3, 4 };
    lsda::strongestFirst(keys, 0, order);
    EXPECT_EQ(std::vector<int>({ 3, 1, 4, 0, 2 }), order);
    order = { 0, 1, 2, 3, 4 };
    lsda::strongestFirst(keys, 2, order);
    EXPECT_EQ(std::vector<int>({ 3, 1 }), order);
    order = { 4, 2, 0 };  // a subset, in any order
    lsda::strongestFirst(keys, 10, order);
    EXPECT_EQ(std::vector<int>({ 4, 0, 2 }), order);
}

TEST(LSDAdvance_Selection, detect_returns_the_lines_strongest_first_with_their_responses)
{
    const Mat img = building();
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<float> none;
    detector->getLastResponses(none);
    EXPECT_TRUE(none.empty());
    std::vector<Vec4f> lines;
    detector->detect(img, lines);
    ASSERT_GT(lines.size(), 50u);
    std::vector<float> responses, expected;
    detector->getLastResponses(responses);
    computeLineResponses(img, lines, expected);
    ASSERT_EQ(lines.size(), responses.size());
    for (size_t i = 0; i < lines.size(); i++)
    {
        EXPECT_EQ(expected[i], responses[i]) << i;
        if (i > 0)
        {
            EXPECT_GE(responses[i - 1], responses[i]) << i;
        }
    }
    EXPECT_GT(responses.front(), responses.back());
}

TEST(LSDAdvance_Selection, by_default_the_lines_are_the_set_of_the_stages_output)
{
    // The selection off (the defaults) only orders: the set is the clipped output of the stages.
    const Mat img = building();
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines, base, filtered, merged, clipped;
    std::vector<int> labels, keptFrom;
    detector->detect(img, lines);
    detector->getLastStageOutputs(base, filtered, labels, merged);
    lsda::clipToImage(filtered, img.size(), clipped, keptFrom);  // MERGE_THEN_FILTER: the filter is last
    EXPECT_NE(clipped, lines);  // ordered otherwise
    EXPECT_EQ(asSet(clipped), asSet(lines));
}

TEST(LSDAdvance_Selection, minimum_length_drops_exactly_the_shorter_lines)
{
    const Mat img = building();
    std::vector<Vec4f> all;
    createLSDAdvance()->detect(img, all);

    Ptr<LSDAdvance> absolute = createLSDAdvance();
    absolute->setMinLineLength(40);
    std::vector<Vec4f> lines;
    absolute->detect(img, lines);
    EXPECT_LT(lines.size(), all.size());
    EXPECT_EQ(longerThan(all, 40), lines);  // the same order, fewer lines
    EXPECT_EQ((int)lines.size(), absolute->getLastStats().outputSegments);

    const double side = std::min(img.cols, img.rows);
    Ptr<LSDAdvance> relative = createLSDAdvance();
    relative->setMinLineLengthRatio(0.125);
    relative->detect(img, lines);
    EXPECT_EQ(longerThan(all, 0.125 * side), lines);

    // Both: the larger threshold.
    relative->setMinLineLength(100);
    relative->detect(img, lines);
    EXPECT_EQ(longerThan(all, 100), lines);
    relative->setMinLineLength(10);
    relative->detect(img, lines);
    EXPECT_EQ(longerThan(all, 0.125 * side), lines);
}

TEST(LSDAdvance_Selection, budget_keeps_the_strongest_lines)
{
    const Mat img = building();
    std::vector<Vec4f> all;
    std::vector<float> allResponses;
    Ptr<LSDAdvance> reference = createLSDAdvance();
    reference->detect(img, all);
    reference->getLastResponses(allResponses);
    ASSERT_GT(all.size(), 60u);

    Ptr<LSDAdvance> budget = createLSDAdvance();
    budget->setMaxLines(60);
    std::vector<Vec4f> lines;
    std::vector<float> responses;
    budget->detect(img, lines);
    budget->getLastResponses(responses);
    EXPECT_EQ(std::vector<Vec4f>(all.begin(), all.begin() + 60), lines);
    EXPECT_EQ(std::vector<float>(allResponses.begin(), allResponses.begin() + 60), responses);
    std::vector<std::vector<int> > sources;
    budget->getLastSources(sources);
    EXPECT_EQ(60u, sources.size());

    // A budget larger than the lines keeps them all; with a minimum length, the strongest long ones.
    budget->setMaxLines((int)all.size() + 10);
    budget->detect(img, lines);
    EXPECT_EQ(all, lines);
    budget->setMaxLines(20);
    budget->setMinLineLength(60);
    budget->detect(img, lines);
    const std::vector<Vec4f> longOnes = longerThan(all, 60);
    ASSERT_GT(longOnes.size(), 20u);
    EXPECT_EQ(std::vector<Vec4f>(longOnes.begin(), longOnes.begin() + 20), lines);
}

TEST(LSDAdvance_Selection, processSegments_returns_the_lines_longest_first_without_responses)
{
    const std::vector<Vec4f> segments = { segmentAt(10, 10, 0, 20), segmentAt(10, 50, 0, 80), segmentAt(10, 90, 0, 50),
                                          segmentAt(200, 10, 90, 35) };
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    std::vector<Vec4f> lines;
    detector->processSegments(segments, lines);
    EXPECT_EQ(std::vector<Vec4f>({ segments[1], segments[2], segments[3], segments[0] }), lines);
    std::vector<float> responses;
    detector->getLastResponses(responses);
    EXPECT_TRUE(responses.empty());

    // The ratio needs imageSize; the budget applies either way.
    detector->setMinLineLengthRatio(0.25);
    detector->setMaxLines(2);
    detector->processSegments(segments, lines);
    EXPECT_EQ(std::vector<Vec4f>({ segments[1], segments[2] }), lines);
    detector->processSegments(segments, lines, Size(400, 160));  // 40 px
    EXPECT_EQ(std::vector<Vec4f>({ segments[1], segments[2] }), lines);
    detector->setMaxLines(0);
    detector->processSegments(segments, lines, Size(400, 160));
    EXPECT_EQ(std::vector<Vec4f>({ segments[1], segments[2] }), lines);
    detector->setMinLineLengthRatio(0);
    detector->setMinLineLength(30);
    detector->processSegments(segments, lines);
    EXPECT_EQ(std::vector<Vec4f>({ segments[1], segments[2], segments[3] }), lines);
}

TEST(LSDAdvance_Selection, parameters_reject_values_out_of_range_naming_them)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    EXPECT_THROW(detector->setMinLineLength(-1), cv::Exception);
    EXPECT_THROW(detector->setMinLineLengthRatio(1.5), cv::Exception);
    EXPECT_THROW(detector->setMaxLines(-1), cv::Exception);
    try
    {
        detector->setMaxLines(-3);
        FAIL() << "no exception";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find("maxLines")) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("0 (all)")) << e.err;
    }
    EXPECT_EQ(0, detector->getMaxLines());
    EXPECT_EQ(0.0, detector->getMinLineLength());
    EXPECT_EQ(0.0, detector->getMinLineLengthRatio());
}

TEST(LSDAdvance_Selection, frameInSequence_counts_the_calls_of_one_object_until_a_reset)
{
    const Mat img = building();
    Ptr<LSDAdvance> detector = createLSDAdvance(LSDAdvance::PRESET_SEQUENCE);
    std::vector<Vec4f> lines;
    for (int k = 0; k < 3; k++)
    {
        detector->detect(img, lines);
        EXPECT_EQ(k, detector->getLastStats().frameInSequence);
    }
    detector->reset();
    detector->detect(img, lines);
    EXPECT_EQ(0, detector->getLastStats().frameInSequence);
    detector->detect(img, lines);
    detector->setMaxLines(10);  // a setter starts a new sequence
    detector->detect(img, lines);
    EXPECT_EQ(0, detector->getLastStats().frameInSequence);
    // A detector made anew each frame never leaves the first frame.
    for (int k = 0; k < 3; k++)
    {
        Ptr<LSDAdvance> perFrame = createLSDAdvance(LSDAdvance::PRESET_SEQUENCE);
        perFrame->detect(img, lines);
        EXPECT_EQ(0, perFrame->getLastStats().frameInSequence);
        EXPECT_EQ(1.0, perFrame->getLastStats().alpha);
    }
}

TEST(LSDAdvance_Selection, front_end_preset_keeps_60_lines_spread_across_directions)
{
    const Ptr<LSDAdvance> frontEnd = createLSDAdvance(LSDAdvance::PRESET_FRONT_END);
    EXPECT_EQ(60, frontEnd->getMaxLines());
    EXPECT_EQ(LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS, frontEnd->getLineOrder());
    EXPECT_EQ(4, frontEnd->getDirectionBins());
    EXPECT_EQ(2, frontEnd->getGridCells());
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_ADAPTIVE, frontEnd->getLengthFilterMode());  // stateless
    EXPECT_EQ(LSDAdvance::SMOOTH_EVERY_IMAGE, frontEnd->getLSDParams().fullScaleSmoothing);

    // Otherwise the defaults.
    Ptr<LSDAdvance> reverted = createLSDAdvance(LSDAdvance::PRESET_FRONT_END);
    reverted->setMaxLines(0);
    reverted->setLineOrder(LSDAdvance::LINE_ORDER_STRONGEST);
    reverted->setGridCells(1);
    const LSDAdvance::Params a = reverted->getParams(), b;
    for (const lsda::Field<LSDAdvance::Params>& f : lsda::fieldsOf<LSDAdvance::Params>())
        EXPECT_EQ(f.get(b), f.get(a)) << f.name;
    LSDAdvance::LSDParams c = reverted->getLSDParams();
    c.fullScaleSmoothing = LSDAdvance::SMOOTH_ALIASED_IMAGES;
    const LSDAdvance::LSDParams d;
    for (const lsda::Field<LSDAdvance::LSDParams>& f : lsda::fieldsOf<LSDAdvance::LSDParams>())
        EXPECT_EQ(f.get(d), f.get(c)) << f.name;

    // Its lines: the defaults' lines of the smoothed image in the order across directions in each
    // quarter of the image, cut to 60.
    const Mat img = building();
    std::vector<Vec4f> lines, all;
    frontEnd->detect(img, lines);
    EXPECT_EQ(60u, lines.size());
    Ptr<LSDAdvance> smoothing = createLSDAdvance();
    LSDAdvance::LSDParams lsdParams = smoothing->getLSDParams();
    lsdParams.fullScaleSmoothing = LSDAdvance::SMOOTH_EVERY_IMAGE;
    smoothing->setLSDParams(lsdParams);
    smoothing->detect(img, all);
    std::vector<int> order(all.size()), scratch;
    for (size_t i = 0; i < order.size(); i++)
        order[i] = (int)i;
    lsda::acrossDirections(all, 4, 2, Rect2f(0.f, 0.f, (float)img.cols, (float)img.rows), 60, order, scratch);
    ASSERT_EQ(60u, order.size());
    for (size_t i = 0; i < order.size(); i++)
        EXPECT_EQ(all[order[i]], lines[i]) << i;
    std::vector<Vec4f> again;
    frontEnd->detect(img, again);
    EXPECT_EQ(lines, again);  // stateless
}

// The bin of a segment among `bins` bins of its undirected direction, the first centred on 0 degrees.
int directionBin(const Vec4f& l, int bins)
{
    const double turned = std::fmod(undirectedAngle(l) + 90.0 / bins, 180.0);
    return std::min(bins - 1, (int)(turned * bins / 180.0));
}

TEST(LSDAdvance_Selection, across_directions_takes_the_strongest_of_each_bin_then_the_next_of_each)
{
    // Strongest first: five near-horizontal lines, then two vertical, then one diagonal.
    const std::vector<Vec4f> lines = { segmentAt(0, 0, 1, 90), segmentAt(0, 10, -2, 80), segmentAt(0, 20, 179, 70),
                                       segmentAt(0, 30, 3, 60), segmentAt(0, 40, 0, 50), segmentAt(0, 0, 90, 40),
                                       segmentAt(0, 0, -89, 30), segmentAt(0, 0, 45, 20) };
    std::vector<int> order = { 0, 1, 2, 3, 4, 5, 6, 7 }, scratch;
    lsda::acrossDirections(lines, 4, 1, Rect2f(), 0, order, scratch);
    // Four bins centred on 0, 45, 90 and 135 degrees: the horizontal one holds the lines either
    // side of it (1, 178, 179, 3, 0 deg), then 90 and 91 deg, then 45 deg.
    EXPECT_EQ(std::vector<int>({ 0, 5, 7, 1, 6, 2, 3, 4 }), order);
    // With six bins too: the horizontal bin holds the lines either side of the horizontal.
    std::vector<int> six = { 0, 1, 2, 3, 4, 5, 6, 7 };
    lsda::acrossDirections(lines, 6, 1, Rect2f(), 0, six, scratch);
    EXPECT_EQ(std::vector<int>({ 0, 5, 7, 1, 6, 2, 3, 4 }), six);
    // A direction and its opposite are one: a horizontal line pointing left is in bin 0.
    std::vector<int> opposite = { 0, 1 }, scratchOpposite;
    lsda::acrossDirections({ segmentAt(50, 0, 180, 10), segmentAt(0, 5, 0, 5) }, 4, 1, Rect2f(), 0, opposite, scratchOpposite);
    EXPECT_EQ(std::vector<int>({ 0, 1 }), opposite);
    EXPECT_EQ(0, scratchOpposite[0]);
    EXPECT_EQ(1, scratchOpposite[1]);
    // The first N are the budget of N: a prefix of the order of all of them.
    std::vector<int> budget = { 0, 1, 2, 3, 4, 5, 6, 7 };
    lsda::acrossDirections(lines, 4, 1, Rect2f(), 5, budget, scratch);
    EXPECT_EQ(std::vector<int>(order.begin(), order.begin() + 5), budget);
    // One bin: the strongest-first order.
    std::vector<int> one = { 0, 1, 2, 3, 4, 5, 6, 7 };
    lsda::acrossDirections(lines, 1, 1, Rect2f(), 0, one, scratch);
    EXPECT_EQ(std::vector<int>({ 0, 1, 2, 3, 4, 5, 6, 7 }), one);
}

TEST(LSDAdvance_Selection, across_directions_spreads_a_budget_over_the_bins_of_real_lines)
{
    const Mat img = building();
    // (direction bins, grid cells per side)
    for (const Vec2i& config : { Vec2i(2, 1), Vec2i(6, 1), Vec2i(12, 1), Vec2i(4, 2), Vec2i(4, 3) })
    {
        const int directions = config[0], cells = config[1], bins = directions * cells * cells;
        SCOPED_TRACE(cv::format("%d direction bins, %d x %d cells", directions, cells, cells));
        Ptr<LSDAdvance> spread = createLSDAdvance();
        spread->setLineOrder(LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS);
        spread->setDirectionBins(directions);
        spread->setGridCells(cells);
        std::vector<Vec4f> all, strongest, lines;
        spread->detect(img, all);
        createLSDAdvance()->detect(img, strongest);
        EXPECT_EQ(asSet(strongest), asSet(all));  // without a budget, only the order changes
        const int budget = std::min(3 * bins, (int)all.size() / 2);
        spread->setMaxLines(budget);
        spread->detect(img, lines);
        ASSERT_EQ((size_t)budget, lines.size());
        EXPECT_EQ(std::vector<Vec4f>(all.begin(), all.begin() + budget), lines);
        EXPECT_NE(std::vector<Vec4f>(strongest.begin(), strongest.begin() + budget), lines);
        // Every bin gives its strongest lines, as many as the budget has for each bin, or all it
        // holds (the others fill the budget). A bin: a direction in the cell of the midpoint.
        const auto binOf = [&](const Vec4f& l) {
            const int column = std::min(cells - 1, (int)(0.5 * (l[0] + l[2]) * cells / img.cols));
            const int row = std::min(cells - 1, (int)(0.5 * (l[1] + l[3]) * cells / img.rows));
            return (row * cells + column) * directions + directionBin(l, directions);
        };
        std::vector<int> available(bins, 0), taken(bins, 0);
        for (const Vec4f& l : all)
            available[binOf(l)]++;
        for (const Vec4f& l : lines)
            taken[binOf(l)]++;
        const int perBin = budget / bins;
        for (int b = 0; b < bins; b++)
            EXPECT_GE(taken[b], std::min(perBin, available[b])) << "bin " << b;
        // The responses follow the lines: each that of its line.
        std::vector<float> responses, expected;
        spread->getLastResponses(responses);
        computeLineResponses(img, lines, expected);
        EXPECT_EQ(expected, responses);
    }
}

TEST(LSDAdvance_Selection, grid_cells_take_the_strongest_of_each_direction_in_each_cell)
{
    // Strongest first, in a 200 x 100 area: three horizontal lines with midpoints in its top-left
    // quarter, one horizontal in the top-right, one vertical in the top-left, one horizontal in the
    // bottom-right.
    const std::vector<Vec4f> lines = { segmentAt(10, 10, 0, 60), segmentAt(10, 20, 0, 60), segmentAt(10, 30, 0, 60),
                                       segmentAt(120, 10, 0, 60), segmentAt(50, 2, 90, 40),
                                       segmentAt(120, 80, 0, 60) };
    const Rect2f area(0.f, 0.f, 200.f, 100.f);
    std::vector<int> order = { 0, 1, 2, 3, 4, 5 }, scratch;
    lsda::acrossDirections(lines, 4, 2, area, 0, order, scratch);
    // The first of each (cell, direction) bin, then the second of the top-left horizontal one.
    EXPECT_EQ(std::vector<int>({ 0, 3, 4, 5, 1, 2 }), order);
    // One cell: the directions alone.
    std::vector<int> one = { 0, 1, 2, 3, 4, 5 };
    lsda::acrossDirections(lines, 4, 1, area, 0, one, scratch);
    EXPECT_EQ(std::vector<int>({ 0, 4, 1, 2, 3, 5 }), one);
    // The cells are those of the area: moved by its offset, the same lines fall in other cells; a
    // midpoint outside the area counts in the nearest cell.
    std::vector<int> moved = { 0, 1, 2, 3, 4, 5 };
    lsda::acrossDirections(lines, 4, 2, Rect2f(-100.f, -50.f, 200.f, 100.f), 0, moved, scratch);
    EXPECT_EQ(std::vector<int>({ 0, 4, 1, 2, 3, 5 }), moved);  // all in the bottom-right cell
}

// A detector whose processSegments() returns the given segments themselves (no filter, no merging)
// in LINE_ORDER_ACROSS_DIRECTIONS, the first maxLines.
Ptr<LSDAdvance> segmentsAcrossDirections(int maxLines)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    detector->setMergeStrategy(LSDAdvance::MERGE_NONE);
    detector->setLengthFilterMode(LSDAdvance::LENGTH_FILTER_NONE);
    detector->setLineOrder(LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS);
    detector->setMaxLines(maxLines);
    return detector;
}

TEST(LSDAdvance_Selection, grid_cells_of_process_segments_cover_the_segments)
{
    // Without an image, the grid is on the segments' bounding box, here far from the origin: the
    // four longest horizontal segments in its top-left quarter, one shorter in each other quarter.
    const std::vector<Vec4f> segments = { segmentAt(1000, 1000, 0, 100), segmentAt(1000, 1002, 0, 98),
                                          segmentAt(1000, 1004, 0, 96), segmentAt(1000, 1006, 0, 94),
                                          segmentAt(1200, 1000, 0, 50), segmentAt(1000, 1100, 0, 50),
                                          segmentAt(1200, 1100, 0, 50) };
    Ptr<LSDAdvance> detector = segmentsAcrossDirections(4);
    std::vector<Vec4f> lines;
    detector->processSegments(segments, lines);
    EXPECT_EQ(std::vector<Vec4f>(segments.begin(), segments.begin() + 4), lines);  // one cell: the longest
    detector->setGridCells(2);
    detector->processSegments(segments, lines);
    EXPECT_EQ(asSet({ segments[0], segments[4], segments[5], segments[6] }), asSet(lines));  // one per quarter
}

TEST(LSDAdvance_Selection, across_directions_orders_process_segments_by_length_within_the_bins)
{
    const std::vector<Vec4f> segments = { segmentAt(10, 10, 0, 100), segmentAt(10, 30, 0, 90), segmentAt(10, 50, 90, 40),
                                          segmentAt(200, 10, 90, 30) };
    Ptr<LSDAdvance> detector = segmentsAcrossDirections(2);
    std::vector<Vec4f> lines;
    detector->processSegments(segments, lines);
    EXPECT_EQ(std::vector<Vec4f>({ segments[0], segments[2] }), lines);
}


}} // namespace
