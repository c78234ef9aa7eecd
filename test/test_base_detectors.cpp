// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0 on each base detector (LSD, FLD, EDLines): the stages work on all of them, every
// base parameter is used, and every base returns segments brighter side on the left.

#include "test_precomp.hpp"
#include "parameter_access.hpp"
#include "opencv2/ximgproc.hpp"

namespace opencv_test { namespace {

const int kBases[] = { LSDAdvance::BASE_LSD, LSDAdvance::BASE_FLD, LSDAdvance::BASE_EDLINES, LSDAdvance::BASE_FAST_LSD };

const char* baseName(int base)
{
    switch (base)
    {
    case LSDAdvance::BASE_LSD: return "LSD";
    case LSDAdvance::BASE_FLD: return "FLD";
    case LSDAdvance::BASE_EDLINES: return "EDLines";
    default: return "fast LSD";
    }
}

// A bright rectangle (x 120..519, y 100..379) on a dark, slightly noisy background.
Mat brightRectangle()
{
    Mat img(480, 640, CV_8UC1, Scalar(40));
    rectangle(img, Point(120, 100), Point(519, 379), Scalar(200), FILLED);
    Mat noise(img.size(), CV_8SC1);
    RNG rng(7);
    rng.fill(noise, RNG::NORMAL, 0, 3);
    cv::add(img, noise, img, noArray(), CV_8U);
    return img;
}

// Five bright bars 76 px wide, 8 px apart (x 120..531, y 100..379): their tops are collinear
// pieces of one line y = 99.5. The gaps are wider than EdgeDrawing's own joining distance (6 px).
Mat barsWithCollinearTops()
{
    Mat img(480, 640, CV_8UC1, Scalar(40));
    for (int x = 120; x < 540; x += 84)
        rectangle(img, Point(x, 100), Point(x + 75, 379), Scalar(200), FILLED);
    return img;
}

// The rectangle's sides, each directed with the bright inside on its left (y pointing down).
std::vector<Vec4f> rectangleSides()
{
    return { Vec4f(519, 100, 120, 100),    // top: going -x, the inside (below) is on the left
             Vec4f(120, 100, 120, 379),    // left side: going +y
             Vec4f(120, 379, 519, 379),    // bottom: going +x
             Vec4f(519, 379, 519, 100) };  // right side: going -y
}

// Segments lying within 2 px of the side's line, at most 5 deg off it.
std::vector<Vec4f> piecesAlong(const std::vector<Vec4f>& lines, const Vec4f& side)
{
    const Point2d a(side[0], side[1]), d = Point2d(side[2], side[3]) - a;
    const Point2d u = d * (1.0 / std::sqrt(d.dot(d)));
    std::vector<Vec4f> pieces;
    for (const Vec4f& l : lines)
    {
        const Point2d p(l[0], l[1]), q(l[2], l[3]);
        const double offP = std::abs(u.cross(p - a)), offQ = std::abs(u.cross(q - a));
        const Point2d e = q - p;
        const double len = std::sqrt(e.dot(e));
        if (len > 0 && offP < 2.0 && offQ < 2.0 && std::abs(u.cross(e)) / len < std::sin(5 * CV_PI / 180))
            pieces.push_back(l);
    }
    return pieces;
}

// The LSDParams fields documented "BASE_FAST_LSD only".
bool onlyForFastLsd(const ParameterAccess& p)
{
    return p.name == "LSDParams::seedGradientRatio" || p.name == "LSDParams::seedAlignedNeighbours" ||
           p.name == "LSDParams::tileHeight" || p.name == "LSDParams::regionGrowth";
}

Ptr<LSDAdvance> onBase(int base, bool stages)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(stages ? LSDAdvance::LENGTH_FILTER_ADAPTIVE : LSDAdvance::LENGTH_FILTER_NONE);
    detector->setBaseDetector(base);
    if (!stages)
        detector->setMergeStrategy(LSDAdvance::MERGE_NONE);
    return detector;
}

TEST(LSDAdvance_BaseDetectors, every_base_finds_the_rectangle_sides_oriented_brighter_left)
{
    const Mat img = brightRectangle();
    for (int base : kBases)
    {
        SCOPED_TRACE(baseName(base));
        std::vector<Vec4f> lines;
        onBase(base, true)->detect(img, lines);
        for (const Vec4f& side : rectangleSides())
        {
            SCOPED_TRACE(side);
            const std::vector<Vec4f> pieces = piecesAlong(lines, side);
            ASSERT_FALSE(pieces.empty());
            const Point2d d(side[2] - side[0], side[3] - side[1]);
            double covered = 0;
            for (const Vec4f& p : pieces)
            {
                const Point2d e(p[2] - p[0], p[3] - p[1]);
                EXPECT_GT(e.dot(d), 0) << "segment " << p << " points against the brighter-left orientation";
                covered += std::sqrt(e.dot(e));
            }
            EXPECT_GT(covered, 0.9 * std::sqrt(d.dot(d)));
        }
    }
}

TEST(LSDAdvance_BaseDetectors, stages_merge_collinear_pieces_into_one_segment_on_every_base)
{
    const Mat img = barsWithCollinearTops();
    const Vec4f top(531, 100, 120, 100);
    for (int base : kBases)
    {
        SCOPED_TRACE(baseName(base));
        Ptr<LSDAdvance> alone = onBase(base, false), stages = onBase(base, true);
        // FLD stops up to 6 px short of a corner: 8 px gaps become up to 20 px between its pieces.
        stages->setEndpointDistance(20);
        std::vector<Vec4f> baseLines, lines;
        alone->detect(img, baseLines);
        stages->detect(img, lines);
        // The base alone returns the line in pieces: otherwise there is nothing to merge.
        ASSERT_EQ(5u, piecesAlong(baseLines, top).size());
        const std::vector<Vec4f> merged = piecesAlong(lines, top);
        ASSERT_EQ(1u, merged.size());
        EXPECT_LT(merged[0][2], merged[0][0]) << "brighter side (below) on the left: pointing -x";
        EXPECT_NEAR(531, merged[0][0], 7.0);
        EXPECT_NEAR(120, merged[0][2], 7.0);
        EXPECT_NEAR(99.5, 0.5 * (merged[0][1] + merged[0][3]), 1.0);
    }
}

TEST(LSDAdvance_BaseDetectors, edlines_segments_are_turned_brighter_left)
{
    // EdgeDrawing itself orients a segment along the edge it traced; some come out reversed.
    Mat img(400, 400, CV_8UC1, Scalar(50));
    rectangle(img, Rect(100, 100, 200, 150), Scalar(200), FILLED);
    circle(img, Point(320, 330), 40, Scalar(220), FILLED);
    Ptr<EdgeDrawing> ed = createEdgeDrawing();
    std::vector<Vec4f> raw, oriented = std::vector<Vec4f>();
    ed->detectEdges(img);
    ed->detectLines(raw);
    // The base segments in EdgeDrawing's order (the output is ordered by response).
    Ptr<LSDAdvance> detector = onBase(LSDAdvance::BASE_EDLINES, false);
    std::vector<Vec4f> lines, filtered, merged;
    std::vector<int> labels;
    detector->detect(img, lines);
    detector->getLastStageOutputs(oriented, filtered, labels, merged);
    ASSERT_EQ(raw.size(), oriented.size());
    int reversed = 0;
    for (size_t k = 0; k < raw.size(); k++)
    {
        const bool same = raw[k] == oriented[k];
        const bool swapped = raw[k] == Vec4f(oriented[k][2], oriented[k][3], oriented[k][0], oriented[k][1]);
        ASSERT_TRUE(same || swapped) << raw[k] << " vs " << oriented[k];
        reversed += swapped && !same;
    }
    EXPECT_GT(reversed, 0) << "EdgeDrawing now orients its lines; the turn-round is redundant";
    std::vector<Vec4f> check = oriented;
    lsda::orientBrighterLeft(img, check);
    EXPECT_EQ(oriented, check) << "every oriented segment already has the brighter side on its left";
}

TEST(LSDAdvance_BaseDetectors, orientBrighterLeft_turns_only_segments_with_the_bright_side_on_the_right)
{
    Mat img(100, 100, CV_8UC1, Scalar(20));
    img.rowRange(50, 100).setTo(Scalar(220));  // bright below y = 50
    // Going -x along y = 50, "left" (y - 1 direction rotated) is below: bright. Keep it.
    std::vector<Vec4f> segments = { Vec4f(80, 50, 20, 50), Vec4f(20, 50, 80, 50), Vec4f(5, 5, 5, 5) };
    lsda::orientBrighterLeft(img, segments);
    EXPECT_EQ(Vec4f(80, 50, 20, 50), segments[0]);
    EXPECT_EQ(Vec4f(80, 50, 20, 50), segments[1]);
    EXPECT_EQ(Vec4f(5, 5, 5, 5), segments[2]);  // a point has no side
}

// A blurred vertical step between columns 99 and 100 (its edge at x = 99.5) and a horizontal one
// between rows 59 and 60 (y = 59.5).
Mat drawnEdges()
{
    Mat img(200, 200, CV_8UC1, Scalar(30));
    img.colRange(100, 200).setTo(Scalar(200));
    img.rowRange(60, 200).colRange(0, 100).setTo(Scalar(120));
    GaussianBlur(img, img, Size(), 1.0);
    return img;
}

// The mean x of the longest nearly vertical segment and the mean y of the longest nearly
// horizontal one.
Point2d edgePositions(const std::vector<Vec4f>& segments)
{
    double longestV = 0, longestH = 0;
    Point2d at(-1, -1);
    for (const Vec4f& s : segments)
    {
        const double len = lsda::segmentLength(s), dx = std::abs(s[2] - s[0]), dy = std::abs(s[3] - s[1]);
        if (dy > 10 * dx && len > longestV && s[0] > 50)
        {
            longestV = len;
            at.x = 0.5 * (s[0] + s[2]);
        }
        if (dx > 10 * dy && len > longestH)
        {
            longestH = len;
            at.y = 0.5 * (s[1] + s[3]);
        }
    }
    return at;
}

TEST(LSDAdvance_BaseDetectors, lsd_bases_at_a_scale_below_1_place_edges_where_they_are)
{
    // OpenCV's LSD divides the coordinates of its scaled image by the scale: at scale 0.5 the
    // edges come 0.5 px too near the origin. Both LSD bases return them on the full image's
    // pixel centres.
    const Mat img = drawnEdges();
    for (double scale : { 1.0, 0.9, 0.8, 0.5 })
    {
        SCOPED_TRACE(scale);
        LSDAdvance::LSDParams lsd;
        lsd.scale = scale;
        lsd.fullScaleSigma = 0;  // at scale 1, OpenCV's LSD reads the image unsmoothed
        std::vector<Vec4f> opencv;
        createLineSegmentDetector(lsd.refine, lsd.scale, lsd.sigmaScale, lsd.quant, lsd.angleTolerance, lsd.logEps,
                                 lsd.densityThreshold, lsd.numBins)
            ->detect(img, opencv);
        const Point2d raw = edgePositions(opencv);
        EXPECT_NEAR(99.5 - 0.5 * (1 / scale - 1), raw.x, 0.05);  // the offset this corrects
        EXPECT_NEAR(59.5 - 0.5 * (1 / scale - 1), raw.y, 0.05);
        for (int base : { (int)LSDAdvance::BASE_LSD, (int)LSDAdvance::BASE_FAST_LSD })
        {
            SCOPED_TRACE(baseName(base));
            std::vector<Vec4f> segments;
            lsda::createBaseDetector(base, lsd, LSDAdvance::FLDParams(), EdgeDrawing::Params())->detect(img, segments);
            const Point2d at = edgePositions(segments);
            EXPECT_NEAR(99.5, at.x, 0.05);
            EXPECT_NEAR(59.5, at.y, 0.05);
            if (base == LSDAdvance::BASE_LSD)
            {
                lsda::toFullResolution(opencv, scale);
                EXPECT_EQ(opencv, segments);  // OpenCV's segments, moved
            }
        }
    }
}

TEST(LSDAdvance_BaseDetectors, fld_and_edlines_bases_return_what_opencv_returns)
{
    // No re-implementation: with the stages off, the base segments are OpenCV's (EDLines' up to
    // orientation, checked above).
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<Vec4f> expected, lines;
    createFastLineDetector()->detect(img, expected);
    onBase(LSDAdvance::BASE_FLD, false)->detect(img, lines);
    EXPECT_EQ(asSet(expected), asSet(lines));  // the output is ordered by response
    Ptr<EdgeDrawing> ed = createEdgeDrawing();
    ed->detectEdges(img);
    ed->detectLines(expected);
    onBase(LSDAdvance::BASE_EDLINES, false)->detect(img, lines);
    EXPECT_EQ(expected.size(), lines.size());
}

// Each parameter of each base changes the base segments of building.jpg: a value to set, and
// what to set before on both detectors for the parameter to act.
TEST(LSDAdvance_BaseDetectors, every_base_parameter_changes_the_base_segments)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    const std::vector<EffectOf> effects = {
        { "LSDParams::refine", LSD_REFINE_STD, nullptr, 0 },
        { "LSDParams::scale", 0.5, nullptr, 0 },
        { "LSDParams::sigmaScale", 1.2, "LSDParams::scale", 0.8 },  // smoothing only below scale 1
        { "LSDParams::fullScaleSigma", 0.0, "LSDParams::fullScaleSmoothing", LSDAdvance::SMOOTH_EVERY_IMAGE },  // a photograph
        { "LSDParams::fullScaleSmoothing", LSDAdvance::SMOOTH_EVERY_IMAGE, nullptr, 0 },
        { "LSDParams::quant", 8.0, nullptr, 0 },
        { "LSDParams::angleTolerance", 12.0, nullptr, 0 },
        { "LSDParams::logEps", 3.0, "LSDParams::refine", LSD_REFINE_ADV },
        { "LSDParams::densityThreshold", 0.95, "LSDParams::refine", LSD_REFINE_STD },
        { "LSDParams::numBins", 4, nullptr, 0 },
        { "LSDParams::seedGradientRatio", 5.0, nullptr, 0 },
        { "LSDParams::seedAlignedNeighbours", 0, nullptr, 0 },
        { "LSDParams::tileHeight", 16, nullptr, 0 },
        { "LSDParams::regionGrowth", LSDAdvance::GROWTH_PER_PIXEL, nullptr, 0 },
        { "FLDParams::lengthThreshold", 30, nullptr, 0 },
        { "FLDParams::distanceThreshold", 3.0, nullptr, 0 },
        { "FLDParams::cannyThreshold1", 150, nullptr, 0 },
        { "FLDParams::cannyThreshold2", 150, nullptr, 0 },
        { "FLDParams::cannyApertureSize", 5, nullptr, 0 },
        { "FLDParams::doMerge", 1, nullptr, 0 },
        { "EdgeDrawing::Params::PFmode", 1, nullptr, 0 },
        { "EdgeDrawing::Params::EdgeDetectionOperator", EdgeDrawing::SOBEL, nullptr, 0 },
        { "EdgeDrawing::Params::GradientThresholdValue", 60, nullptr, 0 },
        { "EdgeDrawing::Params::AnchorThresholdValue", 8, nullptr, 0 },
        { "EdgeDrawing::Params::ScanInterval", 4, nullptr, 0 },
        { "EdgeDrawing::Params::MinPathLength", 60, nullptr, 0 },
        { "EdgeDrawing::Params::Sigma", 2.5, nullptr, 0 },
        { "EdgeDrawing::Params::SumFlag", 0, nullptr, 0 },
        { "EdgeDrawing::Params::NFAValidation", 0, nullptr, 0 },
        { "EdgeDrawing::Params::MinLineLength", 40, nullptr, 0 },
        { "EdgeDrawing::Params::MaxDistanceBetweenTwoLines", 30, nullptr, 0 },
        { "EdgeDrawing::Params::LineFitErrorThreshold", 2.5, nullptr, 0 },
        { "EdgeDrawing::Params::MaxErrorThreshold", 4.0, nullptr, 0 },
    };
    expectEveryParameterChangesTheLines(effects, img, [](const ParameterAccess& p) { return p.base >= 0 && !onlyForFastLsd(p); },
                                        [](const ParameterAccess& p) { return onBase(p.base, false); });
    // LSDParams serve both LSD bases.
    expectEveryParameterChangesTheLines(effects, img, [](const ParameterAccess& p) { return p.base == LSDAdvance::BASE_LSD; },
                                        [](const ParameterAccess&) { return onBase(LSDAdvance::BASE_FAST_LSD, false); });
}

TEST(LSDAdvance_BaseDetectors, base_parameters_of_another_base_are_unused)
{
    // The LSDParams of the module's own LSD only (the seeds, the tiles) leave OpenCV's LSD as it is.
    for (const ParameterAccess& p : everyParameter())
        if (onlyForFastLsd(p))
        {
            SCOPED_TRACE(p.name);
            const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
            std::vector<Vec4f> expected, lines;
            onBase(LSDAdvance::BASE_LSD, true)->detect(img, expected);
            Ptr<LSDAdvance> detector = onBase(LSDAdvance::BASE_LSD, true);
            p.set(*detector, p.range.hi);
            detector->detect(img, lines);
            EXPECT_EQ(expected, lines);
        }

    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<Vec4f> expected, lines;
    onBase(LSDAdvance::BASE_LSD, true)->detect(img, expected);
    Ptr<LSDAdvance> detector = onBase(LSDAdvance::BASE_LSD, true);
    LSDAdvance::FLDParams fld = detector->getFLDParams();
    fld.lengthThreshold = 40;
    detector->setFLDParams(fld);
    EdgeDrawing::Params ed = detector->getEDLinesParams();
    ed.GradientThresholdValue = 80;
    detector->setEDLinesParams(ed);
    detector->detect(img, lines);
    EXPECT_EQ(expected, lines);
}

TEST(LSDAdvance_BaseDetectors, every_base_accepts_images_too_small_for_a_segment)
{
    RNG rng(5);
    for (int base : kBases)
        for (const Size& size : { Size(1, 1), Size(2, 2), Size(5, 12), Size(12, 5), Size(1, 40), Size(6, 6) })
        {
            SCOPED_TRACE(cv::format("%s %dx%d", baseName(base), size.width, size.height));
            Mat img(size, CV_8UC1);
            rng.fill(img, RNG::UNIFORM, 0, 256);
            std::vector<Vec4f> lines;
            ASSERT_NO_THROW(onBase(base, true)->detect(img, lines));
            for (const Vec4f& l : lines)
                EXPECT_TRUE(Rect2f(-1.f, -1.f, size.width + 2.f, size.height + 2.f).contains(Point2f(l[0], l[1])));
        }
}

TEST(LSDAdvance_BaseDetectors, switching_the_base_changes_the_segments_and_back)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    Ptr<LSDAdvance> detector = onBase(LSDAdvance::BASE_LSD, true);
    std::vector<Vec4f> lsd, other, again;
    detector->detect(img, lsd);
    for (int base : { LSDAdvance::BASE_FLD, LSDAdvance::BASE_EDLINES, LSDAdvance::BASE_FAST_LSD })
    {
        SCOPED_TRACE(baseName(base));
        detector->setBaseDetector(base);
        detector->detect(img, other);
        EXPECT_NE(lsd, other);
        detector->setBaseDetector(LSDAdvance::BASE_LSD);
        detector->detect(img, again);
        EXPECT_EQ(lsd, again);
    }
}

}} // namespace
