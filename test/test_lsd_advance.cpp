// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

const int kDark = 40, kBright = 210;

// Dark image with a bright block whose top edge (y = 99.5, x in [19.5, 579.5]) is broken by
// bright notches at the given columns, so that LSD sees collinear pieces.
Mat brokenEdgeImage(const std::vector<int>& notches)
{
    Mat img(300, 640, CV_8UC1, Scalar(kDark));
    rectangle(img, Rect(20, 100, 560, 100), Scalar(kBright), FILLED);
    for (int x : notches)
        rectangle(img, Rect(x, 80, 3, 20), Scalar(kBright), FILLED);
    return img;
}

// Segments near the line y = 99.5 and within 5 deg of horizontal.
std::vector<Vec4f> onTopEdge(const std::vector<Vec4f>& lines)
{
    std::vector<Vec4f> found;
    for (const Vec4f& l : lines)
    {
        const double a = undirectedAngle(l);
        if (std::abs(l[1] - 99.5) < 2 && std::abs(l[3] - 99.5) < 2 && (a < 5 || a > 175))
            found.push_back(l);
    }
    return found;
}

std::vector<Vec4f> detectLines(const Ptr<LSDAdvance>& detector, const Mat& image)
{
    std::vector<Vec4f> lines;
    detector->detect(image, lines);
    return lines;
}

// OpenCV's LSD with its defaults: the detector LSDAdvance is compared with.
std::vector<Vec4f> detectLsd(const Mat& image)
{
    std::vector<Vec4f> lines;
    createLineSegmentDetector()->detect(image, lines);
    return lines;
}

// The default base (the module's own LSD) alone, with a default LSDAdvance's parameters: its stage 0.
std::vector<Vec4f> detectBase(const Mat& image)
{
    const Ptr<LSDAdvance> d = createLSDAdvance();
    EXPECT_EQ(LSDAdvance::BASE_FAST_LSD, d->getBaseDetector());
    std::vector<Vec4f> lines;
    lsda::createBaseDetector(LSDAdvance::BASE_FAST_LSD, d->getLSDParams(), d->getFLDParams(), d->getEDLinesParams())
        ->detect(image, lines);
    return lines;
}

Mat buildingImage()
{
    Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

// A grid of 12 bright 110 x 90 blocks with 150 short (12 px) strokes of clutter over them.
Mat clutterImage(uint64 seed)
{
    Mat img(480, 640, CV_8UC1, Scalar(kDark));
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 4; col++)
            rectangle(img, Rect(30 + col * 150, 30 + row * 150, 110, 90), Scalar(kBright), FILLED);
    RNG rng(seed);
    for (int i = 0; i < 150; i++)
    {
        const Point p(rng.uniform(0, img.cols), rng.uniform(0, img.rows));
        const double a = rng.uniform(0., CV_PI);
        const Point q = p + Point(cvRound(12 * std::cos(a)), cvRound(12 * std::sin(a)));
        line(img, p, q, Scalar(rng.uniform(0, 2) ? kBright : kDark), 3);
    }
    return img;
}

TEST(LSDAdvance_Detect, output_is_Nx1_CV_32FC4)
{
    Mat lines;
    createLSDAdvance()->detect(brokenEdgeImage({}), lines);
    EXPECT_EQ(CV_32FC4, lines.type());
    EXPECT_EQ(1, lines.cols);
    EXPECT_GT(lines.rows, 0);
}

TEST(LSDAdvance_Detect, broken_long_edge_comes_out_as_one_segment)
{
    // The base detector returns the broken edge in three collinear pieces (about 278, 117 and 155 px).
    const Mat broken = brokenEdgeImage({ 300, 420 });
    ASSERT_EQ(3u, onTopEdge(detectBase(broken)).size());

    const std::vector<Vec4f> edge = onTopEdge(detectLines(createLSDAdvance(), broken));
    ASSERT_EQ(1u, edge.size());
    // The reference is the base detector's segment on the same edge without the breaks.
    const std::vector<Vec4f> whole = onTopEdge(detectBase(brokenEdgeImage({})));
    ASSERT_EQ(1u, whole.size());
    for (int i = 0; i < 4; i++)
        EXPECT_NEAR(whole[0][i], edge[0][i], 1.0) << "coordinate " << i;
    // Geometric truth: the step between rows 99 and 100, from x = 19.5 to 579.5.
    EXPECT_NEAR(99.5, edge[0][1], 1.0);
    EXPECT_NEAR(99.5, edge[0][3], 1.0);
    EXPECT_NEAR(560.0, lsda::segmentLength(edge[0]), 3.0);
}

TEST(LSDAdvance_Detect, segments_keep_LSD_orientation_bright_side_on_the_left)
{
    // Dark above, bright below the top edge: LSD points it towards -x; so must the merged one.
    const std::vector<Vec4f> edge = onTopEdge(detectLines(createLSDAdvance(), brokenEdgeImage({ 300, 420 })));
    ASSERT_EQ(1u, edge.size());
    EXPECT_GT(edge[0][0], edge[0][2]);
    const std::vector<Vec4f> basePieces = onTopEdge(detectBase(brokenEdgeImage({ 300, 420 })));
    for (const Vec4f& piece : basePieces)
        EXPECT_GT(piece[0], piece[2]);
}

TEST(LSDAdvance_Detect, short_clutter_is_removed_and_long_edges_stay)
{
    // On OpenCV's default LSD as the base, which sees the 12 px strokes.
    const Mat img = clutterImage(42);
    Ptr<LSDAdvance> detector = createLSDAdvance();
    detector->setBaseDetector(LSDAdvance::BASE_LSD);
    detector->setLSDParams(createLSDAdvance(LSDAdvance::PRESET_PAPER)->getLSDParams());
    const std::vector<Vec4f> lines = detectLines(detector, img);
    const LSDAdvanceStats stats = detector->getLastStats();
    const std::vector<Vec4f> base = detectLsd(img);
    ASSERT_GT(stats.minLength, 6.0);
    size_t shortInBase = 0;
    for (const Vec4f& l : base)
        shortInBase += lsda::segmentLength(l) < stats.minLength;
    ASSERT_GT(shortInBase, 100u);
    for (const Vec4f& l : lines)
        EXPECT_GE(lsda::segmentLength(l), stats.minLength) << l;
    EXPECT_LT(lines.size(), base.size() / 2);
    // No long block edge is lost.
    const auto longOnes = [](const std::vector<Vec4f>& v) {
        return std::count_if(v.begin(), v.end(), [](const Vec4f& l) { return lsda::segmentLength(l) >= 80; });
    };
    EXPECT_GE(longOnes(lines), longOnes(base));
    EXPECT_GE(longOnes(lines), 20);
}

TEST(LSDAdvance_Detect, stats_report_every_stage_in_the_paper_order)
{
    const Mat img = clutterImage(7);
    Ptr<LSDAdvance> detector = createLSDAdvance();
    detector->setStageOrder(LSDAdvance::FILTER_THEN_MERGE);
    const std::vector<Vec4f> lines = detectLines(detector, img);
    const LSDAdvanceStats stats = detector->getLastStats();
    const std::vector<Vec4f> base = detectBase(img);
    EXPECT_EQ((int)base.size(), stats.baseSegments);
    EXPECT_NEAR(lsda::adaptiveMinLength(base, detector->getLengthThresholdScale(), LSDAdvance::LENGTH_THRESHOLD_CAPPED), stats.minLength, 1e-9);
    EXPECT_EQ(1.0, stats.alpha);
    std::vector<Vec4f> kept;
    lsda::keepLongOrStrong(base, std::vector<float>(), stats.minLength, 0.0, kept);
    EXPECT_EQ((int)kept.size(), stats.filteredSegments);
    EXPECT_EQ((int)lines.size(), stats.mergedSegments);
    EXPECT_EQ((int)lines.size(), stats.outputSegments);
    EXPECT_LT(stats.mergedSegments, stats.filteredSegments);
    EXPECT_GT(stats.mergeGroups, 0);
    EXPECT_GE(stats.baseMs, 0.0);
    EXPECT_GE(stats.filterMs, 0.0);
    EXPECT_GE(stats.groupingMs, 0.0);
    EXPECT_GE(stats.mergingMs, 0.0);
}

TEST(LSDAdvance_Detect, length_threshold_scale_multiplies_the_threshold_and_keeps_more_segments)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::vector<Vec4f> full = detectLines(detector, img);
    detector->setLengthThresholdScale(0.5);
    const std::vector<Vec4f> half = detectLines(detector, img);
    EXPECT_NEAR(0.5 * lsda::adaptiveMinLength(detectBase(img), 1.0, LSDAdvance::LENGTH_THRESHOLD_CAPPED),
                detector->getLastStats().minLength, 1e-9);
    EXPECT_GT(half.size(), full.size());
}

TEST(LSDAdvance_Detect, stats_report_every_stage_when_merging_first)
{
    const Mat img = clutterImage(7);
    Ptr<LSDAdvance> detector = createLSDAdvance();
    ASSERT_EQ(LSDAdvance::MERGE_THEN_FILTER, detector->getStageOrder());
    const std::vector<Vec4f> lines = detectLines(detector, img);
    const LSDAdvanceStats stats = detector->getLastStats();
    const std::vector<Vec4f> base = detectBase(img);
    EXPECT_EQ((int)base.size(), stats.baseSegments);
    EXPECT_NEAR(lsda::adaptiveMinLength(base, detector->getLengthThresholdScale(), LSDAdvance::LENGTH_THRESHOLD_CAPPED), stats.minLength, 1e-9);
    EXPECT_LT(stats.mergedSegments, stats.baseSegments);
    EXPECT_LT(stats.filteredSegments, stats.mergedSegments);
    EXPECT_EQ((int)lines.size(), stats.filteredSegments);
    EXPECT_EQ((int)lines.size(), stats.outputSegments);
}

TEST(LSDAdvance_Detect, merging_first_keeps_pieces_the_filter_would_drop)
{
    // The 55 px piece between notches 400 and 460 is shorter than the length threshold: the
    // paper's order drops it before it can join, and the edge stays broken.
    const Mat broken = brokenEdgeImage({ 300, 400, 460 });
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::vector<Vec4f> mergedFirst = onTopEdge(detectLines(detector, broken));
    ASSERT_EQ(1u, mergedFirst.size());
    EXPECT_NEAR(560.0, lsda::segmentLength(mergedFirst[0]), 3.0);
    detector->setStageOrder(LSDAdvance::FILTER_THEN_MERGE);
    const std::vector<Vec4f> filteredFirst = onTopEdge(detectLines(detector, broken));
    EXPECT_GT(filteredFirst.size(), 1u);
}

TEST(LSDAdvance_Detect, merge_none_returns_the_filtered_base_segments)
{
    const Mat img = clutterImage(9);
    Ptr<LSDAdvance> detector = createLSDAdvance();
    detector->setMergeStrategy(LSDAdvance::MERGE_NONE);
    const std::vector<Vec4f> lines = detectLines(detector, img);
    std::vector<Vec4f> kept;
    lsda::keepLongOrStrong(detectBase(img), std::vector<float>(), detector->getLastStats().minLength, 0.0, kept);
    EXPECT_EQ(asSet(kept), asSet(lines));  // the output is ordered by response
    EXPECT_EQ(0, detector->getLastStats().mergeGroups);
}

TEST(LSDAdvance_Detect, processSegments_runs_the_stages_on_given_segments)
{
    const Mat img = buildingImage();
    const std::vector<Vec4f> base = detectBase(img);
    Ptr<LSDAdvance> fromImage = createLSDAdvance(), fromSegments = createLSDAdvance();
    std::vector<Vec4f> expected = detectLines(fromImage, img), lines;
    fromSegments->processSegments(base, lines, img.size());
    EXPECT_EQ(asSet(expected), asSet(lines));  // ordered by length, not by response
    // Without the image there are no responses: with keepStrongSegments too, stage 1 keeps long
    // segments only, where detect() also keeps short strong ones.
    fromSegments->setKeepStrongSegments(true);
    fromSegments->processSegments(base, lines, img.size());
    EXPECT_EQ(asSet(expected), asSet(lines));
    fromImage->setKeepStrongSegments(true);
    EXPECT_LT(lines.size(), detectLines(fromImage, img).size());
    EXPECT_EQ((int)base.size(), fromSegments->getLastStats().baseSegments);
    fromSegments->processSegments(std::vector<Vec4f>(), lines);
    EXPECT_TRUE(lines.empty());
    EXPECT_THROW(fromSegments->processSegments(Mat(3, 4, CV_32FC1), lines), cv::Exception);
}

TEST(LSDAdvance_Detect, processSegments_rejects_non_finite_and_huge_coordinates)
{
    std::vector<Vec4f> segments(50, Vec4f(10, 10, 80, 12));
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines;
    const float bad[] = { std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 1e30f };
    for (float v : bad)
    {
        SCOPED_TRACE(v);
        std::vector<Vec4f> withBad = segments;
        withBad[7][2] = v;
        EXPECT_THROW(detector->processSegments(withBad, lines), cv::Exception);
    }
    // Still usable, and the rejected calls did not count as frames.
    detector->processSegments(segments, lines);
    EXPECT_FALSE(lines.empty());
    EXPECT_EQ(1.0, detector->getLastStats().alpha);
}

TEST(LSDAdvance_Detect, length_filter_none_keeps_every_segment)
{
    const Mat img = clutterImage(3);
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    detectLines(detector, img);
    LSDAdvanceStats stats = detector->getLastStats();
    EXPECT_EQ(stats.mergedSegments, stats.filteredSegments);
    EXPECT_EQ(0.0, stats.minLength);
    detector->setStageOrder(LSDAdvance::FILTER_THEN_MERGE);
    detectLines(detector, img);
    stats = detector->getLastStats();
    EXPECT_EQ(stats.baseSegments, stats.filteredSegments);
}

TEST(LSDAdvance_Detect, color_input_equals_its_gray_conversion)
{
    const Mat gray = buildingImage();
    Mat bgr, bgra;
    cvtColor(gray, bgr, COLOR_GRAY2BGR);
    cvtColor(gray, bgra, COLOR_GRAY2BGRA);
    const std::vector<Vec4f> expected = detectLines(createLSDAdvance(), gray);
    EXPECT_EQ(expected, detectLines(createLSDAdvance(), bgr));
    EXPECT_EQ(expected, detectLines(createLSDAdvance(), bgra));
}

TEST(LSDAdvance_Detect, roi_view_is_read_like_LSD_reads_it)
{
    // LSD's smoothing reads the pixels around a view, so a view and its copy may differ
    // slightly; the base stage must see exactly what LSD sees, and merged lines stay within
    // the extent of LSD's (which may reach a pixel or two past the view's border).
    const Mat img = buildingImage();
    const Mat roi = img(Rect(40, 30, 300, 250));
    ASSERT_FALSE(roi.isContinuous());
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::vector<Vec4f> lines = detectLines(detector, roi);
    const std::vector<Vec4f> base = detectBase(roi);
    EXPECT_EQ((int)base.size(), detector->getLastStats().baseSegments);
    ASSERT_FALSE(lines.empty());
    Vec4f lo(FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX), hi(-FLT_MAX, -FLT_MAX, -FLT_MAX, -FLT_MAX);
    for (const Vec4f& l : base)
        for (int i = 0; i < 4; i++)
        {
            lo[i % 2] = std::min(lo[i % 2], l[i]);
            hi[i % 2] = std::max(hi[i % 2], l[i]);
        }
    for (const Vec4f& l : lines)
        for (int i = 0; i < 4; i++)
        {
            EXPECT_GE(l[i], lo[i % 2] - 1.0f);
            EXPECT_LE(l[i], hi[i % 2] + 1.0f);
        }
}

TEST(LSDAdvance_Detect, building_gives_fewer_and_longer_segments_than_LSD)
{
    const Mat img = buildingImage();
    const std::vector<Vec4f> lsd = detectLsd(img);
    const std::vector<Vec4f> ours = detectLines(createLSDAdvance(), img);
    EXPECT_LT(ours.size(), lsd.size());
    EXPECT_GT(longSegmentShare(ours, 60.0), longSegmentShare(lsd, 60.0));
}

TEST(LSDAdvance_Input, empty_image_throws)
{
    std::vector<Vec4f> lines;
    EXPECT_THROW(createLSDAdvance()->detect(Mat(), lines), cv::Exception);
}

TEST(LSDAdvance_Input, unsupported_types_throw_naming_the_accepted_ones)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const int types[] = { CV_16UC1, CV_32FC1, CV_64FC1, CV_8UC2, CV_8SC1, CV_16UC3 };
    for (int type : types)
    {
        SCOPED_TRACE(typeToString(type));
        std::vector<Vec4f> lines;
        try
        {
            detector->detect(Mat(50, 60, type, Scalar::all(1)), lines);
            ADD_FAILURE() << "no exception";
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.msg.find(typeToString(type)));
            EXPECT_NE(std::string::npos, e.msg.find("CV_8UC1"));
        }
    }
    // The object stays usable after a rejected call.
    EXPECT_FALSE(detectLines(detector, brokenEdgeImage({})).empty());
}

TEST(LSDAdvance_Input, tiny_images_give_no_lines_and_no_error)
{
    const Size sizes[] = { Size(1, 1), Size(2, 2), Size(1, 50), Size(50, 1), Size(3, 3) };
    for (const Size& size : sizes)
    {
        SCOPED_TRACE(size);
        Mat img(size, CV_8UC1);
        randu(img, 0, 256);
        std::vector<Vec4f> lines;
        EXPECT_NO_THROW(createLSDAdvance()->detect(img, lines));
    }
}

// Detects on the frames in order and returns the alpha used by each.
std::vector<double> alphasOf(const Ptr<LSDAdvance>& detector, const std::vector<Mat>& frames,
                             std::vector<int>* kept = nullptr)
{
    std::vector<double> alphas;
    for (const Mat& frame : frames)
    {
        detectLines(detector, frame);
        alphas.push_back(detector->getLastStats().alpha);
        if (kept)
            kept->push_back(detector->getLastStats().filteredSegments);
    }
    return alphas;
}

// Frames whose kept counts change by far more than 10% from one to the next.
std::vector<Mat> changingFrames()
{
    const Mat building = buildingImage();
    return { building(Rect(0, 0, 160, 160)).clone(), building, building(Rect(0, 0, 320, 240)).clone(),
             building };
}

TEST(LSDAdvance_Sequence, alpha_follows_the_kept_counts_of_the_two_previous_frames)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    std::vector<int> kept;
    const std::vector<double> alphas = alphasOf(detector, changingFrames(), &kept);
    EXPECT_EQ(1.0, alphas[0]);
    EXPECT_EQ(1.0, alphas[1]);
    for (size_t k = 2; k < alphas.size(); k++)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(lsda::interFrameAlpha(kept[k - 1], kept[k - 2]), alphas[k]);
    }
    EXPECT_NE(1.0, alphas[2]);
    EXPECT_NE(1.0, alphas[3]);
}

TEST(LSDAdvance_Sequence, reset_starts_a_new_sequence)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    const std::vector<Mat> frames = changingFrames();
    const std::vector<double> first = alphasOf(detector, frames);
    detector->reset();
    EXPECT_EQ(first, alphasOf(detector, frames));
}

TEST(LSDAdvance_Sequence, replay_after_reset_gives_identical_lines)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    const std::vector<Mat> frames = changingFrames();
    std::vector<std::vector<Vec4f> > first;
    for (const Mat& f : frames)
        first.push_back(detectLines(detector, f));
    detector->reset();
    for (size_t k = 0; k < frames.size(); k++)
        EXPECT_EQ(first[k], detectLines(detector, frames[k])) << "frame " << k;
}

TEST(LSDAdvance_Sequence, every_setter_resets_the_sequence)
{
    // Every parameter can change the kept counts (merging runs before the filter by default).
    const std::vector<Mat> frames = changingFrames();
    const std::vector<std::function<void(LSDAdvance&)> > setters = {
        [](LSDAdvance& d) { d.setLSDParams(d.getLSDParams()); },
        [](LSDAdvance& d) { d.setFLDParams(d.getFLDParams()); },
        [](LSDAdvance& d) { d.setEDLinesParams(d.getEDLinesParams()); },
        [](LSDAdvance& d) { d.setParams(d.getParams()); },
        [](LSDAdvance& d) { d.setLengthFilterMode(LSDAdvance::LENGTH_FILTER_INTERFRAME); },
        [](LSDAdvance& d) { d.setMergeThreshold(d.getMergeThreshold()); },
        [](LSDAdvance& d) { d.setEndpointDistance(d.getEndpointDistance()); },
    };
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    ASSERT_NE(1.0, alphasOf(detector, std::vector<Mat>(frames.begin(), frames.begin() + 3))[2]);
    for (size_t i = 0; i < setters.size(); i++)
    {
        SCOPED_TRACE(i);
        detector->reset();
        alphasOf(detector, std::vector<Mat>(frames.begin(), frames.begin() + 2));
        setters[i](*detector);
        EXPECT_EQ(1.0, alphasOf(detector, { frames[2] })[0]);
    }
}

TEST(LSDAdvance_Sequence, each_interframe_mode_uses_its_rule)
{
    const std::vector<Mat> frames = changingFrames();
    Ptr<LSDAdvance> continuous = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS);
    std::vector<int> kept;
    std::vector<double> alphas = alphasOf(continuous, frames, &kept);
    for (size_t k = 2; k < frames.size(); k++)
    {
        SCOPED_TRACE(k);
        EXPECT_EQ(lsda::continuousInterFrameAlpha(kept[k - 1], kept[k - 2]), alphas[k]);
    }

    // Count tracking compares this frame's count at alpha = 1 with the two previous kept counts.
    Ptr<LSDAdvance> tracking = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING);
    Ptr<LSDAdvance> unit = createLSDAdvance();
    kept.clear();
    alphas = alphasOf(tracking, frames, &kept);
    EXPECT_EQ(1.0, alphas[0]);
    EXPECT_EQ(1.0, alphas[1]);
    for (size_t k = 2; k < frames.size(); k++)
    {
        SCOPED_TRACE(k);
        detectLines(unit, frames[k]);
        const int provisional = unit->getLastStats().filteredSegments;
        EXPECT_EQ(lsda::countTrackingAlpha(provisional, kept[k - 1], kept[k - 2]), alphas[k]);
        EXPECT_NE(1.0, alphas[k]);
    }
}

TEST(LSDAdvance_Sequence, adaptive_mode_ignores_previous_frames)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_ADAPTIVE);
    for (double alpha : alphasOf(detector, changingFrames()))
        EXPECT_EQ(1.0, alpha);
}

TEST(LSDAdvance_Sequence, the_default_detector_is_stateless)
{
    // Like LSD and FLD: building.jpg gives the same lines on a fresh detector and after others.
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::vector<Vec4f> fresh = detectLines(detector, buildingImage());
    for (const char* other : { "graf1.png", "graf3.png" })
        detectLines(detector, imread(samples::findFile(other), IMREAD_GRAYSCALE));
    EXPECT_EQ(fresh, detectLines(detector, buildingImage()));
    EXPECT_EQ(1.0, detector->getLastStats().alpha);
}

TEST(LSDAdvance_Sequence, the_sequence_preset_tracks_the_count)
{
    Ptr<LSDAdvance> detector = createLSDAdvance(LSDAdvance::PRESET_SEQUENCE);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING, detector->getLengthFilterMode());
    const std::vector<double> alphas = alphasOf(detector, changingFrames());
    EXPECT_NE(1.0, alphas[2]);
}

}} // namespace
