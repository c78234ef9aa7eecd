// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the LSD algorithm (Grompone von Gioi et al., IPOL 2012) written for
// speed. Where the time goes in a straightforward implementation, and what this one does instead:
// - level-line angles: no angle is ever computed. Each pixel keeps its unit level-line vector u in
//   16-bit fixed point (4 bytes a pixel, so that the neighbourhoods of random seeds stay in the
//   caches), and a pixel is aligned with a direction r within the tolerance t when u.r >= cos(t).
//   A pixel without a defined gradient, or already in a region, keeps u = (0, 0): the vector is
//   also the pixel's state, and one load answers both questions;
// - pseudo-ordering: a counting sort of the pixels with a defined gradient into the bins of their
//   gradient norm (raster order inside a bin), instead of a comparison sort of every pixel;
// - region growing: a border of undefined pixels around the buffers removes the bounds checks, the
//   test of a neighbour has no branch (whether a neighbour is free is as good as random), and the
//   region's direction is the sum of its unit vectors, kept in float;
// - the NFA (refine = LSD_REFINE_ADV only): log(n!) from a table grown on demand.
// The gradient runs in parallel over rows; everything else is sequential, so the output does not
// depend on the number of threads.

#include "precomp.hpp"
#include "fast_lsd.hpp"
#include "opencv2/core/hal/hal.hpp"
#include <functional>

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

// The length of a unit level-line vector in the fixed point of FastLsd::level.
constexpr float kUnit = 16384.f;

// Rows of the image whose gradients are computed by one task of the parallel loop.
constexpr int kRowsPerStripe = 16;

// How many seeds ahead the neighbourhood of a seed is fetched into the cache.
constexpr int kPrefetchDistance = 4;

inline void prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    CV_UNUSED(address);
#endif
}

// The 2x2 gradient of pixel x of a row (LSD's mask: A, B the pixel and its right neighbour, C, D
// the two below).
inline void gradient2x2(const uchar* above, const uchar* below, int x, int& gx, int& gy)
{
    const int da = below[x + 1] - above[x];
    const int bc = above[x + 1] - below[x];
    gx = da + bc;
    gy = da - bc;
}

// The gradient pass of one row, in two loops without branches that the compiler vectorises (with
// cv::hal::sqrt32f between them): gx^2 + gy^2 into norm (1 where it is 0), its maximum and the
// count of defined pixels (gx^2 + gy^2 > threshold); ...
void gradientNorms(const uchar* __restrict above, const uchar* __restrict below, int n, int threshold,
                   float* __restrict norm, int& rowMax, int& defined)
{
    int maxNorm2 = 0, count = 0;
    for (int x = 0; x < n; x++)
    {
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const int n2 = gx * gx + gy * gy;
        norm[x] = (float)(n2 + (n2 == 0));
        count += n2 > threshold;
        maxNorm2 = maxNorm2 > n2 ? maxNorm2 : n2;
    }
    rowMax = maxNorm2;
    defined = count;
}

// ... then, from |g| in norm, the unit level-line vector (-gy, gx) / |g| in fixed point ((0, 0) for
// an undefined pixel) and the gradient norm |g| / 2.
void levelLines(const uchar* __restrict above, const uchar* __restrict below, int n, int threshold,
                float* __restrict norm, short* __restrict level)
{
    for (int x = 0; x < n; x++)
    {
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const float scale = (float)(gx * gx + gy * gy > threshold) * (kUnit / norm[x]);
        level[2 * x] = (short)(-gy * scale);
        level[2 * x + 1] = (short)(gx * scale);
        norm[x] *= 0.5f;
    }
}

// Whether a pixel's vector is not (0, 0): it has a defined gradient and is in no region yet.
inline bool isFree(const Vec2s& u)
{
    return (u[0] | u[1]) != 0;
}

inline double squaredDistance(double x1, double y1, double x2, double y2)
{
    return (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
}

} // namespace

FastLsd::FastLsd(const LSDAdvance::LSDParams& p)
    : refine(p.refine), scale(p.scale), sigmaScale(p.sigmaScale), quant(p.quant),
      angleTolerance(p.angleTolerance), logEps(p.logEps), densityThreshold(p.densityThreshold),
      numBins(p.numBins)
{
    // The parameters are in their ranges: those of the table of parameters.hpp, which every setter checks.
}

void FastLsd::detect(const Mat& gray, std::vector<Vec4f>& segments)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "FastLsd: the image must be CV_8UC1");
    segments.clear();
    const Mat* image = &gray;
    if (scale != 1.0)
    {
        // Anti-aliasing as the LSD algorithm prescribes: a Gaussian of sigma = sigmaScale / scale
        // over 3 sigma of precision, then the sub-sampling by scale (not by the ratio of rounded
        // sizes, which would move the samples).
        if (saturate_cast<int>(gray.cols * scale) <= 0 || saturate_cast<int>(gray.rows * scale) <= 0)
            return;
        const double sigma = scale < 1.0 ? sigmaScale / scale : sigmaScale;
        const int half = (int)std::ceil(sigma * std::sqrt(2.0 * 3.0 * std::log(10.0)));
        GaussianBlur(gray, blurred, Size(2 * half + 1, 2 * half + 1), sigma);
        resize(blurred, scaled, Size(), scale, scale, INTER_LINEAR_EXACT);
        image = &scaled;
    }
    if (image->cols < 2 || image->rows < 2)
        return;
    // Pixels are addressed by int.
    if ((double)(image->cols + 1) * (image->rows + 1) >= (double)INT_MAX)
        CV_Error_(Error::StsOutOfRange,
                  ("BASE_FAST_LSD analyses at most 2^31 pixels (at its scale), got %dx%d; use a scale below 1 or BASE_LSD",
                   image->cols, image->rows));

    analysed = *image;
    computeGradient(*image);
    orderPixels();

    const double prec = CV_PI * angleTolerance / 180.0;
    const double p = angleTolerance / 180.0;
    logNT = 5.0 * (std::log10((double)width) + std::log10((double)height)) / 2.0 + std::log10(11.0);
    // Fewer points than this cannot give a meaningful segment, whatever their alignment.
    const size_t minRegionSize = (size_t)(-logNT / std::log10(p));
    // Once per frame: most seeds grow no region, and a cosine per seed cost 4 % of the time.
    const float cosUnit = alignmentLimit(prec);

    const int seeds = (int)ordered.size();
    for (int i = 0; i < seeds; i++)
    {
        // Seeds jump across the image: fetch the neighbourhood of a coming one while this one grows.
        if (i + kPrefetchDistance < seeds)
        {
            const int coming = ordered[i + kPrefetchDistance];
            prefetch(&level[coming - stride]);
            prefetch(&level[coming]);
            prefetch(&level[coming + stride]);
        }
        const int seed = ordered[i];
        if (!isFree(level[seed]))
            continue;
        growRegion(seed, cosUnit);
        if ((size_t)regionSize < minRegionSize)
            continue;
        Rect rect;
        regionToRect(prec, p, rect);
        if (refine >= LSD_REFINE_STD && !refineRegion(rect))
            continue;
        if (refine >= LSD_REFINE_ADV && improveRect(rect) <= logEps)
            continue;
        // The 2x2 gradient of pixel (x, y) is that of the point (x + 0.5, y + 0.5).
        Vec4f s((float)(rect.x1 + 0.5), (float)(rect.y1 + 0.5), (float)(rect.x2 + 0.5), (float)(rect.y2 + 0.5));
        if (scale != 1.0)
            s *= (float)(1.0 / scale);
        segments.push_back(s);
    }
}

// The gradient pass over a range of rows (a loop body rather than a lambda: std::function would
// allocate for it on every frame).
class FastLsd::GradientRows CV_FINAL : public ParallelLoopBody
{
public:
    GradientRows(FastLsd& detector, const Mat& gray) : lsd(detector), image(gray) {}
    void operator()(const Range& rows) const CV_OVERRIDE
    {
        const int n = lsd.width - 1;
        for (int y = rows.start; y < rows.end; y++)
        {
            const uchar* above = image.ptr<uchar>(y);
            const uchar* below = image.ptr<uchar>(y + 1);
            const size_t row = (size_t)(y + 1) * lsd.stride + 1;
            float* norm = &lsd.gradNorm[row];
            gradientNorms(above, below, n, lsd.threshold, norm, lsd.rowMaxNorm2[y], lsd.rowDefined[y]);
            hal::sqrt32f(norm, norm, n);
            levelLines(above, below, n, lsd.threshold, norm, &lsd.level[row][0]);
            lsd.level[row - 1] = lsd.level[row + n] = Vec2s(0, 0);
        }
    }

private:
    FastLsd& lsd;
    const Mat& image;
};

void FastLsd::computeGradient(const Mat& image)
{
    width = image.cols;
    height = image.rows;
    stride = width + 1;
    const size_t total = (size_t)stride * (height + 1);
    // Norm threshold rho = quant / sin(tolerance); a pixel is defined when its norm |g| / 2 > rho,
    // i.e. gx^2 + gy^2 > 4 rho^2, compared exactly on integers.
    const double rho = quant / std::sin(CV_PI * angleTolerance / 180.0);
    const double bound = std::floor(4.0 * rho * rho);
    threshold = bound >= (double)INT_MAX ? INT_MAX : (int)bound;

    // Every pixel of level is written below: the rows' gradients, the border and the pixels without
    // a gradient (last row and column) as (0, 0).
    level.resize(total);
    std::fill(level.begin(), level.begin() + stride, Vec2s(0, 0));
    std::fill(level.end() - stride, level.end(), Vec2s(0, 0));
    gradNorm.resize(total);
    rowMaxNorm2.assign(height, 0);
    rowDefined.assign(height, 0);

    parallel_for_(Range(0, height - 1), GradientRows(*this, image), std::max(1.0, (height - 1) / (double)kRowsPerStripe));

    definedCount = 0;
    for (const int d : rowDefined)
        definedCount += d;
}

void FastLsd::orderPixels()
{
    const int maxNorm2 = *std::max_element(rowMaxNorm2.begin(), rowMaxNorm2.end());
    // Bin of a pixel: floor(norm * (numBins - 1) / maxNorm).
    const float binScale = maxNorm2 > 0 ? (float)((numBins - 1) / (0.5 * std::sqrt((double)maxNorm2))) : 0.f;
    auto binOf = [&](int q) { return std::min(numBins - 1, (int)(gradNorm[q] * binScale)); };
    // The defined pixels in raster order, in regionIndex until the regions need it. The compaction
    // writes every pixel and moves on past the defined ones (no branch: defined and undefined
    // pixels alternate at random in textured areas), so it writes one past the last.
    std::vector<int>& defined = regionIndex;
    defined.resize(definedCount + 1);
    ordered.resize(definedCount);
    regionVector.resize(definedCount);
    binStart.assign((size_t)numBins + 1, 0);
    int* next = defined.data();
    for (int y = 0; y < height - 1; y++)
    {
        const int row = (y + 1) * stride + 1;
        const Vec2s* u = &level[row];
        for (int x = 0; x < width - 1; x++)
        {
            *next = row + x;
            next += isFree(u[x]);
        }
    }
    // Highest bin first; inside a bin, raster order (a stable counting sort).
    int* counts = binStart.data();
    for (int i = 0; i < definedCount; i++)
        counts[numBins - 1 - binOf(defined[i])]++;
    int position = 0;
    for (int b = 0; b <= numBins; b++)
    {
        const int count = counts[b];
        counts[b] = position;
        position += count;
    }
    for (int i = 0; i < definedCount; i++)
        ordered[counts[numBins - 1 - binOf(defined[i])]++] = defined[i];
}

template <bool acute>
void FastLsd::growRegionFrom(int seed, float cosUnit)
{
    // A pixel joins when its unit level-line vector u is within the tolerance of the region's
    // direction, the sum S of its pixels' vectors: u.S >= cos(tolerance) |u| |S| (= limit). A pixel
    // that joins gives its vector to regionVector and keeps (0, 0). With an acute tolerance the test
    // is strict, so that a (0, 0) vector fails it without a test of its own; equality has no
    // weight on real data.
    Vec2s* u = level.data();
    int* region = regionIndex.data();
    Vec2s* kept = regionVector.data();

    float sx = u[seed][0], sy = u[seed][1];
    float limit = cosUnit * std::sqrt(sx * sx + sy * sy);
    region[0] = seed;
    kept[0] = u[seed];
    u[seed] = Vec2s(0, 0);
    int size = 1;
    auto visit = [&](int q) {
        const Vec2s v = u[q];
        const float d = sx * v[0] + sy * v[1];
        // No branch until the outcome: whether a neighbour is free is as good as random.
        const bool joins = acute ? d > limit : (isFree(v) & (d >= limit));
        if (!joins)
            return;
        region[size] = q;
        kept[size++] = v;
        u[q] = Vec2s(0, 0);
        sx += v[0];
        sy += v[1];
        limit = cosUnit * std::sqrt(sx * sx + sy * sy);
    };
    // The 8 neighbours row by row, as the published algorithm visits them: the order decides which
    // pixels join, since the region's direction changes with every pixel.
    const int s = stride;
    for (int i = 0; i < size; i++)
    {
        const int c = region[i];
        visit(c - s - 1);
        visit(c - s);
        visit(c - s + 1);
        visit(c - 1);
        visit(c + 1);
        visit(c + s - 1);
        visit(c + s);
        visit(c + s + 1);
    }
    regionSize = size;
    regionSum = Point2f(sx, sy);
}

float FastLsd::alignmentLimit(double tolerance)
{
    return (float)std::cos(tolerance) * kUnit;
}

void FastLsd::growRegion(int seed, float cosUnit)
{
    if (cosUnit > 0)
        growRegionFrom<true>(seed, cosUnit);
    else
        growRegionFrom<false>(seed, cosUnit);
}

void FastLsd::regionToRect(double prec, double p, Rect& rect)
{
    // Centre of mass and inertia of the region, each pixel weighted by its gradient norm, from
    // moments about the seed in one pass. Coordinates from buffer indices by a multiplication: the
    // rounding of q / stride is corrected, so that no integer division is needed.
    if ((int)regionPixel.size() < regionSize)
        regionPixel.resize(regionSize);  // grows to the largest region, once
    const double invStride = 1.0 / stride;
    const int seedY = (int)(regionIndex[0] * invStride);
    const Point origin(regionIndex[0] - seedY * stride - 1, seedY - 1);
    double sum = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < regionSize; i++)
    {
        const int q = regionIndex[i];
        int y = (int)(q * invStride);
        y += (y + 1) * stride <= q;
        y -= y * stride > q;
        const Point at(q - y * stride - 1, y - 1);
        regionPixel[i] = at;
        const double w = gradNorm[q];
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
    const Point2d regionDir(regionSum.x, regionSum.y);
    const double dirNorm = std::sqrt(dir.dot(dir)), regionNorm = std::sqrt(regionDir.dot(regionDir));
    dir = dirNorm > 0 ? dir * (1.0 / dirNorm) : regionDir * (1.0 / regionNorm);
    if (dir.dot(regionDir) < std::cos(prec) * regionNorm)
        dir = -dir;

    double lMin = 0, lMax = 0, wMin = 0, wMax = 0;
    for (int i = 0; i < regionSize; i++)
    {
        const double ddx = regionPixel[i].x - cx, ddy = regionPixel[i].y - cy;
        const double l = ddx * dir.x + ddy * dir.y;
        const double w = -ddx * dir.y + ddy * dir.x;
        lMin = std::min(lMin, l);
        lMax = std::max(lMax, l);
        wMin = std::min(wMin, w);
        wMax = std::max(wMax, w);
    }
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

bool FastLsd::refineRegion(Rect& rect)
{
    double density = regionSize / (std::sqrt(squaredDistance(rect.x1, rect.y1, rect.x2, rect.y2)) * rect.width);
    if (density >= densityThreshold)
        return true;

    // Too sparse: grow the region again from its seed with the tolerance narrowed to twice the
    // spread of the angles near the seed.
    const int seed = regionIndex[0];
    const Point centre = regionPixel[0];
    const Point2d seedDir(regionVector[0][0], regionVector[0][1]);
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int i = 0; i < regionSize; i++)
    {
        level[regionIndex[i]] = regionVector[i];
        if (squaredDistance(centre.x, centre.y, regionPixel[i].x, regionPixel[i].y) < rect.width * rect.width)
        {
            const Point2d dir(regionVector[i][0], regionVector[i][1]);
            const double delta = std::atan2(seedDir.cross(dir), seedDir.dot(dir));
            sum += delta;
            sumSq += delta * delta;
            n++;
        }
    }
    const double mean = sum / n;
    const double tau = 2.0 * std::sqrt(std::max(0.0, (sumSq - 2.0 * mean * sum) / n + mean * mean));

    growRegion(seed, alignmentLimit(tau));
    if (regionSize < 2)
        return false;
    regionToRect(rect.prec, rect.p, rect);
    density = regionSize / (std::sqrt(squaredDistance(rect.x1, rect.y1, rect.x2, rect.y2)) * rect.width);
    return density >= densityThreshold || shrinkRegionRadius(rect, density);
}

bool FastLsd::shrinkRegionRadius(Rect& rect, double density)
{
    const Point centre = regionPixel[0];
    double radius2 = std::max(squaredDistance(centre.x, centre.y, rect.x1, rect.y1),
                              squaredDistance(centre.x, centre.y, rect.x2, rect.y2));
    while (density < densityThreshold)
    {
        radius2 *= 0.75 * 0.75;
        for (int i = 0; i < regionSize;)
        {
            if (squaredDistance(centre.x, centre.y, regionPixel[i].x, regionPixel[i].y) > radius2)
            {
                level[regionIndex[i]] = regionVector[i];
                regionSize--;
                regionIndex[i] = regionIndex[regionSize];
                regionVector[i] = regionVector[regionSize];
                regionPixel[i] = regionPixel[regionSize];
            }
            else
                i++;
        }
        if (regionSize < 2)
            return false;
        regionToRect(rect.prec, rect.p, rect);
        density = regionSize / (std::sqrt(squaredDistance(rect.x1, rect.y1, rect.x2, rect.y2)) * rect.width);
    }
    return true;
}

double FastLsd::rectLogNfa(const Rect& rect) const
{
    // The pixels whose centres lie in the rectangle, row by row: each row meets the rectangle's
    // four sides in an interval.
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
    int total = 0, aligned = 0;
    const int yFirst = std::max(0, (int)std::ceil(yLow)), yLast = std::min(height - 1, (int)std::floor(yHigh));
    for (int y = yFirst; y <= yLast; y++)
    {
        double xLow = DBL_MAX, xHigh = -DBL_MAX;
        for (int e = 0; e < 4; e++)
        {
            const Point2d& a = corners[e];
            const Point2d& b = corners[(e + 1) % 4];
            if ((y < a.y && y < b.y) || (y > a.y && y > b.y))
                continue;
            double x;
            if (a.y == b.y)
            {
                xLow = std::min(xLow, std::min(a.x, b.x));
                xHigh = std::max(xHigh, std::max(a.x, b.x));
                continue;
            }
            x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
            xLow = std::min(xLow, x);
            xHigh = std::max(xHigh, x);
        }
        if (xLow > xHigh)
            continue;
        const int xFirst = std::max(0, (int)std::ceil(xLow)), xLast = std::min(width - 1, (int)std::floor(xHigh));
        if (xFirst > xLast)
            continue;
        total += xLast - xFirst + 1;
        if (y == height - 1)
            continue;  // the last row and column have no gradient
        const uchar* above = analysed.ptr<uchar>(y);
        const uchar* below = analysed.ptr<uchar>(y + 1);
        for (int x = xFirst; x <= std::min(xLast, width - 2); x++)
        {
            // Pixels of regions count here too: the test of alignment, from the image.
            int gx, gy;
            gradient2x2(above, below, x, gx, gy);
            const int n2 = gx * gx + gy * gy;
            aligned += n2 > threshold && -gy * rect.dx + gx * rect.dy >= cosTol * std::sqrt((double)n2);
        }
    }
    return logNfa(total, aligned, rect.p);
}

double FastLsd::improveRect(Rect& rect) const
{
    // The published variations of the rectangle, each kept when it lowers the NFA: finer
    // precision, thinner, one side moved in, the other side moved in, finer precision again.
    constexpr double delta = 0.5, halfDelta = delta / 2.0;
    double best = rectLogNfa(rect);
    if (best > logEps)
        return best;

    auto tryVariation = [&](const Rect& candidate) {
        const double value = rectLogNfa(candidate);
        if (value > best)
        {
            best = value;
            rect = candidate;
        }
    };

    // Five steps of one variation from the best rectangle so far; the steps that narrow the
    // rectangle, and the last phase, stop at the published minimal width. True when valid.
    auto varyFromBest = [&](bool whileWide, const std::function<void(Rect&)>& step) {
        Rect r = rect;
        for (int n = 0; n < 5; n++)
            if (!whileWide || r.width - delta >= 0.5)
            {
                step(r);
                tryVariation(r);
            }
        return best > logEps;
    };
    const auto finerPrecision = [](Rect& r) {
        r.p /= 2;
        r.prec = r.p * CV_PI;
    };
    if (varyFromBest(false, finerPrecision) || varyFromBest(true, [](Rect& r) { r.width -= delta; }))
        return best;
    for (const double side : { 1.0, -1.0 })
    {
        const auto moveSideIn = [side](Rect& r) {
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

double FastLsd::logFactorial(int n) const
{
    if (logFactorials.empty())
        logFactorials.push_back(0.0);
    while ((int)logFactorials.size() <= n)
        logFactorials.push_back(logFactorials.back() + std::log((double)logFactorials.size()));
    return logFactorials[n];
}

double FastLsd::logNfa(int n, int k, double p) const
{
    // -log10(NFA) with NFA = NT * sum_{i >= k} C(n, i) p^i (1 - p)^(n - i), the binomial tail summed
    // from its first term until the remaining terms cannot change it by 10 %.
    if (n == 0 || k == 0)
        return -logNT;
    if (n == k)
        return -logNT - n * std::log10(p);
    const double firstLog = logFactorial(n) - logFactorial(k) - logFactorial(n - k) + k * std::log(p) +
                            (n - k) * std::log(1.0 - p);
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

}}} // namespace cv::ximgproc::lsda
