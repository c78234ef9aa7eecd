// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 1: adaptive length suppression with the inter-frame count factor: its thresholds, its
// modes (the frame's alpha) and its strong segments.

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

// Relative margin around the square of a positive length within which the squared length of a
// segment does not decide whether segmentLength() reaches that length: hypot is within an ulp of
// the true length and dx^2 + dy^2 within a few of its square, far inside the margin.
constexpr double kSquareMargin = 1e-9;

// segmentLength(s) >= length, decided without libm's hypot unless the squared length is too near.
bool atLeastAsLong(const Vec4f& s, double length)
{
    if (length > 0)
    {
        const double dx = (double)s[2] - s[0], dy = (double)s[3] - s[1];
        const double squared = dx * dx + dy * dy, square = length * length;
        if (squared > square * (1 + kSquareMargin))
            return true;
        if (squared < square * (1 - kSquareMargin))
            return false;
    }
    return segmentLength(s) >= length;
}

bool longOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses, size_t i,
                  double minLength, double minResponse)
{
    return atLeastAsLong(segments[i], minLength) || (!responses.empty() && responses[i] >= minResponse);
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

void LengthFilter::measure(const std::vector<Vec4f>& base, const Mat* gray, const LengthFilterParams& p,
                           KnownResponses& known, LSDAdvanceStats& stats)
{
    const int64 start = getTickCount();
    params = p;
    const bool filtering = p.lengthFilterMode != LSDAdvance::LENGTH_FILTER_NONE;
    unitMinLength = filtering ? p.lengthThresholdScale * adaptiveMinLength(base, 1.0, p.lengthThresholdRule) : 0.0;
    // The responses of the base segments give the threshold of the strong ones, as their lengths
    // give the length threshold; computed only when strong segments are kept.
    strong = filtering && p.keepStrongSegments && gray;
    unitMinResponse = strong ? p.lengthThresholdScale *
                                   adaptiveMinResponse(known.complete(*gray, base), 1.0, p.lengthThresholdRule)
                             : 0.0;
    stats.filterMs += elapsedMs(start);
}

void LengthFilter::apply(const std::vector<Vec4f>& in, const Mat* gray, const KeptCounts& history,
                         KnownResponses& known, std::vector<Vec4f>& kept, std::vector<int>& keptFrom,
                         LSDAdvanceStats& stats)
{
    const int64 start = getTickCount();
    if (params.lengthFilterMode == LSDAdvance::LENGTH_FILTER_NONE)
    {
        kept = in;
        keptFrom.resize(in.size());
        for (size_t i = 0; i < in.size(); i++)
            keptFrom[i] = (int)i;
        stats.filteredSegments = (int)in.size();
        stats.filterMs += elapsedMs(start);
        return;
    }
    // Fused segments have responses of their own; the others have their base segment's.
    const std::vector<float> none;
    const std::vector<float>& responses = strong ? known.complete(*gray, in) : none;
    double alpha = 1.0;  // the first two frames of a sequence, and LENGTH_FILTER_ADAPTIVE
    if (history.frames >= 2)
    {
        if (params.lengthFilterMode == LSDAdvance::LENGTH_FILTER_INTERFRAME)
            alpha = interFrameAlpha(history.previous, history.beforePrevious);
        else if (params.lengthFilterMode == LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS)
            alpha = continuousInterFrameAlpha(history.previous, history.beforePrevious);
        else if (params.lengthFilterMode == LSDAdvance::LENGTH_FILTER_COUNT_TRACKING)
            alpha = countTrackingAlpha(countLongOrStrong(in, responses, unitMinLength, unitMinResponse),
                                       history.previous, history.beforePrevious);
    }
    stats.alpha = alpha;
    stats.minLength = alpha * unitMinLength;
    stats.minResponse = responses.empty() ? 0.0 : alpha * unitMinResponse;
    keepLongOrStrong(in, responses, stats.minLength, stats.minResponse, kept, &keptFrom);
    stats.filteredSegments = (int)kept.size();
    stats.filterMs += elapsedMs(start);
}

}}} // namespace cv::ximgproc::lsda
