// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// After the clipping: what a front end keeps of the lines. A minimum length, an order that means
// something (strongest first with an image, longest first without; or that order taken across
// bins of direction), and a budget of the first N.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

double selectionMinLength(const SelectionParams& params, Size imageSize)
{
    const double relative = imageSize.empty() ? 0.0 : params.minLineLengthRatio * std::min(imageSize.width, imageSize.height);
    return std::max(params.minLineLength, relative);
}

void strongestFirst(const std::vector<float>& keys, int maxLines, std::vector<int>& order)
{
    CV_Assert(maxLines >= 0);
    const auto stronger = [&](int a, int b) { return keys[a] > keys[b] || (keys[a] == keys[b] && a < b); };
    const size_t kept = maxLines > 0 ? std::min(order.size(), (size_t)maxLines) : order.size();
    // A budget needs only its first lines in order; all of them, an introsort rather than the heap
    // sort partial_sort would make of it. Both give the one order: no two lines are equivalent.
    if (kept < order.size())
        std::partial_sort(order.begin(), order.begin() + kept, order.end(), stronger);
    else
        std::sort(order.begin(), order.end(), stronger);
    order.resize(kept);
}

// The column (or row) of a grid of `cells` equal cells over [start, start + size) that holds x.
static int cellOf(double x, double start, double size, int cells)
{
    const double cell = size > 0 ? std::floor((x - start) * cells / size) : 0.0;
    return (int)std::min<double>(cells - 1, std::max(0.0, cell));
}

void acrossDirections(const std::vector<Vec4f>& lines, int bins, int cells, const Rect2f& area, int maxLines,
                      std::vector<int>& order, std::vector<int>& rankInBin)
{
    CV_Assert(bins >= 1 && cells >= 1 && maxLines >= 0);
    std::vector<int> linesInBin((size_t)bins * cells * cells, 0);
    rankInBin.resize(lines.size());
    for (int i : order)
    {
        const Vec4f& l = lines[i];
        // The undirected angle turned by half a bin, in [0, pi): bin 0 is centred on the horizontal.
        double angle = std::atan2((double)l[3] - l[1], (double)l[2] - l[0]) + 0.5 * CV_PI / bins;
        angle = angle - CV_PI * std::floor(angle / CV_PI);
        const int direction = std::min(bins - 1, (int)(angle * bins / CV_PI));
        const int column = cellOf(0.5 * ((double)l[0] + l[2]), area.x, area.width, cells);
        const int row = cellOf(0.5 * ((double)l[1] + l[3]), area.y, area.height, cells);
        rankInBin[i] = linesInBin[((size_t)row * cells + column) * bins + direction]++;
    }
    // Stable: equal ranks keep the strongest-first order.
    std::stable_sort(order.begin(), order.end(), [&rankInBin](int a, int b) { return rankInBin[a] < rankInBin[b]; });
    if (maxLines > 0 && order.size() > (size_t)maxLines)
        order.resize(maxLines);
}

void LineSelection::apply(const std::vector<Vec4f>& lines, const Mat* gray, const SelectionParams& params,
                          Size imageSize, KnownResponses& known, std::vector<Vec4f>& selected,
                          std::vector<float>& responses, std::vector<int>& keptFrom)
{
    const double minLength = selectionMinLength(params, imageSize);
    // Every line is at least 0 long: without a minimum, the lines themselves, no length computed.
    const bool everyLine = minLength <= 0;
    if (!everyLine)
    {
        keepLongOrStrong(lines, std::vector<float>(), minLength, 0.0, longEnough, &longFrom);
        known.followKept(lines, longEnough, longFrom);
    }
    const std::vector<Vec4f>& candidates = everyLine ? lines : longEnough;
    // The responses of the lines that passed the minimum length only: with an image they are the
    // order, and the caller's (getLastResponses, KeyLine::response).
    if (!gray)
    {
        lengths.resize(candidates.size());
        for (size_t i = 0; i < candidates.size(); i++)
            lengths[i] = (float)segmentLength(candidates[i]);
    }
    const std::vector<float>& keys = gray ? known.complete(*gray, candidates) : lengths;
    order.resize(candidates.size());
    for (size_t i = 0; i < order.size(); i++)
        order[i] = (int)i;
    if (params.lineOrder == LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS)
    {
        strongestFirst(keys, 0, order);
        // Without an image size (processSegments), the grid covers the lines' endpoints.
        Rect2f area{ Point2f(), Size2f(imageSize) };
        if (imageSize.empty() && !candidates.empty())
            area = boundingRect(Mat(candidates).reshape(2, (int)candidates.size() * 2));
        acrossDirections(candidates, params.directionBins, params.gridCells, area, params.maxLines, order, rankInBin);
    }
    else
        strongestFirst(keys, params.maxLines, order);

    selected.resize(order.size());
    keptFrom.resize(order.size());
    responses.resize(gray ? order.size() : 0);
    for (size_t j = 0; j < order.size(); j++)
    {
        selected[j] = candidates[order[j]];
        keptFrom[j] = everyLine ? order[j] : longFrom[order[j]];
        if (gray)
            responses[j] = keys[order[j]];
    }
}

}}} // namespace cv::ximgproc::lsda
