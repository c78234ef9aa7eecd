// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// BASE_FAST_LSD's vector kernels that are not inline (kernels.hpp). Each vector path gives the
// integers and floats of its scalar path, which also does what the vectors leave.

#include "../precomp.hpp"
#include "kernels.hpp"
#include "opencv2/core/hal/hal.hpp"
#include <cstring>

#ifdef LSD_ADVANCE_SCALAR
static_assert(!CV_SIMD128 && !CV_SIMD128_64F, "the scalar build compiles no universal intrinsics");
#endif

namespace cv {
namespace ximgproc {
namespace lsda {

bool compiledWithUniversalIntrinsics()
{
    return CV_SIMD128 != 0;
}

namespace fast_lsd {

namespace {

// For a mask of four lanes: the set lanes first (a left-pack), and how many are set.
alignas(16) const int kPackedLanes[16][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 },
                                              { 2, 0, 0, 0 }, { 0, 2, 0, 0 }, { 1, 2, 0, 0 }, { 0, 1, 2, 0 },
                                              { 3, 0, 0, 0 }, { 0, 3, 0, 0 }, { 1, 3, 0, 0 }, { 0, 1, 3, 0 },
                                              { 2, 3, 0, 0 }, { 0, 2, 3, 0 }, { 1, 2, 3, 0 }, { 0, 1, 2, 3 } };
const int kLaneCount[16] = { 0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4 };

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

// ... then, from |g| in norm, the unit level-line vector (-gy, gx) / |g| in fixed point and the
// gradient norm |g| / 2 ((0, 0) and 0 for an undefined pixel).
void levelLines(const uchar* __restrict above, const uchar* __restrict below, int n, int threshold,
                float* __restrict norm, short* __restrict level)
{
    for (int x = 0; x < n; x++)
    {
        int gx, gy;
        gradient2x2(above, below, x, gx, gy);
        const float defined = (float)(gx * gx + gy * gy > threshold);
        const float scale = defined * (kUnit / norm[x]);
        level[2 * x] = (short)(-gy * scale);
        level[2 * x + 1] = (short)(gx * scale);
        norm[x] *= 0.5f * defined;
    }
}

} // namespace

// Eight pixels at a time in one pass with the same float operations as the two loops above
// (bit-identical), which do the rest of the row.
void gradientRow(const uchar* above, const uchar* below, int n, int threshold, float* norm, short* level,
                 int& rowMax, int& defined)
{
    int x = 0, maxNorm2 = 0, count = 0;
#if CV_SIMD128
    const v_int32x4 limit = v_setall_s32(threshold), one = v_setall_s32(1);
    const v_float32x4 unit = v_setall_f32(kUnit), half = v_setall_f32(0.5f);
    // The maximum in float, exact (gx^2 + gy^2 <= 2 * 510^2 < 2^24): SSE2 has no 32-bit integer max.
    v_float32x4 maxima = v_setzero_f32();
    v_int32x4 counts = v_setzero_s32();
    for (; x + 8 <= n; x += 8)
    {
        const v_int16x8 a = v_reinterpret_as_s16(v_load_expand(above + x)), b = v_reinterpret_as_s16(v_load_expand(above + x + 1));
        const v_int16x8 c = v_reinterpret_as_s16(v_load_expand(below + x)), d = v_reinterpret_as_s16(v_load_expand(below + x + 1));
        const v_int16x8 da = d - a, bc = b - c, gx = da + bc, gy = da - bc;
        v_int16x8 pairs[2];
        v_zip(gx, gy, pairs[0], pairs[1]);
        v_int32x4 gx32[2], gy32[2];
        v_expand(gx, gx32[0], gx32[1]);
        v_expand(gy, gy32[0], gy32[1]);
        v_int32x4 ux[2], uy[2];
        for (int h = 0; h < 2; h++)
        {
            const v_int32x4 n2 = v_dotprod(pairs[h], pairs[h]);
            const v_int32x4 isDefined = n2 > limit;
            maxima = v_max(maxima, v_cvt_f32(n2));
            counts -= isDefined;
            const v_float32x4 root = v_sqrt(v_cvt_f32(n2 + ((n2 == v_setzero_s32()) & one)));
            // The loops' products by 1 or 0 as masks: x or +0 (x is positive), the same floats.
            const v_float32x4 def = v_reinterpret_as_f32(isDefined);
            const v_float32x4 scale = (unit / root) & def;
            ux[h] = v_trunc(v_cvt_f32(v_setzero_s32() - gy32[h]) * scale);
            uy[h] = v_trunc(v_cvt_f32(gx32[h]) * scale);
            v_store(norm + x + 4 * h, (root * half) & def);
        }
        v_store_interleave(level + 2 * x, v_pack(ux[0], ux[1]), v_pack(uy[0], uy[1]));
    }
    maxNorm2 = (int)v_reduce_max(maxima);
    count = v_reduce_sum(counts);
#endif
    if (x < n)
    {
        int tailMax, tailDefined;
        gradientNorms(above + x, below + x, n - x, threshold, norm + x, tailMax, tailDefined);
        hal::sqrt32f(norm + x, norm + x, n - x);
        levelLines(above + x, below + x, n - x, threshold, norm + x, level + 2 * x);
        maxNorm2 = std::max(maxNorm2, tailMax);
        count += tailDefined;
    }
    rowMax = maxNorm2;
    defined = count;
}

// A compaction without a branch per pixel (seeds and other pixels alternate at random in textured
// areas): every pixel is written, and the end moves on past the seeds.
int* strongPixels(const float* norm, int row, int n, float least, int* next)
{
    int x = 0;
#if CV_SIMD128
    const v_float32x4 leastNorm = v_setall_f32(least);
    for (; x + 4 <= n; x += 4)
    {
        const int lanes = v_signmask(v_load(norm + x) >= leastNorm);
        v_store(next, v_setall_s32(row + x) + v_load(kPackedLanes[lanes]));
        next += kLaneCount[lanes];
    }
#endif
    for (; x < n; x++)
    {
        *next = row + x;
        next += norm[x] >= least;
    }
    return next;
}

int* edgePixels(const GradientField& field, int needed, int alignedDot, const int* candidate, const int* end,
                int* seeds)
{
#if CV_SIMD128
    // GradientField::alignedNeighbours four candidates at a time when its limit is 0 or more, in
    // the same integers: a vector (u_x, u_y) as one 32-bit lane, its products with a neighbour's in
    // one v_dotprod.
    if (alignedDot >= 0)
    {
        const Vec2s* level = field.level.data();
        const auto word = [&](int pixel) {
            int w;
            std::memcpy(&w, &level[pixel], sizeof w);
            return w;
        };
        const v_int32x4 limit = v_setall_s32(alignedDot), axis = v_setall_s32(kStep), minusAxis = v_setall_s32(-kStep);
        const v_int32x4 rowStep = v_setall_s32(field.stride), least = v_setall_s32(needed);
        for (; candidate + 4 <= end; candidate += 4)
        {
            const int q[4] = { candidate[0], candidate[1], candidate[2], candidate[3] };
            const v_int32x4 u(word(q[0]), word(q[1]), word(q[2]), word(q[3]));
            const v_int32x4 ux = v_shr<16>(v_shl<16>(u)), uy = v_shr<16>(u);
            // The step along the level line: (u > kStep) - (u < -kStep) per axis, from the masks (-1).
            const v_int32x4 dx = (ux < minusAxis) - (ux > axis);
            const v_int32x4 offset = ((uy > axis) & rowStep) - ((uy < minusAxis) & rowStep) + dx;
            int off[4];
            v_store(off, offset);
            const v_int32x4 a(word(q[0] + off[0]), word(q[1] + off[1]), word(q[2] + off[2]), word(q[3] + off[3]));
            const v_int32x4 b(word(q[0] - off[0]), word(q[1] - off[1]), word(q[2] - off[2]), word(q[3] - off[3]));
            const v_int16x8 u16 = v_reinterpret_as_s16(u);
            const v_int32x4 aligned = v_setzero_s32() - (v_dotprod(u16, v_reinterpret_as_s16(a)) > limit) -
                                      (v_dotprod(u16, v_reinterpret_as_s16(b)) > limit);
            const int keep = v_signmask(aligned >= least);
            for (int j = 0; j < 4; j++)
            {
                *seeds = q[j];
                seeds += (keep >> j) & 1;
            }
        }
    }
#endif
    for (; candidate < end; candidate++)
    {
        const int q = *candidate;
        *seeds = q;
        seeds += field.alignedNeighbours(q, alignedDot) >= needed;
    }
    return seeds;
}

void regionExtents(const Point* pixel, int count, double cx, double cy, const Point2d& dir, double& lMin,
                   double& lMax, double& wMin, double& wMax)
{
    lMin = lMax = wMin = wMax = 0;
    int i = 0;
#if CV_SIMD128_64F
    // Four pixels at a time with the same double operations (w as a difference: -a b + c = c - a b
    // exactly), the extremes in two lanes each; v_min(l, m) takes l only when l < m, as std::min(m, l).
    {
        const v_float64x2 x0 = v_setall_f64(cx), y0 = v_setall_f64(cy), ux = v_setall_f64(dir.x), uy = v_setall_f64(dir.y);
        v_float64x2 lLow = v_setzero_f64(), lHigh = lLow, wLow = lLow, wHigh = lLow;
        for (; i + 4 <= count; i += 4)
        {
            v_int32x4 xs, ys;
            v_load_deinterleave(&pixel[i].x, xs, ys);
            const v_float64x2 ddx[2] = { v_cvt_f64(xs) - x0, v_cvt_f64_high(xs) - x0 };
            const v_float64x2 ddy[2] = { v_cvt_f64(ys) - y0, v_cvt_f64_high(ys) - y0 };
            for (int h = 0; h < 2; h++)
            {
                const v_float64x2 l = ddx[h] * ux + ddy[h] * uy, w = ddy[h] * ux - ddx[h] * uy;
                lLow = v_min(l, lLow);
                lHigh = v_max(l, lHigh);
                wLow = v_min(w, wLow);
                wHigh = v_max(w, wHigh);
            }
        }
        double lanes[4][2];
        v_store(lanes[0], lLow);
        v_store(lanes[1], lHigh);
        v_store(lanes[2], wLow);
        v_store(lanes[3], wHigh);
        lMin = std::min(lanes[0][0], lanes[0][1]);
        lMax = std::max(lanes[1][0], lanes[1][1]);
        wMin = std::min(lanes[2][0], lanes[2][1]);
        wMax = std::max(lanes[3][0], lanes[3][1]);
    }
#endif
    for (; i < count; i++)
    {
        const double ddx = pixel[i].x - cx, ddy = pixel[i].y - cy;
        const double l = ddx * dir.x + ddy * dir.y;
        const double w = -ddx * dir.y + ddy * dir.x;
        lMin = std::min(lMin, l);
        lMax = std::max(lMax, l);
        wMin = std::min(wMin, w);
        wMax = std::max(wMax, w);
    }
}

} // namespace fast_lsd

}}} // namespace cv::ximgproc::lsda
