// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// A client that ships its own copy of line_descriptor, with the include guard of
// opencv2/line_descriptor.hpp, includes it before the module: the main header still compiles
// (it only names KeyLine), and detect() on segments works.

#define __OPENCV_LINE_DESCRIPTOR_HPP__  // what the client's copy defines
#include "opencv2/lsd_advance/lsd_advance.hpp"

#include "opencv2/ts.hpp"

namespace opencv_test { namespace {

TEST(LSDAdvance_Headers, main_header_compiles_after_a_client_header_with_line_descriptors_guard)
{
    Mat img(64, 64, CV_8UC1, Scalar(0));
    rectangle(img, Rect(16, 16, 32, 32), Scalar(255), FILLED);
    std::vector<Vec4f> lines;
    Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
    detector->detect(img, lines);
    EXPECT_EQ(4u, lines.size());
}

}} // namespace
