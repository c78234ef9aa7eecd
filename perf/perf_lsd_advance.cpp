// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Each LSDAdvance case has the same case for OpenCV's LSD, so that ratios come from one run.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

using namespace cv::ximgproc;

enum Detector { LSD, LSD_ADVANCE };
CV_ENUM(DetectorType, LSD, LSD_ADVANCE)

typedef std::function<void(const Mat&, std::vector<Vec4f>&)> DetectFunction;

DetectFunction makeDetector(int detector)
{
    if (detector == LSD)
    {
        Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
        return [lsd](const Mat& image, std::vector<Vec4f>& lines) { lsd->detect(image, lines); };
    }
    Ptr<LSDAdvance> advance = createLSDAdvance();
    return [advance](const Mat& image, std::vector<Vec4f>& lines) { advance->detect(image, lines); };
}

typedef perf::TestBaseWithParam<tuple<std::string, DetectorType> > LineDetection_Image;

PERF_TEST_P(LineDetection_Image, detect,
            testing::Combine(testing::Values("building.jpg", "graf1.png"), DetectorType::all()))
{
    const Mat image = imread(samples::findFile(get<0>(GetParam())), IMREAD_GRAYSCALE);
    ASSERT_FALSE(image.empty());
    const DetectFunction detect = makeDetector(get<1>(GetParam()));
    std::vector<Vec4f> lines;
    TEST_CYCLE() detect(image, lines);
    EXPECT_FALSE(lines.empty());
    SANITY_CHECK_NOTHING();
}

// Rectangles and bars with noise, at the usual camera sizes.
Mat syntheticScene(const Size& size)
{
    Mat img(size, CV_8UC1, Scalar(60));
    RNG rng(size.area());
    for (int i = 0; i < 40; i++)
    {
        const Point a(rng.uniform(0, size.width), rng.uniform(0, size.height));
        const Point b(rng.uniform(0, size.width), rng.uniform(0, size.height));
        rectangle(img, a, b, Scalar(rng.uniform(0, 256)), i % 4 == 0 ? 3 : FILLED);
    }
    Mat noise(size, CV_8SC1);
    rng.fill(noise, RNG::NORMAL, 0, 6);
    cv::add(img, noise, img, noArray(), CV_8U);
    return img;
}

typedef perf::TestBaseWithParam<tuple<Size, DetectorType> > LineDetection_Synthetic;

PERF_TEST_P(LineDetection_Synthetic, detect,
            testing::Combine(testing::Values(Size(640, 480), Size(1226, 370), Size(1920, 1080)),
                             DetectorType::all()))
{
    const Mat image = syntheticScene(get<0>(GetParam()));
    const DetectFunction detect = makeDetector(get<1>(GetParam()));
    std::vector<Vec4f> lines;
    TEST_CYCLE() detect(image, lines);
    EXPECT_FALSE(lines.empty());
    SANITY_CHECK_NOTHING();
}

}} // namespace
