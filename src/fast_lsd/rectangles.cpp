// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD: a region's rectangle, its refinement (LSD_REFINE_STD) and its NFA
// (LSD_REFINE_ADV only, with log(n!) from a table grown on demand), and the segment of a valid one.

#include "../precomp.hpp"
#include "kernels.hpp"
#include <functional>

namespace cv {
namespace ximgproc {
namespace lsda {
namespace fast_lsd {

namespace {

// Strides below this give the row of a buffer index exactly from (q + 0.5) / stride in double: the
// quotient then lies at least 0.5 / stride (>= 2^-19) from an integer, and q < 2^31 keeps the
// rounding error of the product below 2^-21.
constexpr int kExactRowStride = 1 << 18;

// Pixel (x, y) of buffer index q (row stride `stride`, one border row and column), by a
// multiplication, with no integer division; the rounding of q / stride is corrected for the
// strides that need it.
inline Point pixelAt(int q, int stride, double invStride)
{
    int y = (int)((q + 0.5) * invStride);
    if (stride >= kExactRowStride)
    {
        y += (y + 1) * stride <= q;
        y -= y * stride > q;
    }
    return Point(q - y * stride - 1, y - 1);
}

// log(n!) from a table grown on demand.
double logFactorial(int n, std::vector<double>& table)
{
    if (table.empty())
        table.push_back(0.0);
    while ((int)table.size() <= n)
        table.push_back(table.back() + std::log((double)table.size()));
    return table[n];
}

// -log10(NFA) with NFA = NT * sum_{i >= k} C(n, i) p^i (1 - p)^(n - i), the binomial tail summed
// from its first term until the remaining terms cannot change it by 10 %.
double logNfa(int n, int k, double p, double logNT, std::vector<double>& logFactorials)
{
    if (n == 0 || k == 0)
        return -logNT;
    if (n == k)
        return -logNT - n * std::log10(p);
    const double firstLog = logFactorial(n, logFactorials) - logFactorial(k, logFactorials) -
                            logFactorial(n - k, logFactorials) + k * std::log(p) + (n - k) * std::log(1.0 - p);
    double term = std::exp(firstLog);
    if (term == 0.0)
        return k > n * p ? -firstLog / std::log(10.0) - logNT : -logNT;
    const double ratio = p / (1.0 - p);
    double tail = term;
    for (int i = k + 1; i <= n; i++)
    {
        const double binomialRatio = (double)(n - i + 1) / i;
        const double step = binomialRatio * ratio;
        term *= step;
        tail += term;
        if (binomialRatio < 1)
        {
            // Bound of the remaining terms: a geometric series of ratio step.
            const double error = term * ((1 - std::pow(step, (double)(n - i + 1))) / (1 - step) - 1);
            if (error < 0.1 * std::abs(-std::log10(tail) - logNT) * tail)
                break;
        }
    }
    return -std::log10(tail) - logNT;
}

// The interval [xLow, xHigh] of row y inside the rectangle of the four corners; xLow > xHigh for none.
void rowInterval(const Point2d* corners, int y, double& xLow, double& xHigh)
{
    xLow = DBL_MAX;
    xHigh = -DBL_MAX;
    for (int e = 0; e < 4; e++)
    {
        const Point2d& a = corners[e];
        const Point2d& b = corners[(e + 1) % 4];
        if ((y < a.y && y < b.y) || (y > a.y && y > b.y))
            continue;
        if (a.y == b.y)
        {
            xLow = std::min(xLow, std::min(a.x, b.x));
            xHigh = std::max(xHigh, std::max(a.x, b.x));
            continue;
        }
        const double x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
        xLow = std::min(xLow, x);
        xHigh = std::max(xHigh, x);
    }
}

// -log10(NFA) of a rectangle: the pixels whose centres lie in it, row by row (each row meets the
// rectangle's four sides in an interval), and those of them aligned with it, from the image.
double rectLogNfa(const GradientField& field, double logNT, const RegionRect& rect, std::vector<double>& logFactorials)
{
    const double hw = rect.width / 2.0;
    const Point2d normal(-rect.dy * hw, rect.dx * hw);
    const Point2d corners[4] = { Point2d(rect.x1, rect.y1) + normal, Point2d(rect.x2, rect.y2) + normal,
                                 Point2d(rect.x2, rect.y2) - normal, Point2d(rect.x1, rect.y1) - normal };
    double yLow = corners[0].y, yHigh = corners[0].y;
    for (const Point2d& c : corners)
    {
        yLow = std::min(yLow, c.y);
        yHigh = std::max(yHigh, c.y);
    }
    const double cosTol = std::cos(rect.prec);
    const int width = field.width, height = field.height;
    int total = 0, aligned = 0;
    const int yFirst = std::max(0, (int)std::ceil(yLow)), yLast = std::min(height - 1, (int)std::floor(yHigh));
    for (int y = yFirst; y <= yLast; y++)
    {
        double xLow, xHigh;
        rowInterval(corners, y, xLow, xHigh);
        if (xLow > xHigh)
            continue;
        const int xFirst = std::max(0, (int)std::ceil(xLow)), xLast = std::min(width - 1, (int)std::floor(xHigh));
        if (xFirst > xLast)
            continue;
        total += xLast - xFirst + 1;
        if (y == height - 1)
            continue;  // the last row and column have no gradient
        const uchar* above = field.analysed.ptr<uchar>(y);
        const uchar* below = field.analysed.ptr<uchar>(y + 1);
        const uchar* inside = field.gradientMask.empty() ? nullptr : field.gradientMask.ptr<uchar>(y);
        for (int x = xFirst; x <= std::min(xLast, width - 2); x++)
        {
            // Pixels of regions count here too: the test of alignment, from the image.
            int gx, gy;
            gradient2x2(above, below, x, gx, gy);
            const int n2 = gx * gx + gy * gy;
            aligned += n2 > field.threshold && (!inside || inside[x]) &&
                       -gy * rect.dx + gx * rect.dy >= cosTol * std::sqrt((double)n2);
        }
    }
    return logNfa(total, aligned, rect.p, logNT, logFactorials);
}

// Shrinks the region from its seed by a quarter of the radius at a time until its rectangle is
// dense enough; false when fewer than 2 pixels are left. The pixels let go become free again.
bool shrinkRegionRadius(GradientField& field, const RegionRules& rules, Region& region, RegionRect& rect,
                        double currentDensity)
{
    const Point centre = region.pixel[0];
    double radius2 = std::max(squaredDistance(centre.x, centre.y, rect.x1, rect.y1),
                              squaredDistance(centre.x, centre.y, rect.x2, rect.y2));
    while (currentDensity < rules.densityThreshold)
    {
        radius2 *= 0.75 * 0.75;
        for (int i = 0; i < region.size;)
        {
            if (squaredDistance(centre.x, centre.y, region.pixel[i].x, region.pixel[i].y) > radius2)
            {
                field.level[region.index[i]] = region.vector[i];
                region.size--;
                region.index[i] = region.index[region.size];
                region.vector[i] = region.vector[region.size];
                region.pixel[i] = region.pixel[region.size];
            }
            else
                i++;
        }
        if (region.size < 2)
            return false;
        regionToRect(field, region, rect.prec, rect.p, rect);
        currentDensity = density(region, rect);
    }
    return true;
}

} // namespace

void regionToRect(const GradientField& field, Region& region, double prec, double p, RegionRect& rect)
{
    // Centre of mass and inertia of the region, each pixel weighted by its gradient norm, from
    // moments about the seed in one pass.
    if ((int)region.pixel.size() < region.size)
        region.pixel.resize(region.size);  // grows to the largest region, once
    const int stride = field.stride;
    const double invStride = 1.0 / stride;
    const int seedY = (int)(region.index[0] * invStride);
    const Point origin(region.index[0] - seedY * stride - 1, seedY - 1);
    double sum = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < region.size; i++)
    {
        const int q = region.index[i];
        const Point at = pixelAt(q, stride, invStride);
        region.pixel[i] = at;
        const double w = field.gradNorm[q];
        const double dx = at.x - origin.x, dy = at.y - origin.y;
        sum += w;
        sx += w * dx;
        sy += w * dy;
        sxx += w * dx * dx;
        syy += w * dy * dy;
        sxy += w * dx * dy;
    }
    const double mx = sx / sum, my = sy / sum;
    const double cx = origin.x + mx, cy = origin.y + my;
    const double ixx = syy - sum * my * my, iyy = sxx - sum * mx * mx, ixy = -(sxy - sum * mx * my);
    // The rectangle's direction is the eigenvector of the smallest eigenvalue, turned to point
    // along the region's level lines.
    const double lambda = 0.5 * (ixx + iyy - std::sqrt((ixx - iyy) * (ixx - iyy) + 4.0 * ixy * ixy));
    Point2d dir = std::abs(ixx) > std::abs(iyy) ? Point2d(ixy, lambda - ixx) : Point2d(lambda - iyy, ixy);
    const Point2d regionDir(region.sum.x, region.sum.y);
    const double dirNorm = std::sqrt(dir.dot(dir)), regionNorm = std::sqrt(regionDir.dot(regionDir));
    dir = dirNorm > 0 ? dir * (1.0 / dirNorm) : regionDir * (1.0 / regionNorm);
    if (dir.dot(regionDir) < std::cos(prec) * regionNorm)
        dir = -dir;

    double lMin, lMax, wMin, wMax;
    regionExtents(region.pixel.data(), region.size, cx, cy, dir, lMin, lMax, wMin, wMax);
    rect.x1 = cx + lMin * dir.x;
    rect.y1 = cy + lMin * dir.y;
    rect.x2 = cx + lMax * dir.x;
    rect.y2 = cy + lMax * dir.y;
    rect.width = std::max(wMax - wMin, 1.0);
    rect.x = cx;
    rect.y = cy;
    rect.dx = dir.x;
    rect.dy = dir.y;
    rect.prec = prec;
    rect.p = p;
}

double density(const Region& region, const RegionRect& rect)
{
    return region.size / (std::sqrt(squaredDistance(rect.x1, rect.y1, rect.x2, rect.y2)) * rect.width);
}

bool refineRegion(GradientField& field, const GrowthBounds& bounds, const RegionRules& rules, Region& region,
                  RegionRect& rect)
{
    if (density(region, rect) >= rules.densityThreshold)
        return true;

    // Too sparse: grow the region again from its seed with the tolerance narrowed to twice the
    // spread of the angles near the seed.
    const int seed = region.index[0];
    const Point centre = region.pixel[0];
    const Point2d seedDir(region.vector[0][0], region.vector[0][1]);
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int i = 0; i < region.size; i++)
    {
        field.level[region.index[i]] = region.vector[i];
        if (squaredDistance(centre.x, centre.y, region.pixel[i].x, region.pixel[i].y) < rect.width * rect.width)
        {
            const Point2d dir(region.vector[i][0], region.vector[i][1]);
            const double delta = std::atan2(seedDir.cross(dir), seedDir.dot(dir));
            sum += delta;
            sumSq += delta * delta;
            n++;
        }
    }
    const double mean = sum / n;
    const double tau = 2.0 * std::sqrt(std::max(0.0, (sumSq - 2.0 * mean * sum) / n + mean * mean));

    growRegion(field, bounds, rules.regionGrowth, seed, alignmentLimit(tau), region);
    if (region.size < 2)
        return false;
    regionToRect(field, region, rect.prec, rect.p, rect);
    const double regrownDensity = density(region, rect);
    return regrownDensity >= rules.densityThreshold || shrinkRegionRadius(field, rules, region, rect, regrownDensity);
}

double improveRect(const GradientField& field, const RegionRules& rules, RegionRect& rect,
                   std::vector<double>& logFactorials)
{
    // The published variations of the rectangle, each kept when it lowers the NFA: finer
    // precision, thinner, one side moved in, the other side moved in, finer precision again.
    constexpr double delta = 0.5, halfDelta = delta / 2.0;
    double best = rectLogNfa(field, rules.logNT, rect, logFactorials);
    if (best > rules.logEps)
        return best;

    // Five steps of one variation from the best rectangle so far; the steps that narrow the
    // rectangle, and the last phase, stop at the published minimal width. True when valid.
    auto varyFromBest = [&](bool whileWide, const std::function<void(RegionRect&)>& step) {
        RegionRect r = rect;
        for (int n = 0; n < 5; n++)
            if (!whileWide || r.width - delta >= 0.5)
            {
                step(r);
                const double value = rectLogNfa(field, rules.logNT, r, logFactorials);
                if (value > best)
                {
                    best = value;
                    rect = r;
                }
            }
        return best > rules.logEps;
    };
    const auto finerPrecision = [](RegionRect& r) {
        r.p /= 2;
        r.prec = r.p * CV_PI;
    };
    if (varyFromBest(false, finerPrecision) || varyFromBest(true, [](RegionRect& r) { r.width -= delta; }))
        return best;
    for (const double side : { 1.0, -1.0 })
    {
        const auto moveSideIn = [side](RegionRect& r) {
            const double ox = -r.dy * halfDelta * side, oy = r.dx * halfDelta * side;
            r.x1 += ox;
            r.y1 += oy;
            r.x2 += ox;
            r.y2 += oy;
            r.width -= delta;
        };
        if (varyFromBest(true, moveSideIn))
            return best;
    }
    varyFromBest(true, finerPrecision);
    return best;
}

void RegionGrower::emitRegion(GradientField& field, const RegionRules& rules)
{
    RegionRect rect;
    regionToRect(field, region, rules.tolerance, rules.probability, rect);
    if (rules.refine >= kLsdRefineStd && !refineRegion(field, bounds, rules, region, rect))
        return;
    emitRect(field, rules, rect);
}

bool RegionGrower::emitUnlessRegrown(const GradientField& field, const RegionRules& rules)
{
    RegionRect rect;
    regionToRect(field, region, rules.tolerance, rules.probability, rect);
    if (rules.refine >= kLsdRefineStd && density(region, rect) < rules.densityThreshold)
        return false;
    emitRect(field, rules, rect);
    return true;
}

void RegionGrower::emitRect(const GradientField& field, const RegionRules& rules, RegionRect& rect)
{
    if (rules.refine >= kLsdRefineAdv && improveRect(field, rules, rect, logFactorials) <= rules.logEps)
        return;
    // The 2x2 gradient of pixel (x, y) is that of the point (x + 0.5, y + 0.5).
    Vec4f s((float)(rect.x1 + 0.5), (float)(rect.y1 + 0.5), (float)(rect.x2 + 0.5), (float)(rect.y2 + 0.5));
    if (rules.scale != 1.0)
        s *= (float)(1.0 / rules.scale);
    segments.push_back(s);
}

}}}} // namespace cv::ximgproc::lsda::fast_lsd
