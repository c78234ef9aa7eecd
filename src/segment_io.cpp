// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The callers' arrays: images to gray, segment arrays to segments (checked), segments drawn.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

Mat toGray8U(InputArray image, const char* what)
{
    if (image.empty())
        CV_Error_(Error::StsBadArg, ("%s: the input image is empty; expected a non-empty "
                                     "CV_8UC1 (gray), CV_8UC3 (BGR) or CV_8UC4 (BGRA) image", what));
    const int type = image.type();
    if (type == CV_8UC1)
        return image.getMat();
    Mat gray;
    if (type == CV_8UC3)
        cvtColor(image, gray, COLOR_BGR2GRAY);
    else if (type == CV_8UC4)
        cvtColor(image, gray, COLOR_BGRA2GRAY);
    else
        CV_Error_(Error::BadDepth,
                  ("%s: unsupported image type %s (%dx%d); accepted: CV_8UC1 (gray), "
                   "CV_8UC3 (BGR), CV_8UC4 (BGRA)",
                   what, typeToString(type).c_str(), image.cols(), image.rows()));
    return gray;
}

void toSegments(InputArray lines, const char* what, std::vector<Vec4f>& segments)
{
    segments.clear();
    if (lines.empty())
        return;
    const Mat m = lines.getMat();
    if (m.type() != CV_32FC4 || (m.rows != 1 && m.cols != 1))
        CV_Error_(Error::StsBadArg, ("%s must be an N x 1 or 1 x N CV_32FC4 array (std::vector<Vec4f>), got %s %dx%d",
                                     what, typeToString(m.type()).c_str(), m.cols, m.rows));
    m.reshape(4, (int)m.total()).copyTo(segments);
}

std::vector<Vec4f> toSegments(InputArray lines, const char* what)
{
    std::vector<Vec4f> segments;
    toSegments(lines, what, segments);
    return segments;
}

void toImageSegments(InputArray lines, const char* what, std::vector<Vec4f>& segments)
{
    toSegments(lines, what, segments);
    if (!checkRange(Mat(segments), true, nullptr, -kMaxCoordinate, kMaxCoordinate))
        CV_Error_(Error::StsOutOfRange, ("%s must hold finite coordinates within [-%g, %g) px", what, kMaxCoordinate,
                                         kMaxCoordinate));
}

void drawSegments(InputOutputArray image, InputArray lines)
{
    if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3))
        CV_Error_(Error::StsBadArg, ("LSDAdvance::drawSegments: image must be a non-empty CV_8UC1 or CV_8UC3 "
                                     "image, got %s %dx%d", typeToString(image.type()).c_str(), image.cols(),
                                     image.rows()));
    // What detect() writes and LineSegmentDetector::drawSegments draws: N segments of 4 float or int
    // coordinates, as N x 1 (or 1 x N) 4-channel or N x 4 1-channel arrays.
    Mat segments = lines.getMat();
    const int count = segments.empty() ? 0 : segments.checkVector(4, -1, false);
    if (count < 0 || (count > 0 && segments.depth() != CV_32F && segments.depth() != CV_32S))
        CV_Error_(Error::StsBadArg, ("LSDAdvance::drawSegments: lines must be N segments (x1, y1, x2, y2) of CV_32F or "
                                     "CV_32S: std::vector<Vec4f> or <Vec4i>, an N x 1 4-channel or N x 4 1-channel "
                                     "Mat, got %s %dx%d", typeToString(segments.type()).c_str(), segments.cols,
                                     segments.rows));
    if (count > 0)
        segments = (segments.isContinuous() ? segments : segments.clone()).reshape(4, count);
    if (image.channels() == 1)
        cvtColor(image, image, COLOR_GRAY2BGR);
    Mat canvas = image.getMat();
    const Scalar red(0, 0, 255);
    for (int i = 0; i < count; i++)
        if (segments.depth() == CV_32F)
        {
            const Vec4f& s = segments.at<Vec4f>(i);
            line(canvas, Point2f(s[0], s[1]), Point2f(s[2], s[3]), red, 1);
        }
        else
        {
            const Vec4i& s = segments.at<Vec4i>(i);
            line(canvas, Point(s[0], s[1]), Point(s[2], s[3]), red, 1);
        }
}

}}} // namespace cv::ximgproc::lsda
