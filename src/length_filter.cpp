// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 1: adaptive length suppression with the inter-frame count factor.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

double segmentLength(const Vec4f& s)
{
    return std::hypot((double)s[2] - s[0], (double)s[3] - s[1]);
}

namespace {

// r = (N(k-1) - N(k-2)) / N(k-2), 0 when N(k-2) = 0.
double countChange(int keptPrevious, int keptBeforePrevious)
{
    CV_CheckGE(keptPrevious, 0, "segment counts are not negative");
    CV_CheckGE(keptBeforePrevious, 0, "segment counts are not negative");
    return keptBeforePrevious == 0 ? 0.0 : (double)(keptPrevious - keptBeforePrevious) / keptBeforePrevious;
}

} // namespace

double interFrameAlpha(int keptPrevious, int keptBeforePrevious)
{
    const double r = countChange(keptPrevious, keptBeforePrevious);
    if (r < -0.1)
        return 1.0 - 0.2 * (1.0 + r);
    if (r <= 0.1)
        return 1.0;
    return std::min(1.0 + 0.1 * (r - 0.1), 1.2);
}

double continuousInterFrameAlpha(int keptPrevious, int keptBeforePrevious)
{
    const double r = countChange(keptPrevious, keptBeforePrevious);
    if (r < -0.1)
        return std::max(1.0 + 0.2 * (r + 0.1), 0.8);
    return interFrameAlpha(keptPrevious, keptBeforePrevious);
}

double countTrackingAlpha(int provisional, int keptPrevious, int keptBeforePrevious)
{
    CV_CheckGE(provisional, 0, "segment counts are not negative");
    CV_CheckGE(keptPrevious, 0, "segment counts are not negative");
    CV_CheckGE(keptBeforePrevious, 0, "segment counts are not negative");
    const double recent = 0.5 * (keptPrevious + keptBeforePrevious);
    if (recent <= 0)
        return 1.0;
    const double r = (provisional - recent) / recent;
    return std::min(std::max(1.0 + 0.5 * r, 0.8), 1.2);
}

int countAtLeast(const std::vector<Vec4f>& segments, double minLength)
{
    int count = 0;
    for (const Vec4f& s : segments)
        count += segmentLength(s) >= minLength;
    return count;
}

double adaptiveMinLength(const std::vector<Vec4f>& segments, double alpha, int rule)
{
    if (segments.empty())
        return 0.0;
    double sum = 0.0, sumSq = 0.0;
    for (const Vec4f& s : segments)
    {
        const double len = segmentLength(s);
        sum += len;
        sumSq += len * len;
    }
    const double n = (double)segments.size();
    const double mean = sum / n;
    if (mean <= 0.0)
        return 0.0;
    const double stddev = std::sqrt(std::max(sumSq / n - mean * mean, 0.0));
    if (rule == LSDAdvance::LENGTH_THRESHOLD_CAPPED)
        return std::min(mean, stddev) * alpha;
    return std::max((1.0 - std::abs(mean - stddev) / mean) * mean * alpha, 0.0);
}

void dropShortSegments(const std::vector<Vec4f>& segments, double minLength,
                       std::vector<Vec4f>& kept, std::vector<int>* keptFrom)
{
    kept.clear();
    kept.reserve(segments.size());
    if (keptFrom)
        keptFrom->clear();
    for (size_t i = 0; i < segments.size(); i++)
        if (segmentLength(segments[i]) >= minLength)
        {
            kept.push_back(segments[i]);
            if (keptFrom)
                keptFrom->push_back((int)i);
        }
}

}}} // namespace cv::ximgproc::lsda
