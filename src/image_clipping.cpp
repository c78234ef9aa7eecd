// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// After the stages: every segment clipped to the image domain along its own line.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

bool clipToDomain(const Vec4f& segment, const Size& imageSize, Vec4f& clipped)
{
    const double xMin = -0.5, yMin = -0.5, xMax = imageSize.width - 0.5, yMax = imageSize.height - 0.5;
    const auto inside = [&](double x, double y) { return x >= xMin && x <= xMax && y >= yMin && y <= yMax; };
    if (inside(segment[0], segment[1]) && inside(segment[2], segment[3]))
    {
        clipped = segment;
        return segment[0] != segment[2] || segment[1] != segment[3];
    }
    // Liang-Barsky: the part of a + t d, t in [0, 1], on the inner side of each edge.
    const double ax = segment[0], ay = segment[1], dx = (double)segment[2] - ax, dy = (double)segment[3] - ay;
    const double p[4] = { -dx, dx, -dy, dy };
    const double q[4] = { ax - xMin, xMax - ax, ay - yMin, yMax - ay };
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 4; k++)
    {
        if (p[k] == 0)
        {
            if (q[k] < 0)
                return false;  // parallel to this edge, outside it
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
    }
    if (!(t0 < t1))
        return false;
    // Rounding may leave a computed end a hair outside: put it on the edge.
    const auto onDomain = [&](double t, float& x, float& y) {
        x = (float)std::min(std::max(ax + t * dx, xMin), xMax);
        y = (float)std::min(std::max(ay + t * dy, yMin), yMax);
    };
    onDomain(t0, clipped[0], clipped[1]);
    onDomain(t1, clipped[2], clipped[3]);
    return clipped[0] != clipped[2] || clipped[1] != clipped[3];
}

void clipToImage(const std::vector<Vec4f>& segments, const Size& imageSize, std::vector<Vec4f>& clipped,
                 std::vector<int>& keptFrom)
{
    CV_Assert(imageSize.width > 0 && imageSize.height > 0);
    clipped.clear();
    keptFrom.clear();
    Vec4f c;
    for (size_t i = 0; i < segments.size(); i++)
        if (clipToDomain(segments[i], imageSize, c))
        {
            clipped.push_back(c);
            keptFrom.push_back((int)i);
        }
}

}}} // namespace cv::ximgproc::lsda
