// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Every method of the benchmark apps (apps/lsd_advance_bench/line_methods.hpp: OpenCV's LSD,
// FLD and EDLines, PL-VINS's LSD set-up, ELSED when the optional peer is built with
// cmake -DLSD_ADVANCE_ELSED_DIR=<dir>, and each LSDAdvance variant of the method files
// apps/lsd_advance_bench/methods/<name>.yml) on the same images, so that ratios come from one
// run (perf/perf_ratios.sh).

#include "perf_precomp.hpp"
#include "../apps/lsd_advance_bench/line_methods.hpp"

namespace opencv_test { namespace {

// The body of every case: times `method` on `image` (TEST_CYCLE needs the test's own members).
#define MEASURE_DETECTION(image, method)                 \
    ASSERT_FALSE((image).empty());                       \
    const LineMethod detector = makeLineMethod(method);  \
    std::vector<Vec4f> lines;                            \
    TEST_CYCLE() detector.detect(image, lines);          \
    EXPECT_FALSE(lines.empty());                         \
    SANITY_CHECK_NOTHING()

typedef perf::TestBaseWithParam<tuple<std::string, std::string> > LineDetection_Image;

PERF_TEST_P(LineDetection_Image, detect,
            testing::Combine(testing::Values("building.jpg", "graf1.png"), testing::ValuesIn(lineMethodNames())))
{
    const Mat image = imread(samples::findFile(get<0>(GetParam())), IMREAD_GRAYSCALE);
    MEASURE_DETECTION(image, get<1>(GetParam()));
}

typedef perf::TestBaseWithParam<tuple<std::string, std::string> > LineDetection_Data;

// Two YorkUrban images (640x480) and two KITTI frames (1226x370).
PERF_TEST_P(LineDetection_Data, detect,
            testing::Combine(testing::Values("yorkurban/images/P1020177.jpg", "yorkurban/images/P1080091.jpg",
                                             "kitti_seq1/image_l/000000.png", "kitti_seq1/image_l/000030.png"),
                             testing::ValuesIn(lineMethodNames())))
{
    const Mat image = evaluationImage(get<0>(GetParam()));
    MEASURE_DETECTION(image, get<1>(GetParam()));
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

typedef perf::TestBaseWithParam<tuple<Size, std::string> > LineDetection_Synthetic;

PERF_TEST_P(LineDetection_Synthetic, detect,
            testing::Combine(testing::Values(Size(640, 480), Size(1226, 370), Size(1920, 1080)),
                             testing::Values("lsd", "lsdadvance", "lsdadvance_edlines")))
{
    const Mat image = syntheticScene(get<0>(GetParam()));
    MEASURE_DETECTION(image, get<1>(GetParam()));
}

}} // namespace
