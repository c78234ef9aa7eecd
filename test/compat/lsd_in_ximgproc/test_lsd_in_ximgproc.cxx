// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The module built against an OpenCV whose LineSegmentDetector has moved from imgproc to ximgproc
// (opencv#29349, opencv_contrib#4158), as the header layer of include/ lays it out: this file and
// the module's sources are compiled with it (cmake/standalone.cmake, target
// opencv_test_lsd_advance_lsd_in_ximgproc). BASE_LSD then detects with cv::ximgproc's.

#include "opencv2/ts.hpp"
#include "opencv2/lsd_advance.hpp"
#include "opencv2/imgcodecs.hpp"
#include "../../../src/opencv_lsd.hpp"
#include "../../../src/stages.hpp"

#include <type_traits>

// Whether cv:: still declares createLineSegmentDetector: a call from a namespace that sees both
// cv and a fallback template (each at global scope, through sibling namespaces) resolves to cv's
// when it exists, a non-template taking no argument being the better match.
namespace lsd_in_imgproc_fallback {
struct NotInImgproc
{
};
template <class... A> NotInImgproc createLineSegmentDetector(A...);
} // namespace lsd_in_imgproc_fallback
namespace lsd_in_imgproc_lookup {
using namespace ::cv;
using namespace ::lsd_in_imgproc_fallback;
typedef decltype(createLineSegmentDetector()) Found;
static_assert(std::is_same<Found, NotInImgproc>::value, "the layer hides imgproc's LineSegmentDetector");
} // namespace lsd_in_imgproc_lookup

static_assert(std::is_same<cv::ximgproc::lsda::OpenCVLineSegmentDetector, cv::ximgproc::LineSegmentDetector>::value,
              "BASE_LSD uses cv::ximgproc::LineSegmentDetector when imgproc has none");
static_assert(cv::ximgproc::lsda::kHaveOpenCVLsd, "an OpenCV with LineSegmentDetector in ximgproc has one");

namespace opencv_test { namespace {

using namespace cv::ximgproc;

TEST(LSDAdvance_LsdInXimgproc, base_lsd_detects_with_the_ximgproc_lineSegmentDetector)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    for (LSDAdvance::Preset preset : { LSDAdvance::PRESET_MOST_ACCURATE, LSDAdvance::PRESET_PAPER })
    {
        Ptr<LSDAdvance> d = createLSDAdvance(preset);
        d->setBaseDetector(LSDAdvance::BASE_LSD);
        LSDAdvance::LSDParams unsmoothed = d->getLSDParams();
        unsmoothed.fullScaleSigma = 0;  // OpenCV's LSD reads the image as it is at scale 1
        d->setLSDParams(unsmoothed);
        std::vector<Vec4f> lines, base, expected;
        d->detect(img, lines);
        EXPECT_FALSE(lines.empty()) << preset;
        d->getLastStageOutputs(base, noArray(), noArray(), noArray());
        const LSDAdvance::LSDParams p = d->getLSDParams();
        cv::ximgproc::createLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance,
                                                p.logEps, p.densityThreshold, p.numBins)
            ->detect(img, expected);
        ASSERT_FALSE(expected.empty()) << preset;
        lsda::toFullResolution(expected, p.scale);  // as BASE_LSD moves them below scale 1
        EXPECT_EQ(expected, base) << preset;
    }
}

}} // namespace

CV_TEST_MAIN("")
