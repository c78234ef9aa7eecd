// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// computeLBD's gradient (src/lbd/): OpenCV's 5 x 5 Gaussian of sigma 1 then its 3 x 3 Sobel, in the
// same integers (GaussianBlur on 8-bit images is bit-exact fixed point, Sobel on its output exact),
// computed only in the tiles of kTile x kTile pixels that a line's support region reaches.

#include "parts.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

#include "opencv2/core/hal/intrin.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {
namespace lbd {

namespace {

// OpenCV's 5-tap Gaussian of sigma 1 in the fixed point of its bit-exact GaussianBlur on 8-bit
// images (8 fractional bits, the taps summing to 256): outer, inner, centre.
constexpr int kGaussTaps[3] = { 14, 62, 104 };
// The identity in the same fixed point: GaussianBlur does not smooth along a side of 1 px.
constexpr int kIdentityTaps[3] = { 0, 0, 256 };

inline uint32_t packGradient(int dx, int dy)
{
    return (uint32_t)(ushort)dx | (uint32_t)(ushort)dy << 16;
}

// The x-interval, within [-inf, +inf], of a convex polygon's part between rows ya and yb
// (inclusive); false when it has none.
bool slabInterval(const Point2d* polygon, int n, double ya, double yb, double& xmin, double& xmax)
{
    xmin = DBL_MAX;
    xmax = -DBL_MAX;
    for (int i = 0; i < n; i++)
    {
        const Point2d& p = polygon[i];
        const Point2d& q = polygon[(i + 1) % n];
        if (p.y >= ya && p.y <= yb)
        {
            xmin = std::min(xmin, p.x);
            xmax = std::max(xmax, p.x);
        }
        for (const double y : { ya, yb })
            if ((p.y - y) * (q.y - y) < 0)
            {
                const double x = p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y);
                xmin = std::min(xmin, x);
                xmax = std::max(xmax, x);
            }
    }
    return xmin <= xmax;
}

} // namespace

// One chunk of the gradient: GaussianBlur's fixed point (rows of the horizontal pass in 8.8,
// the vertical pass rounded to 8 bits), then Sobel, each with BORDER_REFLECT_101. Integers all
// through, so any order of the sums gives OpenCV's values.
void computeGradientChunk(const Mat& gray, const GradientChunk& chunk, uint32_t* gradient)
{
    const int width = gray.cols, height = gray.rows;
    const int* kx = width > 1 ? kGaussTaps : kIdentityTaps;
    const int* ky = height > 1 ? kGaussTaps : kIdentityTaps;
    // Blurred pixels: the chunk and one around it, within the image; the rows of the horizontal
    // pass they need, two more each way.
    const int bx0 = std::max(chunk.x0 - 1, 0), bx1 = std::min(chunk.x1 + 1, width), bw = bx1 - bx0;
    const int by0 = std::max(chunk.y0 - 1, 0), by1 = std::min(chunk.y1 + 1, height);
    const int hy0 = std::max(chunk.y0 - 3, 0), hy1 = std::min(chunk.y1 + 3, height);

    // The horizontal pass minus 32768, so that it fits signed 16 bits (for the vertical pass's
    // multiply-adds; the taps sum to 256, which puts 256 * 32768 back).
    short smoothedRows[kTile + 6][kChunkColumns + 2];
    uchar blurred[kTile + 2][kChunkColumns + 2 + 8];  // column q: image column chunk.x0 - 1 + q
    uchar source[kChunkColumns + 6];

    for (int y = hy0; y < hy1; y++)
    {
        const uchar* row = gray.ptr<uchar>(y);
        // Columns bx0 - 2 .. bx1 + 1, reflected where they leave the image.
        const int inside0 = std::max(bx0 - 2, 0), inside1 = std::min(bx1 + 2, width);
        for (int x = bx0 - 2; x < inside0; x++)
            source[x - (bx0 - 2)] = row[borderInterpolate(x, width, BORDER_REFLECT_101)];
        std::memcpy(source + inside0 - (bx0 - 2), row + inside0, inside1 - inside0);
        for (int x = inside1; x < bx1 + 2; x++)
            source[x - (bx0 - 2)] = row[borderInterpolate(x, width, BORDER_REFLECT_101)];
        short* out = smoothedRows[y - hy0];
        int j = 0;
#if CV_SIMD128
        const v_uint16x8 k0 = v_setall_u16((ushort)kx[0]), k1 = v_setall_u16((ushort)kx[1]);
        const v_uint16x8 k2 = v_setall_u16((ushort)kx[2]), offset = v_setall_u16(0x8000);
        for (; j + 8 <= bw; j += 8)
        {
            const uchar* s = source + j;
            // At most 255 * 256: no lane wraps.
            const v_uint16x8 sum = v_mul_wrap(k0, v_load_expand(s) + v_load_expand(s + 4)) +
                                   v_mul_wrap(k1, v_load_expand(s + 1) + v_load_expand(s + 3)) +
                                   v_mul_wrap(k2, v_load_expand(s + 2));
            v_store(out + j, v_reinterpret_as_s16(sum ^ offset));
        }
#endif
        for (; j < bw; j++)
        {
            const uchar* s = source + j;
            out[j] = (short)(kx[0] * (s[0] + s[4]) + kx[1] * (s[1] + s[3]) + kx[2] * s[2] - 32768);
        }
    }

    constexpr int kRestored = 256 * 32768 + (1 << 15);  // the offset back, and the rounding
    const int offset = bx0 - (chunk.x0 - 1);  // column of blurred for bx0
    for (int y = by0; y < by1; y++)
    {
        const short* r[5];
        for (int t = 0; t < 5; t++)
        {
            const int ry = y + t - 2;
            r[t] = smoothedRows[((ry >= 0 && ry < height) ? ry : borderInterpolate(ry, height, BORDER_REFLECT_101)) - hy0];
        }
        uchar* out = blurred[y - by0] + offset;
        int j = 0;
#if CV_SIMD128
        const v_int16x8 k01 = v_reinterpret_as_s16(v_setall_s32(ky[0] | ky[1] << 16));
        const v_int16x8 k23 = v_reinterpret_as_s16(v_setall_s32(ky[2] | ky[1] << 16));
        const v_int16x8 k4 = v_reinterpret_as_s16(v_setall_s32(ky[0])), zero = v_setzero_s16();
        const v_int32x4 restored = v_setall_s32(kRestored);
        for (; j + 8 <= bw; j += 8)
        {
            v_int16x8 p01[2], p23[2], p4[2];
            v_zip(v_load(r[0] + j), v_load(r[1] + j), p01[0], p01[1]);
            v_zip(v_load(r[2] + j), v_load(r[3] + j), p23[0], p23[1]);
            v_zip(v_load(r[4] + j), zero, p4[0], p4[1]);
            v_int32x4 sum[2];
            for (int h = 0; h < 2; h++)
                sum[h] = v_shr<16>(v_dotprod(p01[h], k01) + v_dotprod(p23[h], k23) + v_dotprod(p4[h], k4) + restored);
            v_pack_u_store(out + j, v_pack(sum[0], sum[1]));
        }
#endif
        for (; j < bw; j++)
            out[j] = (uchar)((ky[0] * (r[0][j] + r[4][j]) + ky[1] * (r[1][j] + r[3][j]) + ky[2] * r[2][j] + kRestored) >> 16);
        // The columns beside the chunk that are outside the image: their reflections.
        uchar* b = blurred[y - by0];
        if (chunk.x0 == 0)
            b[0] = b[1 + borderInterpolate(-1, width, BORDER_REFLECT_101)];
        if (chunk.x1 == width)
            b[width - chunk.x0 + 1] = b[1 + borderInterpolate(width, width, BORDER_REFLECT_101) - chunk.x0];
    }

    const int cw = chunk.x1 - chunk.x0;
    for (int y = chunk.y0; y < chunk.y1; y++)
    {
        const int above = y > 0 ? y - 1 : borderInterpolate(-1, height, BORDER_REFLECT_101);
        const int below = y + 1 < height ? y + 1 : borderInterpolate(height, height, BORDER_REFLECT_101);
        const uchar* a = blurred[above - by0];
        const uchar* m = blurred[y - by0];
        const uchar* b = blurred[below - by0];
        uint32_t* out = gradient + (size_t)y * width + chunk.x0;
        int q = 0;
#if CV_SIMD128
        for (; q + 8 <= cw; q += 8)
        {
            const auto at = [](const uchar* p) { return v_reinterpret_as_s16(v_load_expand(p)); };
            const v_int16x8 a0 = at(a + q), a1 = at(a + q + 1), a2 = at(a + q + 2);
            const v_int16x8 m0 = at(m + q), m2 = at(m + q + 2);
            const v_int16x8 b0 = at(b + q), b1 = at(b + q + 1), b2 = at(b + q + 2);
            const v_int16x8 dx = (a2 - a0) + ((m2 - m0) + (m2 - m0)) + (b2 - b0);
            const v_int16x8 dy = (b0 + (b1 + b1) + b2) - (a0 + (a1 + a1) + a2);
            v_store_interleave((short*)(out + q), dx, dy);
        }
#endif
        for (; q < cw; q++)
        {
            const int dx = (a[q + 2] - a[q]) + 2 * (m[q + 2] - m[q]) + (b[q + 2] - b[q]);
            const int dy = (b[q] + 2 * b[q + 1] + b[q + 2]) - (a[q] + 2 * a[q + 1] + a[q + 2]);
            out[q] = packGradient(dx, dy);
        }
    }
}

// Marks the tiles whose pixels the samples of a region may read, and returns whether each sample
// rounds to a pixel of the image. A sample reads the pixel nearest to it, clamped into the
// image; the float steps from sample to sample drift from the exact positions by less than
// `margin`, a bound of their rounding errors.
bool markRegionTiles(const LineRegion& r, Size size, int tilesX, std::vector<uchar>& tiles)
{
    const double along = r.length - 1, across = kSampledRows - 1;
    const double extent = std::max(std::abs((double)r.x0), std::abs((double)r.y0)) + along + across + 2;
    const double margin = 1.0 + (along + across) * extent * std::ldexp(1.0, -22);
    const Point2d u(r.c, r.s), v(-r.s, r.c), origin(r.x0, r.y0);
    const Point2d corner = origin - margin * u - margin * v;
    const Point2d a = (along + 2 * margin) * u, b = (across + 2 * margin) * v;
    const Point2d polygon[4] = { corner, corner + a, corner + a + b, corner + b };
    const int bandsY = (size.height + kTile - 1) / kTile;
    double xmin = DBL_MAX, xmax = -DBL_MAX, ymin = DBL_MAX, ymax = -DBL_MAX;
    for (const Point2d& p : polygon)
    {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
    }
    const int firstBand = std::max(0, std::min(bandsY - 1, (int)std::floor(ymin / kTile)));
    const int lastBand = std::max(0, std::min(bandsY - 1, (int)std::floor(ymax / kTile)));
    for (int band = firstBand; band <= lastBand; band++)
    {
        // A band's rows, and all rows beyond the image for the first and last bands (they read
        // the border rows).
        const double ya = band == 0 ? -DBL_MAX : (double)band * kTile - 0.5;
        const double yb = band == bandsY - 1 ? DBL_MAX : (double)(band + 1) * kTile - 0.5;
        double left, right;
        if (!slabInterval(polygon, 4, ya, yb, left, right))
            continue;
        const int first = (int)std::max(0.0, std::min((double)size.width - 1, std::floor(left))) / kTile;
        const int last = (int)std::max(0.0, std::min((double)size.width - 1, std::ceil(right))) / kTile;
        std::fill(tiles.begin() + band * tilesX + first, tiles.begin() + band * tilesX + last + 1, (uchar)1);
    }
    return xmin >= 0 && ymin >= 0 && xmax <= size.width - 1 && ymax <= size.height - 1;
}

// The chunks of the marked tiles, row of tiles by row of tiles, runs of tiles cut at
// kChunkColumns.
void layChunks(const std::vector<uchar>& tiles, Size size, int tilesX, std::vector<GradientChunk>& chunks)
{
    chunks.clear();
    const int bandsY = (size.height + kTile - 1) / kTile;
    for (int band = 0; band < bandsY; band++)
    {
        const uchar* marks = &tiles[band * tilesX];
        const int y0 = band * kTile, y1 = std::min(size.height, y0 + kTile);
        for (int t = 0; t < tilesX;)
        {
            if (!marks[t])
            {
                t++;
                continue;
            }
            int end = t;
            while (end < tilesX && marks[end] && (end - t + 1) * kTile <= kChunkColumns)
                end++;
            chunks.push_back(GradientChunk{ y0, y1, t * kTile, std::min(size.width, end * kTile) });
            t = end;
        }
    }
}

} // namespace lbd

void lbdGradient(const Mat& gray, Mat& gradient)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "lbdGradient: gray image");
    CV_Assert(!gray.empty());
    gradient.create(gray.size(), CV_16SC2);
    std::vector<uint32_t> packed(gray.total());
    for (int y0 = 0; y0 < gray.rows; y0 += lbd::kTile)
        for (int x0 = 0; x0 < gray.cols; x0 += lbd::kChunkColumns)
            lbd::computeGradientChunk(gray,
                                 lbd::GradientChunk{ y0, std::min(gray.rows, y0 + lbd::kTile), x0, std::min(gray.cols, x0 + lbd::kChunkColumns) },
                                 packed.data());
    for (int y = 0; y < gray.rows; y++)
        for (int x = 0; x < gray.cols; x++)
        {
            const uint32_t g = packed[(size_t)y * gray.cols + x];
            gradient.at<Vec2s>(y, x) = Vec2s((short)(g & 0xFFFF), (short)(g >> 16));
        }
}

}}} // namespace cv::ximgproc::lsda

#endif
