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
    return countLongOrStrong(segments, std::vector<float>(), minLength, 0.0);
}

namespace {

// The rule on values given by their sum, sum of squares and count (mean, population standard
// deviation), times alpha; 0 for no values.
double thresholdOf(double sum, double sumSq, double n, double alpha, int rule)
{
    if (n <= 0)
        return 0.0;
    const double mean = sum / n;
    if (mean <= 0.0)
        return 0.0;
    const double stddev = std::sqrt(std::max(sumSq / n - mean * mean, 0.0));
    if (rule == LSDAdvance::LENGTH_THRESHOLD_CAPPED)
        return std::min(mean, stddev) * alpha;
    return std::max((1.0 - std::abs(mean - stddev) / mean) * mean * alpha, 0.0);
}

bool longOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses, size_t i,
                  double minLength, double minResponse)
{
    return segmentLength(segments[i]) >= minLength || (!responses.empty() && responses[i] >= minResponse);
}

void checkResponses(const std::vector<Vec4f>& segments, const std::vector<float>& responses)
{
    CV_Assert(responses.empty() || responses.size() == segments.size());
}

} // namespace

double adaptiveMinLength(const std::vector<Vec4f>& segments, double alpha, int rule)
{
    double sum = 0.0, sumSq = 0.0;
    for (const Vec4f& s : segments)
    {
        const double len = segmentLength(s);
        sum += len;
        sumSq += len * len;
    }
    return thresholdOf(sum, sumSq, (double)segments.size(), alpha, rule);
}

double adaptiveMinResponse(const std::vector<float>& responses, double alpha, int rule)
{
    double sum = 0.0, sumSq = 0.0;
    for (float r : responses)
    {
        sum += r;
        sumSq += (double)r * r;
    }
    return thresholdOf(sum, sumSq, (double)responses.size(), alpha, rule);
}

void dropShortSegments(const std::vector<Vec4f>& segments, double minLength,
                       std::vector<Vec4f>& kept, std::vector<int>* keptFrom)
{
    keepLongOrStrong(segments, std::vector<float>(), minLength, 0.0, kept, keptFrom);
}

void keepLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                      double minLength, double minResponse, std::vector<Vec4f>& kept, std::vector<int>* keptFrom)
{
    checkResponses(segments, responses);
    kept.clear();
    kept.reserve(segments.size());
    if (keptFrom)
        keptFrom->clear();
    for (size_t i = 0; i < segments.size(); i++)
        if (longOrStrong(segments, responses, i, minLength, minResponse))
        {
            kept.push_back(segments[i]);
            if (keptFrom)
                keptFrom->push_back((int)i);
        }
}

int countLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                      double minLength, double minResponse)
{
    checkResponses(segments, responses);
    int count = 0;
    for (size_t i = 0; i < segments.size(); i++)
        count += longOrStrong(segments, responses, i, minLength, minResponse);
    return count;
}

}}} // namespace cv::ximgproc::lsda
