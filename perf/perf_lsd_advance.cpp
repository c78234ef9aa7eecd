// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Every LSDAdvance case has the same case for OpenCV's LSD, FLD and EDLines (and ELSED when the
// optional peer is built: cmake -DLSD_ADVANCE_ELSED_DIR=<dir>), so that ratios come from one run
// (doc/performance.md).

#include "perf_precomp.hpp"
#include "opencv2/ximgproc.hpp"
#include "opencv2/core/utils/filesystem.hpp"

#ifdef LSD_ADVANCE_HAVE_ELSED
#include "ELSED.h"
#endif

namespace opencv_test { namespace {

using namespace cv::ximgproc;

enum Method
{
    LSD,                      // OpenCV's LineSegmentDetector, defaults
    FLD,                      // FastLineDetector, defaults
    EDLINES,                  // EdgeDrawing's EDLines, defaults
    LSDA,                     // LSDAdvance, defaults (PRESET_MOST_ACCURATE)
    LSDA_BASE_ONLY,           // LSDAdvance's default base (its own LSD), stages off
    LSDA_ON_OPENCV_LSD_FULL,  // LSDAdvance on OpenCV's LSD with the default base's set-up (scale 1, no refinement)
    LSDA_ON_OPENCV_LSD,       // LSDAdvance on OpenCV's LSD with OpenCV's default set-up (the paper's base)
    LSDA_ON_FLD,              // LSDAdvance on FastLineDetector
    LSDA_FASTEST,             // LSDAdvance, PRESET_FASTEST
    LSDA_ON_EDLINES,          // LSDAdvance on EDLines
    LSDA_ON_EDLINES_TUNED,    // LSDAdvance on EDLines, the sweep's best set-up (doc/performance.md)
    ELSED                     // the optional peer ELSED, defaults; a case only when it is built
};
#ifdef LSD_ADVANCE_HAVE_ELSED
#define LSDA_PEER_METHODS , ELSED
#else
#define LSDA_PEER_METHODS
#endif
// Expands LSDA_PEER_METHODS before CV_ENUM turns the list into the printed case names.
#define LSDA_METHOD_ENUM(...) CV_ENUM(__VA_ARGS__)
LSDA_METHOD_ENUM(MethodType, LSD, FLD, EDLINES, LSDA, LSDA_BASE_ONLY, LSDA_ON_OPENCV_LSD_FULL, LSDA_ON_OPENCV_LSD,
                 LSDA_ON_FLD, LSDA_FASTEST, LSDA_ON_EDLINES, LSDA_ON_EDLINES_TUNED LSDA_PEER_METHODS)

typedef std::function<void(const Mat&, std::vector<Vec4f>&)> DetectFunction;

DetectFunction makeDetector(int method)
{
    if (method == LSD)
    {
        Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
        return [lsd](const Mat& image, std::vector<Vec4f>& lines) { lsd->detect(image, lines); };
    }
    if (method == FLD)
    {
        Ptr<FastLineDetector> fld = createFastLineDetector();
        return [fld](const Mat& image, std::vector<Vec4f>& lines) { fld->detect(image, lines); };
    }
    if (method == EDLINES)
    {
        Ptr<EdgeDrawing> ed = createEdgeDrawing();
        return [ed](const Mat& image, std::vector<Vec4f>& lines) {
            ed->detectEdges(image);
            ed->detectLines(lines);
        };
    }
#ifdef LSD_ADVANCE_HAVE_ELSED
    if (method == ELSED)
    {
        std::shared_ptr<upm::ELSED> elsed = std::make_shared<upm::ELSED>();
        return [elsed](const Mat& image, std::vector<Vec4f>& lines) { lines = elsed->detect(image); };
    }
#endif
    Ptr<LSDAdvance> advance =
        createLSDAdvance(method == LSDA_FASTEST ? LSDAdvance::PRESET_FASTEST : LSDAdvance::PRESET_MOST_ACCURATE);
    if (method == LSDA_ON_EDLINES || method == LSDA_ON_EDLINES_TUNED)
        advance->setBaseDetector(LSDAdvance::BASE_EDLINES);
    if (method == LSDA_BASE_ONLY)
    {
        advance->setLengthFilterMode(LSDAdvance::LENGTH_FILTER_NONE);
        advance->setMergeStrategy(LSDAdvance::MERGE_NONE);
    }
    else if (method == LSDA_ON_OPENCV_LSD_FULL)
        advance->setBaseDetector(LSDAdvance::BASE_LSD);
    else if (method == LSDA_ON_OPENCV_LSD)  // the paper's base
    {
        advance->setBaseDetector(LSDAdvance::BASE_LSD);
        advance->setLSDParams(createLSDAdvance(LSDAdvance::PRESET_PAPER)->getLSDParams());
    }
    else if (method == LSDA_ON_FLD)
        advance->setBaseDetector(LSDAdvance::BASE_FLD);
    else if (method == LSDA_ON_EDLINES_TUNED)
    {
        EdgeDrawing::Params ed = advance->getEDLinesParams();
        ed.Sigma = 0.5f;
        ed.GradientThresholdValue = 30;
        advance->setEDLinesParams(ed);
        advance->setLengthThresholdRule(LSDAdvance::LENGTH_THRESHOLD_PAPER);
        advance->setMaxPerpendicularOffset(2.0);
    }
    return [advance](const Mat& image, std::vector<Vec4f>& lines) { advance->detect(image, lines); };
}

// The body of every case: times `method` on `image` (TEST_CYCLE needs the test's own members).
#define MEASURE_DETECTION(image, method)                 \
    ASSERT_FALSE((image).empty());                       \
    const DetectFunction detect = makeDetector(method);  \
    std::vector<Vec4f> lines;                            \
    TEST_CYCLE() detect(image, lines);                   \
    EXPECT_FALSE(lines.empty());                         \
    SANITY_CHECK_NOTHING()

typedef perf::TestBaseWithParam<tuple<std::string, MethodType> > LineDetection_Image;

PERF_TEST_P(LineDetection_Image, detect,
            testing::Combine(testing::Values("building.jpg", "graf1.png"), MethodType::all()))
{
    const Mat image = imread(samples::findFile(get<0>(GetParam())), IMREAD_GRAYSCALE);
    MEASURE_DETECTION(image, get<1>(GetParam()));
}

// An image of the evaluation data (LSD_ADVANCE_DATA_DIR): skipped without it, except under
// CI=true, where it fails.
Mat evaluationImage(const std::string& relativePath)
{
    const char* root = getenv("LSD_ADVANCE_DATA_DIR");
    const char* ci = getenv("CI");
    const std::string path = root ? utils::fs::join(root, relativePath) : std::string();
    if (path.empty() || !utils::fs::exists(path))
    {
        if (ci && std::string(ci) == "true")
            CV_Error_(Error::StsError, ("evaluation image %s not found: set LSD_ADVANCE_DATA_DIR to ../shared/data",
                                        relativePath.c_str()));
        throw SkipTestException("LSD_ADVANCE_DATA_DIR does not hold " + relativePath);
    }
    return imread(path, IMREAD_GRAYSCALE);
}

typedef perf::TestBaseWithParam<tuple<std::string, MethodType> > LineDetection_Data;

// Two YorkUrban images (640x480) and two KITTI frames (1226x370).
PERF_TEST_P(LineDetection_Data, detect,
            testing::Combine(testing::Values("yorkurban/images/P1020177.jpg", "yorkurban/images/P1080091.jpg",
                                             "kitti_seq1/image_l/000000.png", "kitti_seq1/image_l/000030.png"),
                             MethodType::all()))
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

typedef perf::TestBaseWithParam<tuple<Size, MethodType> > LineDetection_Synthetic;

PERF_TEST_P(LineDetection_Synthetic, detect,
            testing::Combine(testing::Values(Size(640, 480), Size(1226, 370), Size(1920, 1080)),
                             testing::Values(MethodType(LSD), MethodType(LSDA), MethodType(LSDA_ON_EDLINES))))
{
    const Mat image = syntheticScene(get<0>(GetParam()));
    MEASURE_DETECTION(image, get<1>(GetParam()));
}

}} // namespace
