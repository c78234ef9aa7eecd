// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The main header compiles alone, without line_descriptor: it is the first include of this file,
// and nothing it includes brings line_descriptor in (only keylines.hpp needs it).

#include "opencv2/lsd_advance/lsd_advance.hpp"

#ifdef __OPENCV_LINE_DESCRIPTOR_HPP__
#error "opencv2/lsd_advance/lsd_advance.hpp includes opencv2/line_descriptor.hpp"
#endif
#ifdef __OPENCV_DESCRIPTOR_HPP__
#error "opencv2/lsd_advance/lsd_advance.hpp includes opencv2/line_descriptor/descriptor.hpp"
#endif

#include "opencv2/ts.hpp"

namespace opencv_test { namespace {

TEST(LSDAdvance_Headers, main_header_alone_declares_a_detector_that_detects)
{
    Mat img(64, 64, CV_8UC1, Scalar(0));
    rectangle(img, Rect(16, 16, 32, 32), Scalar(255), FILLED);
    std::vector<Vec4f> lines;
    ximgproc::createLSDAdvance()->detect(img, lines);
    EXPECT_EQ(4u, lines.size());
}

}} // namespace
