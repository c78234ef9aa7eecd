// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0: input conversion (images and segment arrays) and OpenCV's LSD as the base detector.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

Mat toGray8U(InputArray image)
{
    if (image.empty())
        CV_Error(Error::StsBadArg, "LSDAdvance: the input image is empty; expected a non-empty "
                                   "CV_8UC1 (gray), CV_8UC3 (BGR) or CV_8UC4 (BGRA) image");
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
                  ("LSDAdvance: unsupported image type %s (%dx%d); accepted: CV_8UC1 (gray), "
                   "CV_8UC3 (BGR), CV_8UC4 (BGRA)",
                   typeToString(type).c_str(), image.cols(), image.rows()));
    return gray;
}

Ptr<LineSegmentDetector> createBaseLsd(const LsdParams& p)
{
    return createLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance,
                                     p.logEps, p.densityThreshold, p.numBins);
}

std::vector<Vec4f> toSegments(InputArray lines, const char* what)
{
    std::vector<Vec4f> segments;
    if (lines.empty())
        return segments;
    const Mat m = lines.getMat();
    if (m.type() != CV_32FC4 || (m.rows != 1 && m.cols != 1))
        CV_Error_(Error::StsBadArg, ("%s must be an N x 1 or 1 x N CV_32FC4 array (std::vector<Vec4f>), got %s %dx%d",
                                     what, typeToString(m.type()).c_str(), m.cols, m.rows));
    m.reshape(4, (int)m.total()).copyTo(segments);
    return segments;
}

}}} // namespace cv::ximgproc::lsda
