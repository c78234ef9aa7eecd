// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The LBD descriptor of KeyLines: the module's computeLBD and line_descriptor's
// BinaryDescriptor::compute (its oracle, the same descriptors) on the same lines, so that their
// ratio comes from one run: the lines of PRESET_FRONT_END (a front end's budget of 60) and of the
// defaults, on building.jpg, a YorkUrban image (640x480) and a KITTI frame (1226x370).

#include "perf_precomp.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

namespace opencv_test { namespace {

using namespace cv::ximgproc;

typedef perf::TestBaseWithParam<tuple<std::string, int, std::string> > LBD_Image;

PERF_TEST_P(LBD_Image, describe,
            testing::Combine(testing::Values("building.jpg", "yorkurban/images/P1020177.jpg",
                                             "kitti_seq1/image_l/000000.png"),
                             testing::Values((int)LSDAdvance::PRESET_MOST_ACCURATE, (int)LSDAdvance::PRESET_FRONT_END),
                             testing::Values("computeLBD", "BinaryDescriptor")))
{
    const std::string name = get<0>(GetParam());
    const Mat image = name.find('/') == std::string::npos ? imread(samples::findFile(name), IMREAD_GRAYSCALE)
                                                          : evaluationImage(name);
    ASSERT_FALSE(image.empty());
    std::vector<line_descriptor::KeyLine> keylines;
    createLSDAdvance((LSDAdvance::Preset)get<1>(GetParam()))->detect(image, keylines);
    ASSERT_FALSE(keylines.empty());
    Mat descriptors;
    if (get<2>(GetParam()) == "computeLBD")
    {
        TEST_CYCLE() computeLBD(image, keylines, descriptors);
    }
    else
    {
        const Ptr<line_descriptor::BinaryDescriptor> descriptor = line_descriptor::BinaryDescriptor::createBinaryDescriptor();
        TEST_CYCLE() descriptor->compute(image, keylines, descriptors);
    }
    EXPECT_EQ((int)keylines.size(), descriptors.rows);
    EXPECT_EQ(32, descriptors.cols);
    SANITY_CHECK_NOTHING();
}

}} // namespace

#endif
