// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The input contract of LSDAdvance (class description, "Input." and "Output."): one test per
// kind of input. Every rejected call must throw a cv::Exception that says what was wrong and
// what is accepted, and leave the object exactly as it was: the next frame of its sequence
// gives the lines and alpha of an object that never saw the bad call.

#include "test_precomp.hpp"
#include "parameter_access.hpp"

namespace opencv_test { namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

Mat buildingImage()
{
    Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

// Three frames whose kept counts differ by far more than 10 %: on the third, every
// inter-frame mode uses an alpha different from 1, so a sequence state damaged by a rejected
// call changes the third frame's result.
const std::vector<Mat>& sequenceFrames()
{
    static const std::vector<Mat> frames = [] {
        const Mat building = buildingImage();
        return std::vector<Mat>{ building(Rect(0, 0, 60, 60)).clone(),
                                 building(Rect(0, 0, 200, 150)).clone(),
                                 building(Rect(100, 80, 150, 130)).clone() };
    }();
    return frames;
}

struct FrameResult
{
    std::vector<Vec4f> lines;
    double alpha;
};

const FrameResult& referenceThirdFrame()
{
    static const FrameResult result = [] {
        Ptr<LSDAdvance> reference = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
        FrameResult r;
        for (const Mat& frame : sequenceFrames())
            reference->detect(frame, r.lines);
        r.alpha = reference->getLastStats().alpha;
        return r;
    }();
    return result;
}

// Runs two frames, then the call that must be rejected (its message must contain each of
// `mentions`), then the third frame, which must equal that of an object that never saw the call.
void expectRejectedAndStillCorrect(const std::function<void(LSDAdvance&)>& badCall,
                                   const std::vector<std::string>& mentions)
{
    const FrameResult& expected = referenceThirdFrame();
    ASSERT_NE(1.0, expected.alpha) << "the frames must exercise the sequence state";
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME);
    std::vector<Vec4f> lines;
    detector->detect(sequenceFrames()[0], lines);
    detector->detect(sequenceFrames()[1], lines);
    try
    {
        badCall(*detector);
        ADD_FAILURE() << "the call was accepted";
    }
    catch (const cv::Exception& e)
    {
        for (const std::string& m : mentions)
            EXPECT_NE(std::string::npos, e.err.find(m)) << "'" << m << "' not in: " << e.err;
    }
    detector->detect(sequenceFrames()[2], lines);
    EXPECT_EQ(expected.lines, lines);
    EXPECT_EQ(expected.alpha, detector->getLastStats().alpha);
}

void detectInto(LSDAdvance& d, const Mat& image)
{
    std::vector<Vec4f> lines;
    d.detect(image, lines);
}

// Coordinates are finite and inside the image domain [-0.5, W-0.5] x [-0.5, H-0.5] ("Output." in
// the class description: what reaches past it is clipped), and every segment has a length.
void expectInsideImage(const std::vector<Vec4f>& lines, const Size& size)
{
    for (const Vec4f& l : lines)
    {
        for (int i = 0; i < 4; i++)
        {
            ASSERT_TRUE(std::isfinite(l[i])) << l;
            const float extent = (float)(i % 2 == 0 ? size.width : size.height) - 0.5f;
            EXPECT_GE(l[i], -0.5f) << l;
            EXPECT_LE(l[i], extent) << l;
        }
        EXPECT_GT(lsda::segmentLength(l), 0.0) << l;
    }
}

std::vector<Vec4f> detectFresh(InputArray image)
{
    std::vector<Vec4f> lines;
    createLSDAdvance()->detect(image, lines);
    return lines;
}

void expectTypeRejected(int type)
{
    const Mat bad(40, 50, type, Scalar::all(1));
    expectRejectedAndStillCorrect([&](LSDAdvance& d) { detectInto(d, bad); },
                                  { typeToString(type), "CV_8UC1", "CV_8UC3", "CV_8UC4" });
}

//--- images

TEST(LSDAdvance_InputContract, empty_image_is_rejected)
{
    expectRejectedAndStillCorrect([](LSDAdvance& d) { detectInto(d, Mat()); }, { "empty", "CV_8UC1" });
}

TEST(LSDAdvance_InputContract, zero_rows_image_with_columns_is_rejected)
{
    expectRejectedAndStillCorrect([](LSDAdvance& d) { detectInto(d, Mat(0, 30, CV_8UC1)); }, { "empty" });
}

TEST(LSDAdvance_InputContract, depth_16U_is_rejected_naming_type_and_accepted_ones)
{
    expectTypeRejected(CV_16UC1);
}

TEST(LSDAdvance_InputContract, depth_32F_is_rejected_naming_type_and_accepted_ones)
{
    expectTypeRejected(CV_32FC1);
}

TEST(LSDAdvance_InputContract, depth_64F_is_rejected_naming_type_and_accepted_ones)
{
    expectTypeRejected(CV_64FC1);
}

TEST(LSDAdvance_InputContract, signed_depths_are_rejected)
{
    for (int type : { CV_8SC1, CV_16SC1, CV_32SC1, CV_16FC1 })
    {
        SCOPED_TRACE(typeToString(type));
        expectTypeRejected(type);
    }
}

TEST(LSDAdvance_InputContract, colour_images_of_other_depths_are_rejected)
{
    for (int type : { CV_16UC3, CV_32FC3, CV_64FC4 })
    {
        SCOPED_TRACE(typeToString(type));
        expectTypeRejected(type);
    }
}

TEST(LSDAdvance_InputContract, two_channel_image_is_rejected)
{
    expectTypeRejected(CV_8UC2);
}

// A colour image gives the lines of its conversion to gray.
void expectConvertedToGray(const Mat& colour, int conversion)
{
    Mat gray;
    cvtColor(colour, gray, conversion);
    const std::vector<Vec4f> expected = detectFresh(gray);
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(expected, detectFresh(colour));
}

TEST(LSDAdvance_InputContract, three_channel_image_is_converted_as_BGR)
{
    Mat bgr(200, 240, CV_8UC3, Scalar(20, 30, 40));
    rectangle(bgr, Rect(40, 50, 150, 100), Scalar(250, 10, 10), FILLED);
    rectangle(bgr, Rect(60, 70, 100, 60), Scalar(10, 10, 250), FILLED);
    expectConvertedToGray(bgr, COLOR_BGR2GRAY);
}

TEST(LSDAdvance_InputContract, four_channel_image_is_converted_as_BGRA_ignoring_alpha)
{
    Mat bgra(200, 240, CV_8UC4, Scalar(20, 30, 40, 0));
    rectangle(bgra, Rect(60, 70, 100, 60), Scalar(10, 10, 250, 255), FILLED);
    // An edge only in the alpha channel must not be seen.
    rectangle(bgra, Rect(10, 10, 30, 180), Scalar(20, 30, 40, 255), FILLED);
    expectConvertedToGray(bgra, COLOR_BGRA2GRAY);
}

TEST(LSDAdvance_InputContract, non_continuous_gray_view_gives_the_lines_of_its_copy)
{
    const Mat img = buildingImage();
    const Mat view = img(Rect(33, 21, 301, 257));
    ASSERT_FALSE(view.isContinuous());
    const std::vector<Vec4f> lines = detectFresh(view);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(detectFresh(view.clone()), lines);
    expectInsideImage(lines, view.size());
}

TEST(LSDAdvance_InputContract, non_continuous_colour_view_gives_the_lines_of_its_copy)
{
    Mat bgr;
    cvtColor(buildingImage(), bgr, COLOR_GRAY2BGR);
    const Mat view = bgr(Rect(50, 40, 257, 199));
    ASSERT_FALSE(view.isContinuous());
    EXPECT_EQ(detectFresh(view.clone()), detectFresh(view));
}

TEST(LSDAdvance_InputContract, one_column_wide_view_of_a_larger_image)
{
    const Mat img = buildingImage();
    const Mat column = img(Rect(100, 0, 1, img.rows));
    ASSERT_FALSE(column.isContinuous());
    std::vector<Vec4f> lines;
    ASSERT_NO_THROW(createLSDAdvance()->detect(column, lines));
    expectInsideImage(lines, column.size());
}

TEST(LSDAdvance_InputContract, umat_input_gives_the_lines_of_the_mat)
{
    const Mat img = buildingImage();
    EXPECT_EQ(detectFresh(img), detectFresh(img.getUMat(ACCESS_READ)));
}

//--- masks

// Zeros over a quarter of the image and in a hole: the mask changes the lines.
Mat quarterMask(const Size& size)
{
    Mat mask(size, CV_8UC1, Scalar(255));
    mask(Rect(0, 0, size.width / 2, size.height / 2)).setTo(0);
    mask(Rect(size.width / 2, size.height / 2, size.width / 5, size.height / 5)).setTo(0);
    return mask;
}

std::vector<Vec4f> detectFresh(InputArray image, InputArray mask)
{
    std::vector<Vec4f> lines;
    createLSDAdvance()->detect(image, lines, mask);
    return lines;
}

TEST(LSDAdvance_InputContract, mask_of_another_type_is_rejected_naming_it_and_changes_nothing)
{
    const Mat frame = sequenceFrames()[2];
    for (int type : { CV_8UC3, CV_16UC1, CV_32FC1, CV_8SC1 })
        expectRejectedAndStillCorrect(
            [&](LSDAdvance& d) {
                std::vector<Vec4f> lines;
                d.detect(frame, lines, Mat(frame.size(), type, Scalar::all(1)));
            },
            { "mask", typeToString(type), "CV_8UC1 of the image's size" });
}

TEST(LSDAdvance_InputContract, mask_of_another_size_is_rejected_naming_both_sizes_and_changes_nothing)
{
    const Mat frame = sequenceFrames()[2];
    const Mat mask(frame.rows + 1, frame.cols, CV_8UC1, Scalar(255));
    expectRejectedAndStillCorrect(
        [&](LSDAdvance& d) {
            std::vector<Vec4f> lines;
            d.detect(frame, lines, mask);
        },
        { "mask", cv::format("%dx%d", frame.cols, frame.rows), cv::format("%dx%d", mask.cols, mask.rows) });
    expectRejectedAndStillCorrect(
        [&](LSDAdvance& d) {
            std::vector<Vec4f> lines;
            d.processSegments(std::vector<Vec4f>{ Vec4f(1, 1, 20, 20) }, lines, frame.size(), mask);
        },
        { "processSegments", "mask", cv::format("%dx%d", mask.cols, mask.rows) });
}

TEST(LSDAdvance_InputContract, non_continuous_mask_view_gives_the_lines_of_its_copy)
{
    const Mat img = buildingImage();
    const Mat larger = quarterMask(Size(img.cols + 9, img.rows + 7));
    const Mat view = larger(Rect(4, 3, img.cols, img.rows));
    ASSERT_FALSE(view.isContinuous());
    const std::vector<Vec4f> lines = detectFresh(img, view);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(detectFresh(img), lines);
    EXPECT_EQ(detectFresh(img, view.clone()), lines);
    expectInsideImage(lines, img.size());
}

TEST(LSDAdvance_InputContract, umat_mask_gives_the_lines_of_the_mat)
{
    const Mat img = buildingImage();
    const Mat mask = quarterMask(img.size());
    EXPECT_EQ(detectFresh(img, mask), detectFresh(img.getUMat(ACCESS_READ), mask.getUMat(ACCESS_READ)));
}

TEST(LSDAdvance_InputContract, empty_mask_is_no_mask)
{
    const Mat img = buildingImage();
    EXPECT_EQ(detectFresh(img), detectFresh(img, Mat()));
}

// Tiny images: no lines can be found, no error either.
void expectTinyImageHandled(const Size& size)
{
    Mat img(size, CV_8UC1);
    RNG rng(size.area());
    rng.fill(img, RNG::UNIFORM, 0, 256);
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines;
    ASSERT_NO_THROW(detector->detect(img, lines));
    expectInsideImage(lines, size);
    EXPECT_EQ((int)lines.size(), detector->getLastStats().outputSegments);
}

TEST(LSDAdvance_InputContract, image_1x1)
{
    expectTinyImageHandled(Size(1, 1));
}

TEST(LSDAdvance_InputContract, image_1xN)
{
    expectTinyImageHandled(Size(300, 1));
}

TEST(LSDAdvance_InputContract, image_Nx1)
{
    expectTinyImageHandled(Size(1, 300));
}

TEST(LSDAdvance_InputContract, image_2x2)
{
    expectTinyImageHandled(Size(2, 2));
}

TEST(LSDAdvance_InputContract, images_smaller_than_the_base_detector_support)
{
    // LSD's gradient uses 2x2 pixels and its smallest region a few more: try every size up to
    // 8x8 with a strong edge through the middle.
    for (int h = 1; h <= 8; h++)
        for (int w = 1; w <= 8; w++)
        {
            SCOPED_TRACE(Size(w, h));
            Mat img(h, w, CV_8UC1, Scalar(0));
            img.colRange(w / 2, w).setTo(255);
            for (int scaled = 0; scaled < 2; scaled++)
            {
                Ptr<LSDAdvance> detector = createLSDAdvance();
                LSDAdvance::LSDParams lsd = detector->getLSDParams();
                lsd.scale = scaled ? 0.5 : 1.0;
                detector->setLSDParams(lsd);
                std::vector<Vec4f> lines;
                ASSERT_NO_THROW(detector->detect(img, lines));
                expectInsideImage(lines, img.size());
            }
        }
}

TEST(LSDAdvance_InputContract, image_10000x10000_has_no_overflow)
{
    // 10^8 pixels: LSD's per-pixel buffers take about 41 bytes per pixel (measured peak 4.1 GB,
    // "Memory." in the class description). A few long edges far apart must come out whole
    // and inside the image.
    const int n = 10000;
    Mat img(n, n, CV_8UC1, Scalar(50));
    rectangle(img, Rect(1000, 2000, 8000, 6000), Scalar(200), FILLED);  // edges at x = 999.5, 8999.5
    std::vector<Vec4f> lines;
    Ptr<LSDAdvance> detector = createLSDAdvance();
    ASSERT_NO_THROW(detector->detect(img, lines));
    expectInsideImage(lines, img.size());
    // The four sides of the rectangle, each 6000 or 8000 px long, are found as long segments.
    int longSides = 0;
    for (const Vec4f& l : lines)
        longSides += lsda::segmentLength(l) > 5500;
    EXPECT_EQ(4, longSides);
}

// An image without an edge gives no segment at any stage, and stage 1 computes no threshold.
struct Featureless
{
    const char* name;
    int type;
    Scalar value;
};

void PrintTo(const Featureless& f, std::ostream* out)
{
    *out << f.name;
}

typedef testing::TestWithParam<Featureless> LSDAdvance_Featureless;

TEST_P(LSDAdvance_Featureless, image_gives_no_lines)
{
    const Featureless& f = GetParam();
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines;
    detector->detect(Mat(240, 320, f.type, f.value), lines);
    EXPECT_TRUE(lines.empty());
    const LSDAdvanceStats stats = detector->getLastStats();
    EXPECT_EQ(0, stats.baseSegments);
    EXPECT_EQ(0, stats.outputSegments);
    EXPECT_EQ(0.0, stats.minLength);
    EXPECT_EQ(1.0, stats.alpha);
}

INSTANTIATE_TEST_CASE_P(/**/, LSDAdvance_Featureless,
                        testing::Values(Featureless{ "constant_gray", CV_8UC1, Scalar(117) },
                                        Featureless{ "mid_gray", CV_8UC1, Scalar(128) },
                                        Featureless{ "black", CV_8UC1, Scalar(0) },
                                        Featureless{ "white_colour", CV_8UC3, Scalar::all(255) }));

TEST(LSDAdvance_InputContract, saturated_image_gives_its_edge)
{
    // Clipped at 0 and 255 with a hard step: the step is found, nothing else.
    Mat img(240, 320, CV_8UC1, Scalar(0));
    img(Rect(0, 0, 320, 100)).setTo(255);
    std::vector<Vec4f> lines = detectFresh(img);
    ASSERT_EQ(1u, lines.size());
    EXPECT_NEAR(99.5, lines[0][1], 1.0);
    EXPECT_NEAR(99.5, lines[0][3], 1.0);
    EXPECT_GT(lsda::segmentLength(lines[0]), 300);
    expectInsideImage(lines, img.size());
}

TEST(LSDAdvance_InputContract, checkerboard_gives_lines_on_the_square_edges)
{
    const int square = 20;
    Mat img(240, 320, CV_8UC1);
    for (int y = 0; y < img.rows; y++)
        for (int x = 0; x < img.cols; x++)
            img.at<uchar>(y, x) = ((x / square + y / square) % 2) ? 255 : 0;
    const std::vector<Vec4f> lines = detectFresh(img);
    ASSERT_FALSE(lines.empty());
    expectInsideImage(lines, img.size());
    for (const Vec4f& l : lines)
    {
        // Axis-parallel, on a square boundary (pixel-centre coordinates: k * 20 - 0.5).
        const double a = undirectedAngle(l);
        const bool horizontal = a < 2 || a > 178;
        ASSERT_TRUE(horizontal || std::abs(a - 90) < 2) << l;
        const float across = horizontal ? 0.5f * (l[1] + l[3]) : 0.5f * (l[0] + l[2]);
        const float offGrid = std::abs(across + 0.5f - square * cvRound((across + 0.5f) / square));
        EXPECT_LT(offGrid, 1.5f) << l;
    }
}

// Noise of each kind: the segments it gives, base and returned, are finite and inside the image,
// and it gives some (a test of what an empty output holds would pass whatever the detector did).
struct Noise
{
    const char* name;
    Size size;
    int distribution;  //!< RNG::UNIFORM (a, b: the range) or RNG::NORMAL (a, b: mean and deviation)
    double a, b;
    int preset;
};

void PrintTo(const Noise& n, std::ostream* out)
{
    *out << n.name;
}

typedef testing::TestWithParam<Noise> LSDAdvance_Noise;

TEST_P(LSDAdvance_Noise, gives_finite_segments_inside_the_image)
{
    const Noise& noise = GetParam();
    Mat img(noise.size, CV_8UC1);
    RNG rng(20260101);
    rng.fill(img, noise.distribution, noise.a, noise.b);
    Ptr<LSDAdvance> detector = createLSDAdvance((LSDAdvance::Preset)noise.preset);
    std::vector<Vec4f> lines, base;
    detector->detect(img, lines);
    detector->getLastStageOutputs(base, noArray(), noArray(), noArray());
    const LSDAdvanceStats stats = detector->getLastStats();
    EXPECT_GT(base.size(), 0u);
    EXPECT_GT(lines.size(), 0u);
    EXPECT_EQ((int)lines.size(), stats.outputSegments);
    EXPECT_LE(stats.outputSegments, stats.baseSegments);
    EXPECT_TRUE(std::isfinite(stats.minLength));
    expectInsideImage(lines, img.size());
    for (const Vec4f& s : base)
        for (int i = 0; i < 4; i++)
            ASSERT_TRUE(std::isfinite(s[i])) << s;
}

INSTANTIATE_TEST_CASE_P(/**/, LSDAdvance_Noise,
                        testing::Values(Noise{ "uniform_640x480", Size(640, 480), RNG::UNIFORM, 0, 256,
                                               LSDAdvance::PRESET_MOST_ACCURATE },
                                        Noise{ "uniform_320x240", Size(320, 240), RNG::UNIFORM, 0, 256,
                                               LSDAdvance::PRESET_MOST_ACCURATE },
                                        Noise{ "normal_640x480_sequence", Size(640, 480), RNG::NORMAL, 128, 40,
                                               LSDAdvance::PRESET_SEQUENCE },
                                        Noise{ "normal_640x480_paper", Size(640, 480), RNG::NORMAL, 128, 40,
                                               LSDAdvance::PRESET_PAPER }));

//--- parameters through the setters

// Every parameter stored as a double: NaN, infinities and huge values must all be rejected.
void expectRealValueRejectedByEverySetter(double value)
{
    for (const ParameterAccess& p : everyParameter())
    {
        if (p.integral)
            continue;
        SCOPED_TRACE(cv::format("%s = %g", p.name.c_str(), value));
        ASSERT_FALSE(p.range.accepts(value));
        expectRejectedAndStillCorrect([&](LSDAdvance& d) { p.set(d, value); }, { p.name, "finite" });
    }
}

TEST(LSDAdvance_InputContract, NaN_is_rejected_by_every_real_setter)
{
    expectRealValueRejectedByEverySetter(kNaN);
}

TEST(LSDAdvance_InputContract, infinities_are_rejected_by_every_real_setter)
{
    expectRealValueRejectedByEverySetter(kInf);
    expectRealValueRejectedByEverySetter(-kInf);
}

TEST(LSDAdvance_InputContract, huge_values_are_rejected_by_every_real_setter)
{
    expectRealValueRejectedByEverySetter(1e300);
    expectRealValueRejectedByEverySetter(-DBL_MAX);
}

TEST(LSDAdvance_InputContract, values_outside_each_range_are_rejected_naming_the_parameter)
{
    for (const ParameterAccess& p : everyParameter())
        for (double value : outsideValues(p.range))
        {
            SCOPED_TRACE(cv::format("%s = %g", p.name.c_str(), value));
            expectRejectedAndStillCorrect([&](LSDAdvance& d) { p.set(d, value); }, { p.name, p.range.describe() });
        }
}

TEST(LSDAdvance_InputContract, out_of_range_integers_are_rejected_by_every_int_setter)
{
    for (const ParameterAccess& p : everyParameter())
        if (p.integral && p.range.kind != lsda::Range::FLAG)
            for (int value : { INT_MIN, INT_MAX })
            {
                SCOPED_TRACE(cv::format("%s = %d", p.name.c_str(), value));
                expectRejectedAndStillCorrect([&](LSDAdvance& d) { p.set(d, value); },
                                              { p.name, cv::format("%d", value) });
            }
}

TEST(LSDAdvance_InputContract, every_value_at_the_ends_of_each_range_gives_lines_inside_the_image)
{
    const Mat img = sequenceFrames()[1];
    for (const ParameterAccess& p : everyParameter())
        for (double value : insideValues(p.range))
        {
            SCOPED_TRACE(cv::format("%s = %g", p.name.c_str(), value));
            Ptr<LSDAdvance> detector = createLSDAdvance();
            if (p.base >= 0)
                detector->setBaseDetector(p.base);
            ASSERT_NO_THROW(p.set(*detector, value));
            std::vector<Vec4f> lines;
            ASSERT_NO_THROW(detector->detect(img, lines));
            expectInsideImage(lines, img.size());
        }
}

TEST(LSDAdvance_InputContract, factory_rejects_an_unknown_preset_naming_the_presets)
{
    for (int preset : { -1, (int)LSDAdvance::PRESET_FRONT_END + 1, INT_MAX })
    {
        SCOPED_TRACE(preset);
        try
        {
            createLSDAdvance((LSDAdvance::Preset)preset);
            ADD_FAILURE() << "preset accepted";
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.err.find("PRESET_MOST_ACCURATE")) << e.err;
        }
    }
}

//--- processSegments

TEST(LSDAdvance_InputContract, segments_of_a_wrong_layout_are_rejected)
{
    const Mat wrongType(5, 1, CV_32FC2, Scalar::all(1));
    const Mat twoDimensional(3, 4, CV_32FC4, Scalar::all(1));
    const Mat doubles(5, 1, CV_64FC4, Scalar::all(1));
    for (const Mat& bad : { wrongType, twoDimensional, doubles })
    {
        SCOPED_TRACE(typeToString(bad.type()));
        expectRejectedAndStillCorrect(
            [&](LSDAdvance& d) {
                std::vector<Vec4f> lines;
                d.processSegments(bad, lines);
            },
            { "CV_32FC4", typeToString(bad.type()) });
    }
}

TEST(LSDAdvance_InputContract, segments_with_NaN_inf_or_huge_coordinates_are_rejected)
{
    const float values[] = { (float)kNaN, (float)kInf, -(float)kInf, 1.5e7f, -FLT_MAX };
    for (float v : values)
    {
        SCOPED_TRACE(v);
        std::vector<Vec4f> segments = { Vec4f(10, 10, 50, 10), Vec4f(60, 10, v, 10) };
        expectRejectedAndStillCorrect(
            [&](LSDAdvance& d) {
                std::vector<Vec4f> lines;
                d.processSegments(segments, lines);
            },
            { "finite" });
    }
}

TEST(LSDAdvance_InputContract, empty_segment_set_gives_no_lines)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    std::vector<Vec4f> lines(3);
    detector->processSegments(std::vector<Vec4f>(), lines);
    EXPECT_TRUE(lines.empty());
    EXPECT_EQ(0, detector->getLastStats().baseSegments);
}

//--- clipping to the image ("Output.")

TEST(LSDAdvance_InputContract, a_segment_reaching_past_the_image_is_clipped_along_its_own_line)
{
    const Size size(100, 50);  // domain [-0.5, 99.5] x [-0.5, 49.5]
    Vec4f clipped;
    // Inside (the edges included): unchanged.
    for (const Vec4f& s : { Vec4f(10, 10, 90, 40), Vec4f(-0.5f, -0.5f, 99.5f, 49.5f) })
    {
        ASSERT_TRUE(lsda::clipToDomain(s, size, clipped)) << s;
        EXPECT_EQ(s, clipped);
    }
    // Past the left and the right edge: cut there, on the same line, in the same direction.
    ASSERT_TRUE(lsda::clipToDomain(Vec4f(-10.5f, 20, 109.5f, 32), size, clipped));
    EXPECT_NEAR(-0.5, clipped[0], 1e-5);
    EXPECT_NEAR(21, clipped[1], 1e-4);
    EXPECT_NEAR(99.5, clipped[2], 1e-5);
    EXPECT_NEAR(31, clipped[3], 1e-4);
    // Pointing the other way: it still does.
    ASSERT_TRUE(lsda::clipToDomain(Vec4f(50, 60, 50, 20), size, clipped));
    EXPECT_EQ(Vec4f(50, 49.5f, 50, 20), clipped);
    // Nothing left: outside, or touching the domain at one corner only.
    EXPECT_FALSE(lsda::clipToDomain(Vec4f(-5, -5, -1, 60), size, clipped));
    EXPECT_FALSE(lsda::clipToDomain(Vec4f(-10.5f, 9.5f, 9.5f, -10.5f), size, clipped));
    EXPECT_FALSE(lsda::clipToDomain(Vec4f(200, 20, 200, 20), size, clipped));
    EXPECT_FALSE(lsda::clipToDomain(Vec4f(3, 3, 3, 3), size, clipped));
}

TEST(LSDAdvance_InputContract, processSegments_clips_only_when_given_the_image_size)
{
    const std::vector<Vec4f> segments = { Vec4f(-20, 10, 60, 10), Vec4f(10, 20, 30, 20), Vec4f(150, 5, 170, 5) };
    Ptr<LSDAdvance> d = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    std::vector<Vec4f> lines;
    d->processSegments(segments, lines);
    EXPECT_EQ(segments, lines);
    d->processSegments(segments, lines, Size(100, 40));
    const std::vector<Vec4f> expected = { Vec4f(-0.5f, 10, 60, 10), Vec4f(10, 20, 30, 20) };
    EXPECT_EQ(expected, lines);
    EXPECT_EQ(2, d->getLastStats().outputSegments);
    EXPECT_THROW(d->processSegments(segments, lines, Size(-1, 10)), cv::Exception);
}

TEST(LSDAdvance_InputContract, fused_segments_reaching_past_the_image_are_clipped)
{
    // Collinear pieces along a slanted line that leaves the image: merging extends the fused
    // segment to the projections of its pieces, clipping brings it back inside.
    std::vector<Vec4f> pieces;
    for (int k = 0; k < 6; k++)
        pieces.push_back(segmentAt(-4 + 20 * k, 2 + 4 * k, std::atan2(4.0, 20.0) * 180 / CV_PI, 17));
    const Size size(100, 40);
    Ptr<LSDAdvance> d = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_NONE);
    std::vector<Vec4f> unclipped, lines;
    d->processSegments(pieces, unclipped);
    d->processSegments(pieces, lines, size);
    ASSERT_EQ(1u, unclipped.size());
    ASSERT_EQ(1u, lines.size());
    EXPECT_LT(unclipped[0][0], -0.5f);
    expectInsideImage(lines, size);
    EXPECT_NEAR(undirectedAngle(unclipped[0]), undirectedAngle(lines[0]), 1e-3);
}

//--- parameters through read()

void readText(LSDAdvance& d, const std::string& text)
{
    FileStorage fs(text, FileStorage::READ | FileStorage::MEMORY);
    CV_Assert(fs.isOpened());
    d.read(fs.root());
}

std::string yaml(const std::string& body)
{
    return "%YAML:1.0\n---\n" + body + "\n";
}

TEST(LSDAdvance_InputContract, read_rejects_non_finite_and_out_of_range_values_naming_the_parameter)
{
    for (const ParameterAccess& p : everyParameter())
    {
        std::vector<std::string> values;
        for (double v : outsideValues(p.range))
            values.push_back(cv::format("%.17g", v));
        if (!p.integral)
            values.insert(values.end(), { ".nan", ".inf", "-.inf", "1e300", "-1e300" });
        else if (p.range.kind != lsda::Range::FLAG)
            values.insert(values.end(), { cv::format("%d", INT_MIN), cv::format("%d", INT_MAX) });
        for (const std::string& value : values)
        {
            const std::string text = yamlOf(p, value);
            SCOPED_TRACE(text);
            expectRejectedAndStillCorrect([&](LSDAdvance& d) { readText(d, text); }, { p.key });
        }
    }
}

TEST(LSDAdvance_InputContract, read_rejects_wrong_types_naming_the_parameter)
{
    const std::vector<const char*> wrongForReal = { "\"0.5\"", "[ 0.5, 0.6 ]", "{ value: 0.5 }", "abc" };
    const std::vector<const char*> wrongForInt = { "1.5", "\"1\"", "[ 1 ]", "{ value: 1 }", "1e3" };
    for (const ParameterAccess& p : everyParameter())
        for (const char* value : p.integral ? wrongForInt : wrongForReal)
        {
            const std::string text = yamlOf(p, value);
            SCOPED_TRACE(text);
            // A string for an enumerated value is a name; an unknown name lists the known ones.
            const bool name = p.range.kind == lsda::Range::ENUM && value == std::string("\"1\"");
            expectRejectedAndStillCorrect([&](LSDAdvance& d) { readText(d, text); },
                                          { p.key, name ? p.range.describe() : (p.integral ? "" : "number") });
        }
}

TEST(LSDAdvance_InputContract, read_of_a_file_with_a_bad_value_changes_no_parameter)
{
    // Valid values before and after the bad one: none of them may be applied.
    const std::string text = yaml("lsd: { scale: 0.5 }\nmergeThreshold: .nan\nendpointDistance: 4\nlengthFilterMode: 0");
    expectRejectedAndStillCorrect([&](LSDAdvance& d) { readText(d, text); }, { "mergeThreshold" });
    Ptr<LSDAdvance> detector = createLSDAdvance();
    EXPECT_THROW(readText(*detector, text), cv::Exception);
    EXPECT_EQ(LSDAdvance::LSDParams().scale, detector->getLSDParams().scale);
    EXPECT_EQ(LSDAdvance::Params().endpointDistance, detector->getEndpointDistance());
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_ADAPTIVE, detector->getLengthFilterMode());
}

TEST(LSDAdvance_InputContract, read_of_a_file_without_values_keeps_every_parameter)
{
    Ptr<LSDAdvance> detector = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_INTERFRAME, 3.0, 0.7);
    LSDAdvance::LSDParams lsd = detector->getLSDParams();
    lsd.scale = 0.8;
    detector->setLSDParams(lsd);
    for (const std::string& text : { yaml("{}"), yaml("format: 3") })
    {
        SCOPED_TRACE(text);
        ASSERT_NO_THROW(readText(*detector, text));
        EXPECT_EQ(LSDAdvance::LENGTH_FILTER_INTERFRAME, detector->getLengthFilterMode());
        EXPECT_EQ(3.0, detector->getEndpointDistance());
        EXPECT_EQ(0.7, detector->getMergeThreshold());
        EXPECT_EQ(0.8, detector->getLSDParams().scale);
    }
}

TEST(LSDAdvance_InputContract, read_of_a_future_file_ignores_unknown_keys)
{
    // A later version may add parameters of any type; the known ones are still applied.
    const std::string text = yaml("format: 99\nfutureDetectorKind: 7\nfutureWeights: [ 1, 2, 3 ]\n"
                                  "futureBlock: { a: 1, b: \"x\" }\nmergeThreshold: 0.7\n"
                                  "lsd: { scale: 0.5, futureLsdParameter: 2 }");
    Ptr<LSDAdvance> detector = createLSDAdvance();
    ASSERT_NO_THROW(readText(*detector, text));
    EXPECT_EQ(0.7, detector->getMergeThreshold());
    EXPECT_EQ(0.5, detector->getLSDParams().scale);

    Ptr<LSDAdvance> expected = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_ADAPTIVE, LSDAdvance::Params().endpointDistance, 0.7);
    LSDAdvance::LSDParams lsd = expected->getLSDParams();
    lsd.scale = 0.5;
    expected->setLSDParams(lsd);
    const Mat img = sequenceFrames()[1];
    std::vector<Vec4f> a, b;
    detector->detect(img, a);
    expected->detect(img, b);
    EXPECT_EQ(b, a);
}

TEST(LSDAdvance_InputContract, read_of_a_file_from_disk_with_an_unknown_key_and_a_wrong_type)
{
    const String path = cv::tempfile(".yml");
    {
        Ptr<LSDAdvance> saved = createLSDAdvanceWith(LSDAdvance::LENGTH_FILTER_ADAPTIVE, 5.0, 0.65);
        FileStorage fs(path, FileStorage::WRITE);
        fs << saved->getDefaultName() << "{";
        saved->write(fs);
        fs << "futureParameter" << "anything";
        fs << "}";
    }
    Ptr<LSDAdvance> loaded = createLSDAdvance();
    {
        FileStorage fs(path, FileStorage::READ);
        ASSERT_TRUE(fs.isOpened());
        ASSERT_NO_THROW(loaded->read(fs[loaded->getDefaultName()]));
    }
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_ADAPTIVE, loaded->getLengthFilterMode());
    EXPECT_EQ(5.0, loaded->getEndpointDistance());
    EXPECT_EQ(0.65, loaded->getMergeThreshold());

    // The same file with a wrong type for a known key.
    {
        FileStorage fs(path, FileStorage::WRITE);
        fs << "LSDAdvance" << "{" << "endpointDistance" << "near" << "}";
    }
    {
        FileStorage fs(path, FileStorage::READ);
        ASSERT_TRUE(fs.isOpened());
        try
        {
            loaded->read(fs["LSDAdvance"]);
            ADD_FAILURE() << "a string was accepted for endpointDistance";
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.err.find("endpointDistance")) << e.err;
        }
    }
    std::remove(path.c_str());
    EXPECT_EQ(5.0, loaded->getEndpointDistance());
}

}} // namespace
