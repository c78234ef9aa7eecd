// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD: the gradient pass and the seeds. No level-line angle is ever computed: each pixel
// keeps its unit level-line vector u in 16-bit fixed point (4 bytes a pixel, so that the
// neighbourhoods of random seeds stay in the caches), and a pixel is aligned with a direction r
// within the tolerance t when u.r >= cos(t). A pixel without a defined gradient, or already in a
// region, keeps u = (0, 0): the vector is also the pixel's state, and one load answers both
// questions. The seeds are the pixels from a gradient level up (LSDParams::seedGradientRatio),
// and on edges (LSDParams::seedAlignedNeighbours): their neighbours along the level line aligned.

#include "../precomp.hpp"
#include "kernels.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

namespace {

// The mask on a row of the gradient pass (inside: the gradient's 2x2 support is on the mask):
// the pixels outside made undefined, and the row's maximum and count of defined pixels over the
// others. A row wholly inside is left as it is.
void maskRow(const uchar* inside, const uchar* above, const uchar* below, int n, int threshold, float* norm,
             Vec2s* level, int& rowMax, int& defined)
{
    if (std::find(inside, inside + n, 0) == inside + n)
        return;
    int maxNorm2 = 0, count = 0;
    for (int x = 0; x < n; x++)
    {
        if (!inside[x])
        {
            norm[x] = 0.f;
            level[x] = Vec2s(0, 0);
            continue;
        }
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const int n2 = gx * gx + gy * gy;
        count += n2 > threshold;
        maxNorm2 = std::max(maxNorm2, n2);
    }
    rowMax = maxNorm2;
    defined = count;
}

// The gradient pass over a range of rows.
void gradientRows(const Mat& image, const Range& rows, GradientField& field)
{
    const int n = field.width - 1;
    for (int y = rows.start; y < rows.end; y++)
    {
        const uchar* above = image.ptr<uchar>(y);
        const uchar* below = image.ptr<uchar>(y + 1);
        const size_t row = (size_t)(y + 1) * field.stride + 1;
        float* norm = &field.gradNorm[row];
        gradientRow(above, below, n, field.threshold, norm, &field.level[row][0], field.rowMaxNorm2[y],
                    field.rowDefined[y]);
        if (!field.gradientMask.empty())
            maskRow(field.gradientMask.ptr<uchar>(y), above, below, n, field.threshold, norm, &field.level[row],
                    field.rowMaxNorm2[y], field.rowDefined[y]);
        field.level[row - 1] = field.level[row + n] = Vec2s(0, 0);
    }
}

// The least float norm in a bin (bins grow with the norm).
float lowestNormOfBin(int bin, float binScale, int numBins)
{
    float norm = (float)bin / binScale;
    while (norm > 0 && binOfNorm(std::nextafter(norm, 0.f), binScale, numBins) >= bin)
        norm = std::nextafter(norm, 0.f);
    while (binOfNorm(norm, binScale, numBins) < bin)
        norm = std::nextafter(norm, FLT_MAX);
    return norm;
}

// The seeds are the pixels of the bins from that of seedGradientRatio * rho up: the first seeds of
// the LSD algorithm's order, so that the regions grown are exactly its first ones. seedNorm is the
// least norm in those bins (undefined pixels have a norm of 0).
float seedNormOf(double seedGradientRatio, double rho, int maxNorm2, const GradientField& field)
{
    const double maxNorm = 0.5 * std::sqrt((double)maxNorm2);
    const double seedLevel = seedGradientRatio * rho;
    if (seedGradientRatio == 1.0 || maxNorm2 == 0)
        return FLT_MIN;
    if (seedLevel > maxNorm)
        return FLT_MAX;
    const int bin = binOfNorm((float)seedLevel, field.binScale, field.numBins);
    return std::max(lowestNormOfBin(bin, field.binScale, field.numBins), FLT_MIN);
}

} // namespace

void computeGradient(const Mat& image, const LSDAdvance::LSDParams& params, GradientField& field)
{
    field.analysed = image;
    field.width = image.cols;
    field.height = image.rows;
    field.stride = field.width + 1;
    field.numBins = params.numBins;
    const int height = field.height, stride = field.stride;
    const size_t total = (size_t)stride * (height + 1);
    // Norm threshold rho = quant / sin(tolerance); a pixel is defined when its norm |g| / 2 > rho,
    // i.e. gx^2 + gy^2 > 4 rho^2, compared exactly on integers.
    const double rho = params.quant / std::sin(CV_PI * params.angleTolerance / 180.0);
    const double bound = std::floor(4.0 * rho * rho);
    field.threshold = bound >= (double)INT_MAX ? INT_MAX : (int)bound;

    // Every pixel of level is written below: the rows' gradients, the border and the pixels without
    // a gradient (last row and column) as (0, 0); and one more (0, 0) past the last row, which the
    // test of four neighbours at a time reads (GROWTH_PER_NEIGHBOURHOOD).
    field.level.resize(total + 1);
    std::fill(field.level.begin(), field.level.begin() + stride, Vec2s(0, 0));
    std::fill(field.level.end() - stride - 1, field.level.end(), Vec2s(0, 0));
    field.gradNorm.resize(total);
    field.rowMaxNorm2.assign(height - 1, 0);
    field.rowDefined.assign(height - 1, 0);

    field.rowTasks.evenly(height - 1, kImageRowsPerTask);
    runTasks(field.rowTasks, [&](int, const Range& rows) { gradientRows(image, rows, field); });

    const int maxNorm2 = *std::max_element(field.rowMaxNorm2.begin(), field.rowMaxNorm2.end());
    const double maxNorm = 0.5 * std::sqrt((double)maxNorm2);
    field.binScale = maxNorm2 > 0 ? (float)((field.numBins - 1) / maxNorm) : 0.f;
    field.seedNorm = seedNormOf(params.seedGradientRatio, rho, maxNorm2, field);
}

int GradientField::alignedNeighbours(int pixel, int alignedDot) const
{
    // The neighbour nearest to the level-line direction u: a step along x where |u_x| > sin(22.5
    // deg), along y where |u_y| is, and the one opposite.
    const Vec2s u = level[pixel];
    const int dx = (u[0] > kStep) - (u[0] < -kStep), dy = (u[1] > kStep) - (u[1] < -kStep);
    const int offset = dy * stride + dx;
    const Vec2s a = level[pixel + offset], b = level[pixel - offset];
    const int dotA = u[0] * a[0] + u[1] * a[1], dotB = u[0] * b[0] + u[1] * b[1];
    // A neighbour that is not free, (0, 0), has a product of 0: below a limit of 0 or more (a
    // tolerance under 90 deg) without a test of its own.
    if (alignedDot >= 0)
        return (dotA > alignedDot) + (dotB > alignedDot);
    return (isFree(a) & (dotA > alignedDot)) + (isFree(b) & (dotB > alignedDot));
}

int* seedsOfRow(const GradientField& field, int y, float least, int needed, int alignedDot, int* next)
{
    // Two compactions without a branch per pixel: the pixels whose norm reaches least, then in
    // place those of them on edges. Most pixels are below the seed level, so the test of the
    // neighbours runs on a few.
    const int row = (y + 1) * field.stride + 1;
    int* const strong = next;
    next = strongPixels(&field.gradNorm[row], row, field.width - 1, least, next);
    if (needed == 0)
        return next;
    return edgePixels(field, needed, alignedDot, strong, next, strong);
}

}}}} // namespace cv::ximgproc::lsda::fast_lsd
