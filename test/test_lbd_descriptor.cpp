// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// computeLBD against its oracle, line_descriptor's BinaryDescriptor::compute with its default
// parameters (the version OpenCV links): the same bytes, and before they are made binary the same
// floats, bit for bit, on random images and KeyLines, at the borders, for very short and very long
// lines, on every preset's lines on real images; the matcher's matches; the contract on bad input.

#include "test_precomp.hpp"

#include <thread>

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

namespace opencv_test { namespace {

using line_descriptor::KeyLine;
using line_descriptor::BinaryDescriptor;
using line_descriptor::BinaryDescriptorMatcher;

Mat buildingGray()
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    CV_Assert(!img.empty());
    return img;
}

// BinaryDescriptor::compute describes one KeyLine per class_id: number them (they are copies).
std::vector<KeyLine> numbered(std::vector<KeyLine> keylines)
{
    for (size_t i = 0; i < keylines.size(); i++)
        keylines[i].class_id = (int)i;
    return keylines;
}

// computeLBD's bytes and lbdFloatDescriptors' floats equal BinaryDescriptor::compute's, row by
// row, bit for bit. Returns the number of rows compared.
int expectLikeBinaryDescriptor(const Mat& image, const std::vector<KeyLine>& keylines)
{
    std::vector<KeyLine> reference = numbered(keylines);
    const Ptr<BinaryDescriptor> oracle = BinaryDescriptor::createBinaryDescriptor();
    Mat expectedBytes, expectedFloats, bytes, floats;
    oracle->compute(image, reference, expectedBytes);
    oracle->compute(image, reference, expectedFloats, true);
    computeLBD(image, keylines, bytes);
    lsda::lbdFloatDescriptors(image, keylines, floats);
    EXPECT_EQ(CV_8UC1, bytes.type());
    EXPECT_EQ(CV_32FC1, floats.type());
    if (bytes.size() != expectedBytes.size() || floats.size() != expectedFloats.size())
    {
        ADD_FAILURE() << "sizes " << bytes.size() << " / " << floats.size() << ", expected " << expectedBytes.size()
                      << " / " << expectedFloats.size();
        return 0;
    }
    int differentBytes = 0, differentFloats = 0;
    for (int i = 0; i < bytes.rows; i++)
    {
        const bool byteRow = memcmp(bytes.ptr(i), expectedBytes.ptr(i), bytes.cols) != 0;
        const bool floatRow = memcmp(floats.ptr(i), expectedFloats.ptr(i), floats.cols * sizeof(float)) != 0;
        if ((byteRow || floatRow) && differentBytes + differentFloats < 3)
        {
            const KeyLine& k = keylines[i];
            ADD_FAILURE() << "KeyLine " << i << " (" << k.startPointX << ", " << k.startPointY << ") - (" << k.endPointX
                          << ", " << k.endPointY << "), angle " << k.angle << ", numOfPixels " << k.numOfPixels
                          << ": bytes " << (byteRow ? "differ" : "equal") << ", floats " << (floatRow ? "differ" : "equal");
        }
        differentBytes += byteRow;
        differentFloats += floatRow;
    }
    EXPECT_EQ(0, differentBytes) << "of " << bytes.rows;
    EXPECT_EQ(0, differentFloats) << "of " << floats.rows;
    return bytes.rows;
}

// Random segments of the lengths asked for, endpoints anywhere in the image and up to one pixel
// around it, as KeyLines (linesToKeyLines: its clamping keeps them in [0, W) x [0, H)).
std::vector<KeyLine> randomKeyLines(RNG& rng, Size size, int count, double minLength, double maxLength)
{
    std::vector<Vec4f> segments;
    while ((int)segments.size() < count)
    {
        const double x = rng.uniform(-1.0, size.width + 1.0), y = rng.uniform(-1.0, size.height + 1.0);
        const double angle = rng.uniform(-CV_PI, CV_PI), length = rng.uniform(minLength, maxLength);
        const Vec4f s((float)x, (float)y, (float)(x + length * std::cos(angle)), (float)(y + length * std::sin(angle)));
        if (s[0] != s[2] || s[1] != s[3])
            segments.push_back(s);
    }
    std::vector<KeyLine> keylines;
    linesToKeyLines(segments, size, keylines);
    for (const KeyLine& k : keylines)
        CV_Assert(k.numOfPixels >= 1);
    keylines.erase(std::remove_if(keylines.begin(), keylines.end(), [](const KeyLine& k) {
                       return k.startPointX == k.endPointX && k.startPointY == k.endPointY;  // clamped to a point
                   }),
                   keylines.end());
    return keylines;
}

// Images whose gradients exercise every sign and size: noise, smoothed noise, shapes on a ramp.
Mat randomImage(RNG& rng, Size size, int kind)
{
    Mat img(size, CV_8UC1);
    if (kind == 0)
        rng.fill(img, RNG::UNIFORM, 0, 256);
    else if (kind == 1)
    {
        rng.fill(img, RNG::UNIFORM, 0, 256);
        GaussianBlur(img, img, Size(0, 0), 2.0);
    }
    else
    {
        for (int y = 0; y < size.height; y++)
            for (int x = 0; x < size.width; x++)
                img.at<uchar>(y, x) = saturate_cast<uchar>(40 + 100.0 * x / size.width + 60.0 * y / size.height);
        for (int k = 0; k < 12; k++)
        {
            const Point a(rng.uniform(-10, size.width + 10), rng.uniform(-10, size.height + 10));
            const Point b(rng.uniform(-10, size.width + 10), rng.uniform(-10, size.height + 10));
            if (k % 2)
                rectangle(img, a, b, Scalar(rng.uniform(0, 256)), FILLED);
            else
                line(img, a, b, Scalar(rng.uniform(0, 256)), rng.uniform(1, 6));
        }
    }
    return img;
}

TEST(LSDAdvance_LBD, gradient_is_GaussianBlur_then_Sobel_at_every_size)
{
    RNG rng(20240611);
    for (const Size size : { Size(1, 1), Size(1, 7), Size(7, 1), Size(2, 2), Size(2, 5), Size(3, 4), Size(4, 3),
                             Size(5, 5), Size(31, 33), Size(33, 31), Size(257, 70), Size(300, 200) })
        for (int kind = 0; kind < 3; kind++)
        {
            SCOPED_TRACE(cv::format("%dx%d, image kind %d", size.width, size.height, kind));
            const Mat img = randomImage(rng, size, kind);
            Mat blurred = img.clone(), dx, dy, expected, gradient;
            GaussianBlur(blurred, blurred, Size(5, 5), 1);
            Sobel(blurred, dx, CV_16S, 1, 0, 3);
            Sobel(blurred, dy, CV_16S, 0, 1, 3);
            merge(std::vector<Mat>{ dx, dy }, expected);
            lsda::lbdGradient(img, gradient);
            ASSERT_EQ(CV_16SC2, gradient.type());
            EXPECT_EQ(0, cvtest::norm(gradient, expected, NORM_INF));
        }
}

TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_random_images_and_keylines)
{
    RNG rng(7);
    int rows = 0;
    for (const Size size : { Size(3, 2), Size(9, 17), Size(64, 48), Size(333, 250), Size(640, 480) })
        for (int kind = 0; kind < 3; kind++)
        {
            SCOPED_TRACE(cv::format("%dx%d, image kind %d", size.width, size.height, kind));
            const Mat img = randomImage(rng, size, kind);
            const double longest = std::hypot(size.width, size.height);
            rows += expectLikeBinaryDescriptor(img, randomKeyLines(rng, size, 60, 0.5, longest));
        }
    EXPECT_GT(rows, 800);
}

// KeyLines from other sources than linesToKeyLines: any direction (not the endpoints'), any
// support length, endpoints anywhere in the accepted box: LBD samples what the fields say.
TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_keylines_whose_fields_disagree)
{
    RNG rng(11);
    const Size size(320, 240);
    const Mat img = randomImage(rng, size, 2);
    std::vector<KeyLine> keylines = randomKeyLines(rng, size, 200, 1.0, 300.0);
    for (KeyLine& k : keylines)
    {
        k.angle = (float)rng.uniform(-4.0, 4.0);
        k.numOfPixels = rng.uniform(1, 700);
        const float x = (float)rng.uniform(-1.0, size.width + 1.0), y = (float)rng.uniform(-1.0, size.height + 1.0);
        k.startPointX = k.sPointInOctaveX = x;
        k.startPointY = k.sPointInOctaveY = y;
    }
    keylines.front().startPointX = keylines.front().sPointInOctaveX = -1.f;  // the corners of the box
    keylines.front().endPointY = keylines.front().ePointInOctaveY = (float)size.height;
    EXPECT_EQ(200, expectLikeBinaryDescriptor(img, keylines));
}

TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_very_short_and_very_long_lines)
{
    const Mat gray = buildingGray();
    const Size size = gray.size();
    const float w = (float)size.width - 1, h = (float)size.height - 1;
    // Whole diagonals and sides, a line along the border, sub-pixel and one-pixel lines.
    const std::vector<Vec4f> segments = { Vec4f(0, 0, w, h),        Vec4f(w, h, 0, 0),      Vec4f(0, h, w, 0),
                                          Vec4f(0, 0, w, 0),        Vec4f(0, h, w, h),      Vec4f(0, 0, 0, h),
                                          Vec4f(w, 0, w, h),        Vec4f(10, 10, 10.3f, 10.2f),
                                          Vec4f(100, 100, 101, 100), Vec4f(200, 50, 200, 51), Vec4f(300.5f, 80, 301, 81),
                                          Vec4f(0, 0, 0.5f, 0.5f),  Vec4f(w, h, w - 1, h),   Vec4f(5, 200, 5, 202) };
    std::vector<KeyLine> keylines;
    linesToKeyLines(segments, size, keylines);
    int shortest = INT_MAX, longest = 0;
    for (const KeyLine& k : keylines)
    {
        shortest = std::min(shortest, k.numOfPixels);
        longest = std::max(longest, k.numOfPixels);
    }
    EXPECT_EQ(1, shortest);
    EXPECT_EQ(std::max(size.width, size.height), longest);
    EXPECT_EQ((int)segments.size(), expectLikeBinaryDescriptor(gray, keylines));

    // Support regions far longer than the image, up to numOfPixels' limit, on a small crop.
    const Mat corner = gray(Rect(0, 0, 64, 48)).clone();
    std::vector<KeyLine> stretched;
    linesToKeyLines(std::vector<Vec4f>{ Vec4f(5, 5, 60, 40), Vec4f(30, 2, 31, 45), Vec4f(63, 47, 0, 47) }, corner.size(),
                    stretched);
    stretched[0].numOfPixels = 32767;
    stretched[1].numOfPixels = 20000;
    stretched[2].numOfPixels = 4001;
    EXPECT_EQ(3, expectLikeBinaryDescriptor(corner, stretched));
}

TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_detector_lines_at_the_borders)
{
    const Mat gray = buildingGray();
    // Crops whose sides cut through the building's edges, and the whole image.
    for (const Rect crop : { Rect(0, 0, gray.cols, gray.rows), Rect(37, 21, 200, 150), Rect(150, 90, 301, 203) })
    {
        SCOPED_TRACE(cv::format("crop %d,%d %dx%d", crop.x, crop.y, crop.width, crop.height));
        const Mat img = gray(crop).clone();
        std::vector<KeyLine> keylines;
        createLSDAdvance()->detect(img, keylines);
        int atBorder = 0;
        for (const KeyLine& k : keylines)
        {
            const auto near = [](float v, int side) { return v < 2.f || v > side - 3.f; };
            atBorder += near(k.startPointX, img.cols) || near(k.endPointX, img.cols) || near(k.startPointY, img.rows) ||
                        near(k.endPointY, img.rows);
        }
        EXPECT_GT(atBorder, 10);
        expectLikeBinaryDescriptor(img, keylines);
    }
}

TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_every_preset_on_building)
{
    const Mat gray = buildingGray();
    for (int preset = LSDAdvance::PRESET_MOST_ACCURATE; preset <= LSDAdvance::PRESET_FRONT_END; preset++)
    {
        SCOPED_TRACE(cv::format("preset %d", preset));
        std::vector<KeyLine> keylines;
        createLSDAdvance((LSDAdvance::Preset)preset)->detect(gray, keylines);
        EXPECT_GE(expectLikeBinaryDescriptor(gray, keylines), 50);
    }
}

// Every preset on the shared data: KITTI frames and YorkUrban images.
TEST(LSDAdvance_LBD, equals_BinaryDescriptor_on_every_preset_on_real_data)
{
    std::vector<String> paths;
    const std::vector<String> kitti = loadSequence(dataFolder("kitti_seq1")).imagePaths;
    const std::vector<LabelledImage> york = loadYorkUrban(dataFolder("yorkurban"));
    for (size_t k = 0; k < kitti.size(); k += 12)
        paths.push_back(kitti[k]);
    for (size_t k = 0; k < york.size(); k += 12)
        paths.push_back(york[k].imagePath);
    int rows = 0;
    for (const String& path : paths)
    {
        const Mat gray = imread(path, IMREAD_GRAYSCALE);
        ASSERT_FALSE(gray.empty()) << path;
        for (int preset = LSDAdvance::PRESET_MOST_ACCURATE; preset <= LSDAdvance::PRESET_FRONT_END; preset++)
        {
            SCOPED_TRACE(cv::format("%s, preset %d", path.c_str(), preset));
            std::vector<KeyLine> keylines;
            createLSDAdvance((LSDAdvance::Preset)preset)->detect(gray, keylines);
            rows += expectLikeBinaryDescriptor(gray, keylines);
        }
    }
    EXPECT_GT(rows, 5000);
}

TEST(LSDAdvance_LBD, colour_images_are_described_as_BinaryDescriptor_converts_them)
{
    const Mat bgr = imread(samples::findFile("building.jpg"), IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty());
    Mat bgra;
    cvtColor(bgr, bgra, COLOR_BGR2BGRA);
    std::vector<KeyLine> keylines;
    createLSDAdvance()->detect(bgr, keylines);
    ASSERT_GT(keylines.size(), 50u);
    expectLikeBinaryDescriptor(bgr, keylines);
    expectLikeBinaryDescriptor(bgra, keylines);
}

TEST(LSDAdvance_LBD, output_does_not_depend_on_the_threads_class_ids_or_earlier_calls)
{
    const Mat gray = buildingGray();
    std::vector<KeyLine> keylines;
    createLSDAdvance()->detect(gray, keylines);
    ASSERT_GT(keylines.size(), 100u);
    Mat reference;
    computeLBD(gray, keylines, reference);

    const int threads = getNumThreads();
    for (int n : { 1, 2, 3, 8 })
    {
        setNumThreads(n);
        Mat descriptors;
        computeLBD(gray, keylines, descriptors);
        EXPECT_EQ(0, cvtest::norm(reference, descriptors, NORM_INF)) << n << " threads";
    }
    setNumThreads(threads);

    // Each KeyLine is described on its own: any class_id, repeated or negative.
    std::vector<KeyLine> renumbered = keylines;
    for (size_t i = 0; i < renumbered.size(); i++)
        renumbered[i].class_id = (int)(i % 3) - 1;
    Mat descriptors;
    computeLBD(gray, renumbered, descriptors);
    EXPECT_EQ(0, cvtest::norm(reference, descriptors, NORM_INF));

    // The thread's buffers from a larger and a smaller image change nothing; nor does a
    // descriptors array of another size or type.
    Mat large;
    resize(gray, large, Size(), 2.0, 2.0);
    std::vector<KeyLine> largeLines;
    createLSDAdvance()->detect(large, largeLines);
    Mat other(3, 5, CV_32F);
    computeLBD(large, largeLines, other);
    computeLBD(gray(Rect(0, 0, 50, 40)).clone(), std::vector<KeyLine>(), other);
    EXPECT_EQ(0, other.rows);
    EXPECT_EQ(32, other.cols);
    EXPECT_EQ(CV_8UC1, other.type());
    computeLBD(gray, keylines, other);
    EXPECT_EQ(0, cvtest::norm(reference, other, NORM_INF));
}

TEST(LSDAdvance_LBD, calls_from_several_threads_at_once_give_the_serial_descriptors)
{
    const Mat gray = buildingGray();
    // Different sizes, so that each thread's buffers are sized and resized while the others work.
    const std::vector<Mat> images = { gray, gray(Rect(0, 0, 300, 200)).clone(), gray(Rect(100, 50, 700, 500)).clone(),
                                      gray(Rect(20, 300, 400, 300)).clone() };
    std::vector<std::vector<KeyLine> > keylines(images.size());
    std::vector<Mat> serial(images.size());
    for (size_t t = 0; t < images.size(); t++)
    {
        createLSDAdvance()->detect(images[t], keylines[t]);
        ASSERT_GT(keylines[t].size(), 20u);
        computeLBD(images[t], keylines[t], serial[t]);
    }
    std::vector<Mat> parallel(images.size());
    std::vector<std::string> errors(images.size());
    std::vector<std::thread> threads;
    for (size_t t = 0; t < images.size(); t++)
        threads.emplace_back([&, t] {
            try
            {
                // Three passes over all the images, each thread starting with its own.
                for (int pass = 0; pass < 3; pass++)
                    for (size_t k = 0; k < images.size(); k++)
                    {
                        const size_t i = (t + k) % images.size();
                        Mat descriptors;
                        computeLBD(images[i], keylines[i], descriptors);
                        if (i == t)
                            parallel[t] = descriptors;
                    }
            }
            catch (const std::exception& e)
            {
                errors[t] = e.what();
            }
        });
    for (std::thread& th : threads)
        th.join();
    for (size_t t = 0; t < images.size(); t++)
    {
        SCOPED_TRACE(t);
        EXPECT_EQ("", errors[t]);
        ASSERT_EQ(serial[t].size(), parallel[t].size());
        EXPECT_EQ(0, cvtest::norm(serial[t], parallel[t], NORM_INF));
    }
}

// Images with a side above 32767 px are sampled one row at a time: the descriptors of lines far
// from where the image differs from a crop are those of the crop, the oracle's.
TEST(LSDAdvance_LBD, wide_images_give_the_descriptors_of_a_crop)
{
    const Mat gray = buildingGray();
    Mat wide(gray.rows / 4, 33000, CV_8UC1, Scalar(128));
    const Mat part = gray(Rect(0, 0, 500, gray.rows / 4));
    part.copyTo(wide(Rect(0, 0, part.cols, part.rows)));
    RNG rng(5);
    std::vector<KeyLine> keylines = randomKeyLines(rng, part.size(), 400, 2.0, 200.0);
    // Regions (63 rows, 32 either side) that stay 10 px away from the crop's right side.
    keylines.erase(std::remove_if(keylines.begin(), keylines.end(), [&](const KeyLine& k) {
                       return std::max(k.startPointX, k.endPointX) + k.numOfPixels / 2 + 45 > part.cols;
                   }),
                   keylines.end());
    ASSERT_GT(keylines.size(), 50u);
    Mat fromWide, fromPart;
    computeLBD(wide, keylines, fromWide);
    expectLikeBinaryDescriptor(part, keylines);
    computeLBD(part, keylines, fromPart);
    EXPECT_EQ(0, cvtest::norm(fromPart, fromWide, NORM_INF));
}

TEST(LSDAdvance_LBD, BinaryDescriptorMatcher_matches_them_as_it_matches_line_descriptors)
{
    const Mat gray = buildingGray();
    Mat warped;
    const Mat H = (Mat_<double>(3, 3) << 0.95, 0.08, 12, -0.05, 1.02, 8, 1e-5, 2e-5, 1);
    warpPerspective(gray, warped, H, gray.size());
    std::vector<KeyLine> lines1, lines2;
    createLSDAdvance()->detect(gray, lines1);
    createLSDAdvance()->detect(warped, lines2);
    ASSERT_GT(lines1.size(), 100u);
    ASSERT_GT(lines2.size(), 100u);

    Mat ours1, ours2, theirs1, theirs2;
    computeLBD(gray, lines1, ours1);
    computeLBD(warped, lines2, ours2);
    const Ptr<BinaryDescriptor> oracle = BinaryDescriptor::createBinaryDescriptor();
    oracle->compute(gray, lines1, theirs1);
    oracle->compute(warped, lines2, theirs2);

    const Ptr<BinaryDescriptorMatcher> matcher = BinaryDescriptorMatcher::createBinaryDescriptorMatcher();
    const auto expectSame = [](const std::vector<DMatch>& a, const std::vector<DMatch>& b, const char* what) {
        ASSERT_EQ(a.size(), b.size()) << what;
        for (size_t i = 0; i < a.size(); i++)
        {
            EXPECT_EQ(a[i].queryIdx, b[i].queryIdx) << what << " " << i;
            EXPECT_EQ(a[i].trainIdx, b[i].trainIdx) << what << " " << i;
            EXPECT_EQ(a[i].distance, b[i].distance) << what << " " << i;
        }
    };
    std::vector<DMatch> theirs, ours, mixed, mixedBack;
    matcher->match(theirs1, theirs2, theirs);
    matcher->match(ours1, ours2, ours);
    matcher->match(ours1, theirs2, mixed);
    matcher->match(theirs1, ours2, mixedBack);
    expectSame(theirs, ours, "match, ours");
    expectSame(theirs, mixed, "match, ours against line_descriptor's");
    expectSame(theirs, mixedBack, "match, line_descriptor's against ours");
    int close = 0;
    for (const DMatch& m : ours)
        close += m.distance < 30;
    EXPECT_GT(close, 30);

    std::vector<std::vector<DMatch> > theirsK, oursK;
    matcher->knnMatch(theirs1, theirs2, theirsK, 2);
    matcher->knnMatch(ours1, theirs2, oursK, 2);
    ASSERT_EQ(theirsK.size(), oursK.size());
    for (size_t i = 0; i < theirsK.size(); i++)
        expectSame(theirsK[i], oursK[i], "knnMatch");
}

TEST(LSDAdvance_LBD, detectAndCompute_is_detect_then_computeLBD)
{
    const Mat gray = buildingGray();
    Mat mask = Mat::zeros(gray.size(), CV_8UC1);
    mask(Rect(40, 30, 300, 250)).setTo(255);
    for (const bool masked : { false, true })
    {
        SCOPED_TRACE(masked ? "mask" : "no mask");
        const Mat m = masked ? mask : Mat();
        std::vector<KeyLine> keylines, expected;
        Mat descriptors, expectedDescriptors;
        createLSDAdvance()->detectAndCompute(gray, keylines, descriptors, m);
        createLSDAdvance()->detect(gray, expected, m);
        computeLBD(gray, expected, expectedDescriptors);
        ASSERT_EQ(expected.size(), keylines.size());
        ASSERT_GT(keylines.size(), 30u);
        for (size_t i = 0; i < keylines.size(); i++)
        {
            EXPECT_EQ(expected[i].startPointX, keylines[i].startPointX);
            EXPECT_EQ(expected[i].endPointY, keylines[i].endPointY);
            EXPECT_EQ(expected[i].response, keylines[i].response);
        }
        EXPECT_EQ(0, cvtest::norm(expectedDescriptors, descriptors, NORM_INF));
    }
    Mat bgr;
    cvtColor(gray, bgr, COLOR_GRAY2BGR);
    std::vector<KeyLine> keylines;
    Mat descriptors;
    EXPECT_THROW(createLSDAdvance()->detectAndCompute(Mat(10, 10, CV_32F), keylines, descriptors), cv::Exception);
    createLSDAdvance()->detectAndCompute(bgr, keylines, descriptors);
    EXPECT_EQ((int)keylines.size(), descriptors.rows);
}

// A bad call throws a cv::Exception whose message holds each of `mentions`.
void expectRejected(const Mat& image, const std::vector<KeyLine>& keylines, int code,
                    const std::vector<std::string>& mentions)
{
    Mat descriptors;
    try
    {
        computeLBD(image, keylines, descriptors);
        ADD_FAILURE() << "accepted";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(code, e.code) << e.err;
        for (const std::string& m : mentions)
            EXPECT_NE(std::string::npos, e.err.find(m)) << "'" << m << "' not in: " << e.err;
    }
}

TEST(LSDAdvance_LBD, rejects_bad_images_and_keylines_with_a_clear_exception)
{
    const Mat gray = buildingGray();
    std::vector<KeyLine> good;
    linesToKeyLines(std::vector<Vec4f>{ Vec4f(10, 10, 100, 60), Vec4f(50, 200, 300, 210) }, gray.size(), good);

    expectRejected(Mat(), good, Error::StsBadArg, { "computeLBD", "empty" });
    expectRejected(Mat(40, 40, CV_16UC1, Scalar(3)), good, Error::BadDepth, { "computeLBD", "16UC1", "CV_8UC1" });
    expectRejected(Mat(40, 40, CV_32FC1, Scalar(3)), good, Error::BadDepth, { "computeLBD", "32FC1" });
    expectRejected(Mat(40, 40, CV_8UC2, Scalar(3)), good, Error::BadDepth, { "computeLBD", "8UC2" });

    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    struct Case
    {
        const char* name;
        std::function<void(KeyLine&)> spoil;
        int code;
        std::vector<std::string> mentions;
    };
    const std::vector<Case> cases = {
        { "octave 1", [](KeyLine& k) { k.octave = 1; }, Error::StsNotImplemented, { "KeyLine 1", "octave 1", "octave 0" } },
        { "NaN start", [&](KeyLine& k) { k.startPointX = k.sPointInOctaveX = nan; }, Error::StsOutOfRange, { "KeyLine 1", "finite" } },
        { "infinite end", [&](KeyLine& k) { k.endPointY = k.ePointInOctaveY = inf; }, Error::StsOutOfRange, { "KeyLine 1", "finite" } },
        { "NaN angle", [&](KeyLine& k) { k.angle = nan; }, Error::StsOutOfRange, { "KeyLine 1", "angle" } },
        { "right of the image", [&](KeyLine& k) { k.endPointX = k.ePointInOctaveX = (float)gray.cols + 1.5f; },
          Error::StsOutOfRange, { "KeyLine 1", "outside", "[-1, " } },
        { "above the image", [](KeyLine& k) { k.startPointY = k.sPointInOctaveY = -1.01f; }, Error::StsOutOfRange,
          { "KeyLine 1", "start point", "outside" } },
        { "far away", [](KeyLine& k) { k.startPointX = k.sPointInOctaveX = 1e9f; }, Error::StsOutOfRange, { "outside" } },
        { "zero length", [](KeyLine& k) {
              k.endPointX = k.ePointInOctaveX = k.startPointX;
              k.endPointY = k.ePointInOctaveY = k.startPointY;
          }, Error::StsBadArg, { "KeyLine 1", "zero length" } },
        { "no pixel", [](KeyLine& k) { k.numOfPixels = 0; }, Error::StsOutOfRange, { "KeyLine 1", "numOfPixels 0", "32767" } },
        { "negative pixels", [](KeyLine& k) { k.numOfPixels = -5; }, Error::StsOutOfRange, { "numOfPixels -5" } },
        { "too many pixels", [](KeyLine& k) { k.numOfPixels = 40000; }, Error::StsOutOfRange, { "numOfPixels 40000" } },
        { "octave copy elsewhere", [](KeyLine& k) { k.sPointInOctaveX += 3; }, Error::StsBadArg,
          { "KeyLine 1", "sPointInOctave", "startPoint" } },
    };
    for (const Case& c : cases)
    {
        SCOPED_TRACE(c.name);
        std::vector<KeyLine> keylines = good;
        c.spoil(keylines[1]);
        expectRejected(gray, keylines, c.code, c.mentions);
    }
    // A rejected call leaves the next one correct.
    expectLikeBinaryDescriptor(gray, good);
}

}} // namespace

#endif
