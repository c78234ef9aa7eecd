// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, both LSD bases: the Gaussian pre-smoothing at scale 1 (full_scale_smoothing.hpp).
// Written here rather than called as cv::GaussianBlur, which builds its kernels and filter on
// every call (BASE_FAST_LSD allocates nothing per frame once warm), and reads the pixels around a
// view when the image is one.

#include "precomp.hpp"
#include "full_scale_smoothing.hpp"
#include "opencv2/core/hal/intrin.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

// Weights in 8-bit fixed point: each pass's sum to this.
constexpr int kWeightSum = 256;

// The largest kernel radius: that of the largest LSDParams::fullScaleSigma.
constexpr int kMaxRadius = 16;

// hasAliasedEdges: the least step between two neighbours that is an edge, gray levels (well above a
// camera's noise, whose steps rarely reach it)...
constexpr int kEdgeStep = 16;
// ... and the pixels beyond an edge's two are at its levels when within step >> kLevelShift (a
// quarter of the step) of one of them. The share is that of a sample: the edges of every
// kSampledRowStep-th row (a quarter of the cost of all, and thousands of edges in a photograph).
constexpr int kLevelShift = 2;
constexpr int kSampledRowStep = 4;

inline bool atALevel(int beyond, int b, int c, int step)
{
    return std::min(std::abs(beyond - b), std::abs(beyond - c)) <= step >> kLevelShift;
}

// Adds to counts[0] the edges among the n steps b[x] -> c[x] (those of at least kEdgeStep), and to
// counts[1] those of one pixel (a[x] and d[x], the pixels beyond b[x] and c[x], each at one of
// their levels).
void countEdges(const uchar* a, const uchar* b, const uchar* c, const uchar* d, int n, int64* counts)
{
    int x = 0;
#if CV_SIMD128
    // Per lane, the counts of up to 255 blocks of 16 steps in 8 bits, then summed over the lanes.
    // Operator - saturates: x - y is 0 where x <= y.
    constexpr int kBlocks = 255;
    const v_uint8x16 edgeStep = v_setall_u8(kEdgeStep), lowBits = v_setall_u8(0xFF >> kLevelShift);
    const v_uint8x16 zero = v_setzero_u8();
    while (x + 16 <= n)
    {
        v_uint8x16 edges = zero, onePixel = zero;
        for (int k = 0; k < kBlocks && x + 16 <= n; k++, x += 16)
        {
            const v_uint8x16 vb = v_load(b + x), vc = v_load(c + x), va = v_load(a + x), vd = v_load(d + x);
            const v_uint8x16 step = v_absdiff(vb, vc);
            // step >> kLevelShift per byte: SSE2 shifts 16-bit lanes, whose high bytes' bits the mask drops.
            const v_uint8x16 near = v_reinterpret_as_u8(v_reinterpret_as_u16(step) >> kLevelShift) & lowBits;
            const v_uint8x16 notEdge = edgeStep - step;
            const v_uint8x16 aOff = v_min(v_absdiff(va, vb) - near, v_absdiff(va, vc) - near);
            const v_uint8x16 dOff = v_min(v_absdiff(vd, vb) - near, v_absdiff(vd, vc) - near);
            // A true lane is 0xFF: subtracting it adds 1.
            edges = v_sub_wrap(edges, notEdge == zero);
            onePixel = v_sub_wrap(onePixel, (notEdge | aOff | dOff) == zero);
        }
        v_uint16x8 lo, hi;
        v_expand(edges, lo, hi);
        counts[0] += v_reduce_sum(lo + hi);
        v_expand(onePixel, lo, hi);
        counts[1] += v_reduce_sum(lo + hi);
    }
#endif
    for (; x < n; x++)
    {
        const int step = std::abs(b[x] - c[x]);
        if (step >= kEdgeStep)
        {
            counts[0]++;
            counts[1] += atALevel(a[x], b[x], c[x], step) && atALevel(d[x], b[x], c[x], step);
        }
    }
}

// The edges of the sampled rows of stripe s (rows [s, s + 1) times kImageRowsPerTask): along each
// row y, and down the columns from it (the steps between rows y + 1 and y + 2, read from rows y to
// y + 3), counted into c[0] and c[1].
void countStripe(const Mat& image, int s, int64* c)
{
    c[0] = c[1] = 0;
    const int end = std::min(image.rows, (s + 1) * kImageRowsPerTask);
    for (int y = s * kImageRowsPerTask; y < end; y += kSampledRowStep)
    {
        const uchar* row = image.ptr<uchar>(y);
        countEdges(row, row + 1, row + 2, row + 3, image.cols - 3, c);
        if (y + 3 < image.rows)
            countEdges(row, image.ptr<uchar>(y + 1), image.ptr<uchar>(y + 2), image.ptr<uchar>(y + 3), image.cols, c);
    }
}

// out[x] = (w[0] centre[x] + sum over k of w[k] (before[k - 1][x] + after[k - 1][x]) + 128) / 256
// for x in [0, n): one pass of the Gaussian, 16 pixels at a time in 16 bits (at most 255 * 256).
// The weights' vectors and the rows are copied into locals first: out may alias anything, and
// would otherwise make them reloaded for every 16 pixels. kRadius > 0 is the radius known at
// compile time (that of the default sigma), the loop over the weights then unrolled; 0 reads r.
template <int kRadius>
void weightedSum(const uchar* centre, const uchar* const* before, const uchar* const* after, int r, const ushort* w,
                 int n, uchar* out)
{
    constexpr int kHalf = kWeightSum / 2;
    const int radius = kRadius > 0 ? kRadius : r;
    int x = 0;
#if CV_SIMD128
    const uchar* above[kMaxRadius];
    const uchar* below[kMaxRadius];
    v_uint16x8 weight[kMaxRadius + 1];
    weight[0] = v_setall_u16(w[0]);
    for (int k = 1; k <= radius; k++)
    {
        above[k - 1] = before[k - 1];
        below[k - 1] = after[k - 1];
        weight[k] = v_setall_u16(w[k]);
    }
    const v_uint16x8 half = v_setall_u16(kHalf);
    for (; x + 16 <= n; x += 16)
    {
        v_uint16x8 lo, hi;
        v_expand(v_load(centre + x), lo, hi);
        lo = v_mul_wrap(lo, weight[0]);
        hi = v_mul_wrap(hi, weight[0]);
        for (int k = 1; k <= radius; k++)
        {
            v_uint16x8 beforeLo, beforeHi, afterLo, afterHi;
            v_expand(v_load(above[k - 1] + x), beforeLo, beforeHi);
            v_expand(v_load(below[k - 1] + x), afterLo, afterHi);
            lo += v_mul_wrap(beforeLo + afterLo, weight[k]);
            hi += v_mul_wrap(beforeHi + afterHi, weight[k]);
        }
        // The sums are below 2^16 and the results below 256: the signed pack needs no saturation.
        v_store(out + x, v_pack_u(v_reinterpret_as_s16((lo + half) >> 8), v_reinterpret_as_s16((hi + half) >> 8)));
    }
#endif
    for (; x < n; x++)
    {
        int sum = w[0] * centre[x];
        for (int k = 1; k <= radius; k++)
            sum += w[k] * (before[k - 1][x] + after[k - 1][x]);
        out[x] = (uchar)((sum + kHalf) >> 8);
    }
}

// Both passes share this: the radius of the default sigma (0.5 px) unrolled.
void weightedSum(const uchar* centre, const uchar* const* before, const uchar* const* after, int r, const ushort* w,
                 int n, uchar* out)
{
    if (r == 1)
        weightedSum<1>(centre, before, after, r, w, n, out);
    else
        weightedSum<0>(centre, before, after, r, w, n, out);
}

} // namespace

bool hasAliasedEdges(const Mat& gray, std::vector<int64>& counts)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "hasAliasedEdges: the image must be CV_8UC1");
    const int stripeCount = (gray.rows + kImageRowsPerTask - 1) / kImageRowsPerTask;
    counts.resize(2 * (size_t)stripeCount);
    TaskLayout stripes;
    stripes.evenly(stripeCount, 1);
    runTasks(stripes, [&](int, const Range& items) {
        for (int s = items.start; s < items.end; s++)
            countStripe(gray, s, &counts[2 * (size_t)s]);
    });
    int64 edges = 0, onePixel = 0;
    for (int s = 0; s < stripeCount; s++)
    {
        edges += counts[2 * s];
        onePixel += counts[2 * s + 1];
    }
    return 2 * onePixel > edges;
}

// Both passes of a range of rows: the vertical one into the row's buffer, padded by the radius
// either side with its ends reflected, then the horizontal one into the output (a loop body rather
// than a lambda: std::function would allocate for it on every frame).
class FullScaleSmoothing::SmoothedRows CV_FINAL : public ParallelLoopBody
{
public:
    SmoothedRows(FullScaleSmoothing& smoothing, const Mat& gray) : s(smoothing), image(gray) {}
    void operator()(const Range& rows) const CV_OVERRIDE
    {
        const int width = image.cols, height = image.rows, r = s.radius;
        const uchar* before[kMaxRadius];
        const uchar* after[kMaxRadius];
        for (int y = rows.start; y < rows.end; y++)
        {
            uchar* v = &s.vertical[(size_t)y * (width + 2 * r)] + r;
            for (int k = 1; k <= r; k++)
            {
                before[k - 1] = image.ptr<uchar>(borderInterpolate(y - k, height, BORDER_REFLECT_101));
                after[k - 1] = image.ptr<uchar>(borderInterpolate(y + k, height, BORDER_REFLECT_101));
            }
            weightedSum(image.ptr<uchar>(y), before, after, r, s.weights.data(), width, v);
            for (int k = 1; k <= r; k++)
            {
                v[-k] = v[borderInterpolate(-k, width, BORDER_REFLECT_101)];
                v[width - 1 + k] = v[borderInterpolate(width - 1 + k, width, BORDER_REFLECT_101)];
                before[k - 1] = v - k;
                after[k - 1] = v + k;
            }
            weightedSum(v, before, after, r, s.weights.data(), width, s.smoothed.ptr<uchar>(y));
        }
    }

private:
    FullScaleSmoothing& s;
    const Mat& image;
};

FullScaleSmoothing::FullScaleSmoothing(double sigma, int images) : aliasedOnly(images == LSDAdvance::SMOOTH_ALIASED_IMAGES)
{
    // LSD's support of its own Gaussian: the weights beyond are below 10^-3 of the centre's.
    const int support = sigma > 0 ? (int)std::ceil(sigma * std::sqrt(2.0 * 3.0 * std::log(10.0))) : 0;
    std::vector<double> gaussian(support + 1);
    double total = 0;
    for (int k = 0; k <= support; k++)
    {
        gaussian[k] = std::exp(-k * k / (2.0 * sigma * sigma));
        total += k == 0 ? gaussian[k] : 2 * gaussian[k];
    }
    weights.assign(support + 1, 0);
    int outer = 0;
    for (int k = 1; k <= support; k++)
    {
        weights[k] = (ushort)cvRound(kWeightSum * gaussian[k] / total);
        outer += 2 * weights[k];
    }
    CV_Assert(outer < kWeightSum && support <= kMaxRadius);
    weights[0] = (ushort)(kWeightSum - outer);
    // Weights that round to 0 would only cost time.
    radius = support;
    while (radius > 0 && weights[radius] == 0)
        radius--;
    weights.resize(radius + 1);
}

const Mat& FullScaleSmoothing::apply(const Mat& gray)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "FullScaleSmoothing: the image must be CV_8UC1");
    if (aliasedOnly && !hasAliasedEdges(gray, edgeCounts))
        return gray;
    vertical.resize((size_t)(gray.cols + 2 * radius) * gray.rows);
    pixels.resize(gray.total());
    smoothed = Mat(gray.rows, gray.cols, CV_8UC1, pixels.data());
    TaskLayout stripes;
    stripes.evenly(gray.rows, kImageRowsPerTask);
    const SmoothedRows smoothedRows(*this, gray);
    runTasks(stripes, [&](int, const Range& rows) { smoothedRows(rows); });
    return smoothed;
}

}}} // namespace cv::ximgproc::lsda
