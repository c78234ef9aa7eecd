// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The mask of detect() and processSegments(): checked, and sampled along segments, so that every
// base (cut at the mask) and stage 3 (no fusion across it) keep off masked-out pixels.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

// The mask at the pixel nearest to (x, y), clamped into the image.
inline bool maskAt(const Mat& mask, double x, double y)
{
    const int col = std::min(std::max(cvRound(x), 0), mask.cols - 1);
    const int row = std::min(std::max(cvRound(y), 0), mask.rows - 1);
    return mask.at<uchar>(row, col) != 0;
}

// Samples from a to b at most 1 px apart, both ends included.
inline int sampleSteps(const Point2d& a, const Point2d& b)
{
    return std::max(1, (int)std::ceil(norm(b - a)));
}

} // namespace

Mat toMask(InputArray mask, Size imageSize, const char* what)
{
    if (mask.empty())
        return Mat();
    if (mask.type() != CV_8UC1 || mask.size() != imageSize)
        CV_Error_(Error::StsBadArg,
                  ("%s: the mask must be CV_8UC1 of the image's size %dx%d (or empty for none), got %s %dx%d",
                   what, imageSize.width, imageSize.height, typeToString(mask.type()).c_str(), mask.cols(),
                   mask.rows()));
    return mask.getMat();
}

bool inMask(const Mat& mask, const Point2d& a, const Point2d& b)
{
    const int steps = sampleSteps(a, b);
    const Point2d d = (b - a) * (1.0 / steps);
    for (int k = 0; k <= steps; k++)
        if (!maskAt(mask, a.x + d.x * k, a.y + d.y * k))
            return false;
    return true;
}

void cutAtMask(const Mat& mask, std::vector<Vec4f>& segments, std::vector<Vec4f>& pieces)
{
    pieces.clear();
    for (const Vec4f& s : segments)
    {
        // Outside the image there is no mask: the part of a segment there is left to the clipping.
        Vec4f inside;
        if (!clipToDomain(s, mask.size(), inside))
            continue;
        const Point2d a(inside[0], inside[1]), b(inside[2], inside[3]);
        const int steps = sampleSteps(a, b);
        const Point2d d = (b - a) * (1.0 / steps);
        int first = -1;  // first sample of the current in-mask run
        for (int k = 0; k <= steps + 1; k++)
        {
            const bool in = k <= steps && maskAt(mask, a.x + d.x * k, a.y + d.y * k);
            if (in && first < 0)
                first = k;
            if (in || first < 0)
                continue;
            if (first == 0 && k == steps + 1)
                pieces.push_back(s);  // wholly in the mask: unchanged
            else if (k - 1 > first)
                pieces.push_back(Vec4f((float)(a.x + d.x * first), (float)(a.y + d.y * first),
                                       (float)(a.x + d.x * (k - 1)), (float)(a.y + d.y * (k - 1))));
            first = -1;
        }
    }
    segments.swap(pieces);
}

}}} // namespace cv::ximgproc::lsda
