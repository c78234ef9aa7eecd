// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The response of a segment: its length weighted by the square of the mean gray-level step
// across it, a tenth of that when the image border cuts it. It ranks lines for matching
// (KeyLine::response) and lets stage 1 keep short segments with strong evidence
// (doc/matching.md).

#include "precomp.hpp"
#include "opencv2/core/hal/intrin.hpp"
#include <cstring>

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

// Bilinear interpolation in the cell whose top-left pixel is p, `right` and `down` bytes to the
// next pixel and row (0 on the image's last column or row).
inline float bilinear(const uchar* p, int right, size_t down, float fx, float fy)
{
    const float top = p[0] + fx * (float)(p[right] - p[0]);
    const float bottom = p[down] + fx * (float)(p[down + right] - p[down]);
    return top + fy * (bottom - top);
}

// Bilinear gray level at (x, y), coordinates clamped into the image.
float grayAt(const Mat& gray, float x, float y)
{
    x = std::min(std::max(x, 0.f), (float)(gray.cols - 1));
    y = std::min(std::max(y, 0.f), (float)(gray.rows - 1));
    const int x0 = std::min((int)x, std::max(gray.cols - 2, 0)), y0 = std::min((int)y, std::max(gray.rows - 2, 0));
    return bilinear(gray.ptr<uchar>(y0) + x0, x0 + 1 < gray.cols ? 1 : 0, y0 + 1 < gray.rows ? gray.step[0] : 0,
                    x - (float)x0, y - (float)y0);
}

#if CV_SIMD128
// bilinear() at four points of the image's cells (x in [0, cols - 2], y in [0, rows - 2]), with
// its float operations lane by lane (the same values). Each pair of horizontal neighbours is read
// in one 16-bit load, the four top pairs and the four bottom pairs into one vector.
inline v_float32x4 bilinear4(const uchar* data, size_t down, const v_float32x4& x, const v_float32x4& y)
{
    const v_int32x4 ix = v_trunc(x), iy = v_trunc(y);
    int cx[4], cy[4];
    v_store(cx, ix);
    v_store(cy, iy);
    const uchar* cell[4];
    for (int j = 0; j < 4; j++)
        cell[j] = data + cy[j] * down + cx[j];
    const auto pair = [](const uchar* p) { return (ushort)(p[0] | p[1] << 8); };
    const v_uint16x8 pairs(pair(cell[0]), pair(cell[1]), pair(cell[2]), pair(cell[3]), pair(cell[0] + down),
                           pair(cell[1] + down), pair(cell[2] + down), pair(cell[3] + down));
    v_uint32x4 top, bottom;
    v_expand(pairs, top, bottom);
    const v_uint32x4 byte = v_setall_u32(0xFF);
    const v_int32x4 topLeft = v_reinterpret_as_s32(top & byte), topRight = v_reinterpret_as_s32(v_shr<8>(top));
    const v_int32x4 bottomLeft = v_reinterpret_as_s32(bottom & byte);
    const v_int32x4 bottomRight = v_reinterpret_as_s32(v_shr<8>(bottom));
    const v_float32x4 fx = x - v_cvt_f32(ix), fy = y - v_cvt_f32(iy);
    const v_float32x4 upper = v_cvt_f32(topLeft) + fx * v_cvt_f32(topRight - topLeft);
    const v_float32x4 lower = v_cvt_f32(bottomLeft) + fx * v_cvt_f32(bottomRight - bottomLeft);
    return upper + fy * (lower - upper);
}
#endif

// Sum over the samples p0 + k step (k < samples) of the positive part of gray(p + left) -
// gray(p - left), directly when both probes of the sample lie in [0, cols - 2] x [0, rows - 2]
// (grayAt would read the same four pixels with the same weights), at clamped coordinates
// otherwise: most samples of a segment near the border are inside. `inside`: every probe is.
// Four samples at a time with the float operations of one wherever all their probes are inside;
// the sum in the same order.
double positiveSteps(const Mat& gray, Point2f p0, Point2f step, Point2f left, int samples, bool inside)
{
    const float right = (float)(gray.cols - 2), bottom = (float)(gray.rows - 2);
    const auto inCells = [&](Point2f q) { return q.x >= 0.f && q.x <= right && q.y >= 0.f && q.y <= bottom; };
    const uchar* data = gray.data;
    const size_t down = gray.step[0];
    const auto positiveStep = [&](int k) {
        const Point2f p = p0 + (float)k * step, l = p + left, r = p - left;
        float across;
        if (inside || (inCells(l) && inCells(r)))
        {
            const int lx = (int)l.x, ly = (int)l.y, rx = (int)r.x, ry = (int)r.y;
            across = bilinear(data + ly * down + lx, 1, down, l.x - (float)lx, l.y - (float)ly) -
                     bilinear(data + ry * down + rx, 1, down, r.x - (float)rx, r.y - (float)ry);
        }
        else
            across = grayAt(gray, l.x, l.y) - grayAt(gray, r.x, r.y);
        return std::max(across, 0.f);  // the wrong polarity is no evidence for this segment
    };
    double sum = 0.0;
    int k = 0;
#if CV_SIMD128
    const v_float32x4 lanes(0.f, 1.f, 2.f, 3.f), x0 = v_setall_f32(p0.x), y0 = v_setall_f32(p0.y);
    const v_float32x4 dx = v_setall_f32(step.x), dy = v_setall_f32(step.y);
    const v_float32x4 lx = v_setall_f32(left.x), ly = v_setall_f32(left.y), zero = v_setzero_f32();
    const v_float32x4 xMax = v_setall_f32(right), yMax = v_setall_f32(bottom);
    float across[4];
    for (; k + 4 <= samples; k += 4)
    {
        const v_float32x4 kf = v_setall_f32((float)k) + lanes;  // exact: k < 2^24
        const v_float32x4 px = x0 + kf * dx, py = y0 + kf * dy;
        const v_float32x4 leftX = px + lx, leftY = py + ly, rightX = px - lx, rightY = py - ly;
        if (!inside &&
            !v_check_all((v_min(leftX, rightX) >= zero) & (v_max(leftX, rightX) <= xMax) &
                         (v_min(leftY, rightY) >= zero) & (v_max(leftY, rightY) <= yMax)))
        {
            for (int j = 0; j < 4; j++)
                sum += positiveStep(k + j);
            continue;
        }
        v_store(across, v_max(bilinear4(data, down, leftX, leftY) - bilinear4(data, down, rightX, rightY), zero));
        for (int j = 0; j < 4; j++)
            sum += across[j];
    }
#endif
    for (; k < samples; k++)
        sum += positiveStep(k);
    return sum;
}

// An endpoint this close to the image's edge (pixels from the first or last pixel centre), or
// beyond it, means the frame cuts the segment.
constexpr double kBorderMargin = 2.0;
// The response of a cut segment is scaled by this: measured, it then ranks as if it came after
// every segment inside the image (1/4 keeps half of that gain; doc/matching.md).
constexpr double kCutFactor = 0.1;

bool cutByBorder(const Vec4f& s, Size size)
{
    const auto near = [](double v, int side) { return v < kBorderMargin || v > side - 1 - kBorderMargin; };
    return near(s[0], size.width) || near(s[2], size.width) || near(s[1], size.height) || near(s[3], size.height);
}

// Mean gray-level step across the segment, its left (brighter) side minus its right side, 1 px
// either side of its centre line, sampled at the centre of each unit step (bilinear, coordinates
// clamped into the image); negative steps count 0. Gray levels, in [0, 255].
double meanContrast(const Mat& gray, const Vec4f& s)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "meanContrast samples a gray image");
    const Point2d a(s[0], s[1]), d(s[2] - s[0], s[3] - s[1]);
    const double len = std::sqrt(d.dot(d));
    if (!(len > 0) || gray.empty())
        return 0.0;
    const Point2f left((float)(d.y / len), (float)(-d.x / len));  // unit normal to the left of d, y pointing down
    // One sample at the centre of each unit step; the step across the edge is taken 1 px either
    // side, which spans LSD's sub-pixel placement of the segment on a sharp edge.
    const int samples = std::max(1, cvRound(len));
    const Point2f step((float)(d.x / samples), (float)(d.y / samples));
    const Point2f first((float)a.x + 0.5f * step.x, (float)a.y + 0.5f * step.y);
    // The probes lie within 1 px of the segment: inside when its endpoints are 1 px inside the
    // cells of the image.
    const auto within = [](float v, int side) { return v >= 1.f && v <= (float)side - 3.f; };
    const bool inside = within(s[0], gray.cols) && within(s[2], gray.cols) && within(s[1], gray.rows) &&
                        within(s[3], gray.rows);
    const double sum = positiveSteps(gray, first, step, left, samples, inside);
    return sum / samples;
}

// Segments per task: a segment costs about a sample per pixel of its length, and a task of a few
// costs the pool more than their samples.
constexpr int kSegmentsPerTask = 64;

// The response of segment i of a gray image.
float segmentResponse(const Mat& gray, const Vec4f& segment)
{
    const double longerSide = std::max(gray.cols, gray.rows);
    const double contrast = meanContrast(gray, segment) / 255.0;
    // A segment the frame cuts shows a part of its line that changes from view to view, and
    // LBD's bands reach out of the image: it is found again less often, and matched wrongly
    // more often (measured on HPatches and KITTI, doc/matching.md).
    const double visibility = cutByBorder(segment, gray.size()) ? kCutFactor : 1.0;
    return (float)(segmentLength(segment) / longerSide * contrast * contrast * visibility);
}

// The responses of the segments whose response is negative (not known yet), one per segment.
void unknownResponses(const Mat& gray, const std::vector<Vec4f>& segments, std::vector<float>& responses)
{
    CV_Assert(responses.size() == segments.size());
    if (std::none_of(responses.begin(), responses.end(), [](float r) { return r < 0.f; }))
        return;
    // Before the tasks: the caller gets the error.
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "lineResponses samples a gray image");
    // Each segment that has none yet (negative) alone.
    TaskLayout tasks;
    tasks.evenly((int)segments.size(), kSegmentsPerTask);
    runTasks(tasks, [&](int, const Range& items) {
        for (int i = items.start; i < items.end; i++)
            if (responses[i] < 0.f)
                responses[i] = segmentResponse(gray, segments[i]);
    });
}

} // namespace

void lineResponses(const Mat& gray, const std::vector<Vec4f>& segments, std::vector<float>& responses)
{
    responses.assign(segments.size(), -1.f);
    unknownResponses(gray, segments, responses);
}

void KnownResponses::clear()
{
    known.clear();
}

void KnownResponses::followKept(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out,
                                const std::vector<int>& keptFrom)
{
    if (known.empty())
        return;
    CV_Assert(known.size() == in.size() && keptFrom.size() == out.size());
    carried.resize(out.size());
    for (size_t j = 0; j < out.size(); j++)
    {
        const int i = keptFrom[j];
        // The response is that of the segment's coordinates: it goes with them, bit for bit.
        carried[j] = i >= 0 && std::memcmp(&out[j], &in[i], sizeof(Vec4f)) == 0 ? known[i] : -1.f;
    }
    known.swap(carried);
}

void KnownResponses::followMerged(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out,
                                  const std::vector<int>& mergedInto)
{
    if (known.empty())
        return;
    // Each merged segment from one of its pieces: a survivor that fused nothing is that piece.
    pieceOf.assign(out.size(), -1);
    for (size_t i = 0; i < mergedInto.size(); i++)
        if (mergedInto[i] >= 0)
            pieceOf[mergedInto[i]] = (int)i;
    followKept(in, out, pieceOf);
}

const std::vector<float>& KnownResponses::complete(const Mat& gray, const std::vector<Vec4f>& segments)
{
    if (known.empty())
        known.assign(segments.size(), -1.f);
    unknownResponses(gray, segments, known);
    return known;
}

} // namespace lsda

void computeLineResponses(InputArray image, InputArray lines, OutputArray responses)
{
    CV_INSTRUMENT_REGION();
    const Mat gray = lsda::toGray8U(image);
    const std::vector<Vec4f> segments = lsda::toSegments(lines, "computeLineResponses: lines");
    if (!segments.empty() && !checkRange(Mat(segments), true))
        CV_Error(Error::StsOutOfRange, "computeLineResponses: segment coordinates must be finite");
    std::vector<float> values;
    lsda::lineResponses(gray, segments, values);
    Mat(values).copyTo(responses);
}

}} // namespace cv::ximgproc
