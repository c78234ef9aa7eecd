// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// computeLBD: the LBD descriptor (Zhang & Koch, JVCIR 2013) as line_descriptor's
// BinaryDescriptor::compute computes it with its default parameters, byte for byte, written for
// speed. Where the reference spends its time, and what this one does instead:
// - the gradient: it smooths and differentiates the whole image (a 5 x 5 Gaussian of sigma 1, then
//   3 x 3 Sobel, both with reflected borders) into new buffers at every call. Here the same
//   integers (OpenCV's Gaussian on 8-bit images is bit-exact fixed point, Sobel on its output is
//   exact) come from one pass per 32 x 32 tile, only in the tiles that a line's support region
//   reaches, into a buffer kept by the calling thread: (dx, dy) of a pixel in one 32-bit word;
// - the support region: its 63 rows are sampled one row per lane, four rows at a time. Each lane
//   steps along its row with the same float operations in the same order as the reference, so
//   each row's sums are the same floats; the sign of a projection picks its sum without a branch,
//   and the rounding of a sample's coordinates is inline. The rest (the band sums, the
//   statistics, the normalisations and the bits) runs once per line in the reference's order;
// - the lines are described in parallel, each into its own row: the output does not depend on
//   the number of threads.

#include "parts.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

#include "opencv2/core/hal/intrin.hpp"
#include <climits>
#include <cstdint>
#include <cstring>

namespace cv {
namespace ximgproc {

using line_descriptor::KeyLine;

namespace lsda {

namespace {

using namespace lbd;

// The statistics of a band: means and standard deviations of the positive and negative parts of
// the gradient along the line and across it.
constexpr int kBandFloats = 8;
constexpr int kFloatsPerLine = kBands * kBandFloats;
constexpr int kDescriptorBytes = 32;
// line_descriptor counts a region's length in 16 bits.
constexpr int kMaxRegionLength = 32767;
// A value of the reference's unit feature vector is capped here before it is normalised again.
constexpr float kFeatureCap = 0.4f;

// Sampled pixels per task of the lines, at least: a task of a few short lines costs the pool more
// than their samples.
constexpr int kSamplesPerTask = 1 << 15;

// The weights of the reference, in its float rounding: per row of the region (a Gaussian over
// its 63 rows), and per row of a band for the band above, its own band and the band below (a
// Gaussian over three bands).
struct RegionWeights
{
    float row[kRegionRows];
    float band[3 * kBandRows];
    float invCount[kBands];  //!< 1 / the rows a band's statistics count
    int pairs[kDescriptorBytes][2];  //!< the bands each byte of the binary descriptor compares
};

const RegionWeights& regionWeights()
{
    static const RegionWeights weights = [] {
        RegionWeights w;
        // Integer halves, as line_descriptor computes them: centres 31 and 10, sigmas 31 and 7.
        const double rowCentre = (kRegionRows - 1) / 2, rowSigma = rowCentre;
        const double rowScale = -1 / (2 * rowSigma * rowSigma);
        for (int i = 0; i < kRegionRows; i++)
        {
            const double d = i - rowCentre;
            w.row[i] = (float)std::exp(d * d * rowScale);
        }
        const double bandCentre = (3 * kBandRows - 1) / 2, bandSigma = (2 * kBandRows + 1) / 2;
        const double bandScale = -1 / (2 * bandSigma * bandSigma);
        for (int i = 0; i < 3 * kBandRows; i++)
        {
            const double d = i - bandCentre;
            w.band[i] = (float)std::exp(d * d * bandScale);
        }
        // The first and last bands have a neighbour on one side only.
        for (int b = 0; b < kBands; b++)
            w.invCount[b] = (float)(1.0 / (kBandRows * ((b == 0 || b == kBands - 1) ? 2.0 : 3.0)));
        // Every pair of bands but those that join the first two with the last two, in order.
        int k = 0;
        for (int a = 0; a < kBands; a++)
            for (int b = a + 1; b < kBands; b++)
                if (!(a < 2 && b >= kBands - 2))
                {
                    w.pairs[k][0] = a;
                    w.pairs[k][1] = b;
                    k++;
                }
        CV_Assert(k == kDescriptorBytes);
        return w;
    }();
    return weights;
}

// The buffers of the calling thread, reused by its next calls.
struct Workspace
{
    std::vector<uint32_t> gradient;  //!< (dx, dy) of each pixel, as two 16-bit halves, row by row
    std::vector<uchar> tiles;        //!< per tile: whether a region reaches it
    std::vector<GradientChunk> chunks;
    std::vector<LineRegion> regions;
    TaskLayout gradientTasks, lineTasks;  //!< a chunk per task; lines of kSamplesPerTask samples or more per task
};

Workspace& threadWorkspace()
{
    static thread_local Workspace workspace;
    return workspace;
}

// The reference's rounding of a sample's coordinates: half-way cases away from zero (roundf).
inline int roundHalfAway(float v)
{
    return (int)std::round(v);
}

// The sums of one row of samples: positive and negative parts of the gradient along the line
// (dx c + dy s) and across it (-dx s + dy c), in the order of the samples.
struct RowSums
{
    float alongPositive[kSampledRows], alongNegative[kSampledRows];
    float acrossPositive[kSampledRows], acrossNegative[kSampledRows];
};

// Row h of the region starts at (startX[h], startY[h]).
void rowStarts(const LineRegion& r, float* startX, float* startY)
{
    float x = r.x0, y = r.y0;
    for (int h = 0; h < kSampledRows; h++)
    {
        startX[h] = x;
        startY[h] = y;
        x -= r.s;
        y += r.c;
    }
}

// The rows of a region one by one, as the reference samples them.
void sampleRowsOneByOne(const LineRegion& r, const uint32_t* gradient, Size size, RowSums& sums)
{
    float startX[kSampledRows], startY[kSampledRows];
    rowStarts(r, startX, startY);
    const int right = size.width - 1, bottom = size.height - 1;
    const float minusS = -r.s;
    for (int h = 0; h < kSampledRows; h++)
    {
        float px = startX[h], py = startY[h];
        float alongP = 0, alongN = 0, acrossP = 0, acrossN = 0;
        for (int w = 0; w < r.length; w++)
        {
            const int xi = std::min(std::max(roundHalfAway(px), 0), right);
            const int yi = std::min(std::max(roundHalfAway(py), 0), bottom);
            const uint32_t g = gradient[(size_t)yi * size.width + xi];
            const float dx = (float)(short)(g & 0xFFFF), dy = (float)(short)(g >> 16);
            const float along = dx * r.c + dy * r.s, across = dx * minusS + dy * r.c;
            if (along > 0)
                alongP += along;
            else
                alongN -= along;
            if (across > 0)
                acrossP += across;
            else
                acrossN -= across;
            px += r.c;
            py += r.s;
        }
        sums.alongPositive[h] = alongP;
        sums.alongNegative[h] = alongN;
        sums.acrossPositive[h] = acrossP;
        sums.acrossNegative[h] = acrossN;
    }
}

#if CV_SIMD128
// The rows of a region four at a time, one per lane, with the float operations of
// sampleRowsOneByOne lane by lane. The pixel's index comes from one multiply-add of the 16-bit
// coordinates (images of at most 32767 px a side). Without Clamp, every sample is known to
// round into the image, its coordinates at least 1: there roundf(v) is (int)(v + 0.5f), which
// rounds up only where roundf does (checked for every float in [0.5, 65536)); below 0.5 it is not
// (0.49999997f + 0.5f rounds to 1).
template <bool Clamp>
void sampleRowsFourByFour(const LineRegion& r, const uint32_t* gradient, Size size, RowSums& sums)
{
    float startX[kSampledRows], startY[kSampledRows];
    rowStarts(r, startX, startY);
    const v_float32x4 c = v_setall_f32(r.c), s = v_setall_f32(r.s), minusS = v_setall_f32(-r.s);
    const v_float32x4 zero = v_setzero_f32(), half = v_setall_f32(0.5f), minusHalf = v_setall_f32(-0.5f);
    const v_int32x4 maxX = v_setall_s32(size.width - 1), maxY = v_setall_s32(size.height - 1), origin = v_setzero_s32();
    const v_int16x8 toIndex = v_reinterpret_as_s16(v_setall_s32(1 | size.width << 16));  // (x, y) . (1, W)
    const auto roundCoordinate = [&](const v_float32x4& v, const v_int32x4& last) {
        if (!Clamp)
            return v_trunc(v + half);
        const v_int32x4 t = v_trunc(v);
        const v_float32x4 fraction = v - v_cvt_f32(t);  // exact
        const v_int32x4 rounded = t - v_reinterpret_as_s32(fraction >= half) + v_reinterpret_as_s32(fraction <= minusHalf);
        return v_min(v_max(rounded, origin), last);
    };
    for (int h = 0; h < kSampledRows; h += kLanes)
    {
        v_float32x4 px = v_load(startX + h), py = v_load(startY + h);
        v_float32x4 alongP = zero, alongN = zero, acrossP = zero, acrossN = zero;
        for (int w = 0; w < r.length; w++)
        {
            const v_int32x4 xi = roundCoordinate(px, maxX), yi = roundCoordinate(py, maxY);
            unsigned index[kLanes];  // below 2^30: unsigned spares the loads a sign extension
            v_store((int*)index, v_dotprod(v_reinterpret_as_s16(xi | v_shl<16>(yi)), toIndex));
            const v_int32x4 g((int)gradient[index[0]], (int)gradient[index[1]], (int)gradient[index[2]],
                              (int)gradient[index[3]]);
            const v_float32x4 dx = v_cvt_f32(v_shr<16>(v_shl<16>(g))), dy = v_cvt_f32(v_shr<16>(g));
            const v_float32x4 along = dx * c + dy * s, across = dx * minusS + dy * c;
            // The positive part, or a zero; the rest is the value, or a zero: adding or subtracting
            // a zero of either sign leaves these non-negative sums as the reference's branches do.
            const v_float32x4 alongUp = v_max(along, zero), acrossUp = v_max(across, zero);
            alongP += alongUp;
            alongN -= along - alongUp;
            acrossP += acrossUp;
            acrossN -= across - acrossUp;
            px += c;
            py += s;
        }
        v_store(sums.alongPositive + h, alongP);
        v_store(sums.alongNegative + h, alongN);
        v_store(sums.acrossPositive + h, acrossP);
        v_store(sums.acrossNegative + h, acrossN);
    }
}
#endif

// The row sums of a region: four rows at a time where the image's sides fit 16 bits, without
// clamping when the region is inside the image.
void sampleRegion(const LineRegion& r, const uint32_t* gradient, Size size, RowSums& sums)
{
#if CV_SIMD128
    if (size.width <= SHRT_MAX && size.height <= SHRT_MAX)
    {
        if (r.inside)
            sampleRowsFourByFour<false>(r, gradient, size, sums);
        else
            sampleRowsFourByFour<true>(r, gradient, size, sums);
        return;
    }
#endif
    sampleRowsOneByOne(r, gradient, size, sums);
}

// The 72 floats of a line from its row sums: per band, weighted sums of the rows of the band and
// of the two bands around it, their means and standard deviations, then the two normalisations
// of the reference with its cap between them. In the reference's order of operations.
void describeRegion(const RowSums& sums, float* descriptor)
{
    const RegionWeights& w = regionWeights();
    // Per band: the four sums, then the four sums of squares.
    float band[kBands][kBandFloats] = {};
    for (int h = 0; h < kRegionRows; h++)
    {
        const float g = w.row[h];
        const float row[4] = { g * sums.alongPositive[h], g * sums.alongNegative[h], g * sums.acrossPositive[h],
                               g * sums.acrossNegative[h] };
        const float squares[4] = { row[0] * row[0], row[1] * row[1], row[2] * row[2], row[3] * row[3] };
        const int own = h / kBandRows, k = h % kBandRows;
        // Its own band, the band above (own - 1), the band below (own + 1).
        const int bands[3] = { own, own - 1, own + 1 };
        const float coefficients[3] = { w.band[k + kBandRows], w.band[k + 2 * kBandRows], w.band[k] };
        for (int t = 0; t < 3; t++)
        {
            if (bands[t] < 0 || bands[t] >= kBands)
                continue;
            const float f = coefficients[t], f2 = f * f;
            float* sum = band[bands[t]];
            for (int q = 0; q < 4; q++)
            {
                sum[q] += f * row[q];
                sum[4 + q] += f2 * squares[q];
            }
        }
    }
    for (int b = 0; b < kBands; b++)
    {
        const float invN = w.invCount[b];
        for (int q = 0; q < 4; q++)
        {
            const float mean = band[b][q] * invN;
            descriptor[b * kBandFloats + q] = mean;
            descriptor[b * kBandFloats + 4 + q] = std::sqrt(band[b][4 + q] * invN - mean * mean);
        }
    }
    float means = 0, deviations = 0;
    for (int b = 0; b < kBands; b++)
        for (int q = 0; q < 4; q++)
        {
            const float* d = descriptor + b * kBandFloats;
            means += d[q] * d[q];
            deviations += d[4 + q] * d[4 + q];
        }
    const float meanScale = 1 / std::sqrt(means), deviationScale = 1 / std::sqrt(deviations);
    for (int b = 0; b < kBands; b++)
        for (int q = 0; q < 4; q++)
        {
            descriptor[b * kBandFloats + q] *= meanScale;
            descriptor[b * kBandFloats + 4 + q] *= deviationScale;
        }
    float norm = 0;
    for (int i = 0; i < kFloatsPerLine; i++)
    {
        descriptor[i] = std::min(descriptor[i], kFeatureCap);
        norm += descriptor[i] * descriptor[i];
    }
    const float scale = 1 / std::sqrt(norm);
    for (int i = 0; i < kFloatsPerLine; i++)
        descriptor[i] *= scale;
}

// Byte k, bit i: whether statistic i of band pairs[k][0] exceeds statistic i of band pairs[k][1].
void binarise(const float* descriptor, uchar* bytes)
{
    const RegionWeights& w = regionWeights();
    for (int k = 0; k < kDescriptorBytes; k++)
    {
        const float* a = descriptor + w.pairs[k][0] * kBandFloats;
        const float* b = descriptor + w.pairs[k][1] * kBandFloats;
        int byte = 0;
        for (int i = 0; i < kBandFloats; i++)
            byte |= (a[i] > b[i]) << i;
        bytes[k] = (uchar)byte;
    }
}

// Checks KeyLine i and returns its region.
LineRegion regionOf(const KeyLine& kl, int i, Size size)
{
    if (kl.octave != 0)
        CV_Error_(Error::StsNotImplemented,
                  ("computeLBD: KeyLine %d is of octave %d; only octave 0 (full resolution) is supported: "
                   "describe a multi-octave pyramid with line_descriptor::BinaryDescriptor::compute",
                   i, kl.octave));
    const float coordinates[5] = { kl.sPointInOctaveX, kl.sPointInOctaveY, kl.ePointInOctaveX, kl.ePointInOctaveY,
                                   kl.angle };
    for (float v : coordinates)
        if (!std::isfinite(v))
            CV_Error_(Error::StsOutOfRange,
                      ("computeLBD: KeyLine %d has a coordinate or angle that is not finite (start (%g, %g), end "
                       "(%g, %g), angle %g)",
                       i, kl.sPointInOctaveX, kl.sPointInOctaveY, kl.ePointInOctaveX, kl.ePointInOctaveY, kl.angle));
    if (kl.sPointInOctaveX != kl.startPointX || kl.sPointInOctaveY != kl.startPointY ||
        kl.ePointInOctaveX != kl.endPointX || kl.ePointInOctaveY != kl.endPointY)
        CV_Error_(Error::StsBadArg,
                  ("computeLBD: KeyLine %d of octave 0 has sPointInOctave (%g, %g) / ePointInOctave (%g, %g) other "
                   "than its startPoint (%g, %g) / endPoint (%g, %g); they are the same point at octave 0",
                   i, kl.sPointInOctaveX, kl.sPointInOctaveY, kl.ePointInOctaveX, kl.ePointInOctaveY,
                   kl.startPointX, kl.startPointY, kl.endPointX, kl.endPointY));
    for (int e = 0; e < 2; e++)
    {
        const float x = coordinates[2 * e], y = coordinates[2 * e + 1];
        if (x < -1.f || x > (float)size.width || y < -1.f || y > (float)size.height)
            CV_Error_(Error::StsOutOfRange,
                      ("computeLBD: KeyLine %d has its %s point (%g, %g) outside the %dx%d image (accepted: x in "
                       "[-1, %d], y in [-1, %d], the image and one pixel around it)",
                       i, e == 0 ? "start" : "end", x, y, size.width, size.height, size.width, size.height));
    }
    if (kl.sPointInOctaveX == kl.ePointInOctaveX && kl.sPointInOctaveY == kl.ePointInOctaveY)
        CV_Error_(Error::StsBadArg,
                  ("computeLBD: KeyLine %d has zero length (start = end = (%g, %g)): a line needs two distinct "
                   "endpoints", i, kl.sPointInOctaveX, kl.sPointInOctaveY));
    if (kl.numOfPixels < 1 || kl.numOfPixels > kMaxRegionLength)
        CV_Error_(Error::StsOutOfRange,
                  ("computeLBD: KeyLine %d has numOfPixels %d, the length of its support region in samples; "
                   "accepted: 1 to %d", i, kl.numOfPixels, kMaxRegionLength));

    LineRegion r;
    r.c = std::cos(kl.angle);
    r.s = std::sin(kl.angle);
    r.length = kl.numOfPixels;
    r.inside = false;  // known once its tiles are marked
    // The region's first sample: half its length back along the line and half its rows to the
    // line's left (image coordinates) from the midpoint, in the reference's float operations.
    const float halfLength = (float)((r.length - 1) / 2), halfRows = (float)((kRegionRows - 1) / 2);
    const float midX = (kl.sPointInOctaveX + kl.ePointInOctaveX) * 0.5f;
    const float midY = (kl.sPointInOctaveY + kl.ePointInOctaveY) * 0.5f;
    r.x0 = -r.c * halfLength + r.s * halfRows + midX;
    r.y0 = -r.s * halfLength - r.c * halfRows + midY;
    return r;
}

// Row i of out, 72 floats or (binary) 32 bytes, the description of line i.
void describeLine(const Workspace& ws, int i, Size size, RowSums& sums, Mat& out, bool binary)
{
    float features[kFloatsPerLine];
    sampleRegion(ws.regions[i], ws.gradient.data(), size, sums);
    uchar* row = out.ptr(i);
    if (!binary)
        describeRegion(sums, (float*)row);
    else
    {
        describeRegion(sums, features);
        binarise(features, row);
    }
}

// Checks the input, computes the gradient under the regions of the KeyLines and describes them
// into an N x 32 CV_8U (binary) or N x 72 CV_32F array.
void describeKeyLines(InputArray image, const std::vector<KeyLine>& keylines, OutputArray descriptors, bool binary)
{
    Workspace& ws = threadWorkspace();
    const Mat gray = toGray8U(image, "computeLBD");
    const Size size = gray.size();
    ws.regions.resize(keylines.size());
    for (size_t i = 0; i < keylines.size(); i++)
        ws.regions[i] = regionOf(keylines[i], (int)i, size);

    const int tilesX = (size.width + kTile - 1) / kTile, bandsY = (size.height + kTile - 1) / kTile;
    ws.tiles.assign((size_t)tilesX * bandsY, 0);
    for (LineRegion& r : ws.regions)
        r.inside = markRegionTiles(r, size, tilesX, ws.tiles);
    layChunks(ws.tiles, size, tilesX, ws.chunks);
    if (ws.gradient.size() < gray.total())
        ws.gradient.resize(gray.total());
    ws.gradientTasks.evenly((int)ws.chunks.size(), 1);
    runTasks(ws.gradientTasks, [&](int, const Range& chunks) {
        for (int k = chunks.start; k < chunks.end; k++)
            computeGradientChunk(gray, ws.chunks[k], ws.gradient.data());
    });

    // Tasks of consecutive lines of at least kSamplesPerTask samples, laid out from the lines alone.
    ws.lineTasks.byWeight((int)ws.regions.size(), kSamplesPerTask,
                          [&ws](int i) { return ws.regions[i].length * kSampledRows; });
    descriptors.create((int)keylines.size(), binary ? kDescriptorBytes : kFloatsPerLine, binary ? CV_8U : CV_32F);
    Mat out = descriptors.getMat();
    runTasks(ws.lineTasks, [&](int, const Range& lines) {
        RowSums sums;
        for (int i = lines.start; i < lines.end; i++)
            describeLine(ws, i, size, sums, out, binary);
    });
}

} // namespace

void lbdFloatDescriptors(InputArray image, const std::vector<KeyLine>& keylines, OutputArray descriptors)
{
    describeKeyLines(image, keylines, descriptors, false);
}

} // namespace lsda

void computeLBD(InputArray image, const std::vector<KeyLine>& keylines, OutputArray descriptors)
{
    CV_INSTRUMENT_REGION();
    lsda::describeKeyLines(image, keylines, descriptors, true);
}

void LSDAdvance::detectAndCompute(InputArray image, std::vector<KeyLine>& keylines, OutputArray descriptors,
                                  InputArray mask)
{
    CV_INSTRUMENT_REGION();
    const Mat gray = lsda::toGray8U(image, "LSDAdvance::detectAndCompute");
    detect(gray, keylines, mask);
    computeLBD(gray, keylines, descriptors);
}

}} // namespace cv::ximgproc

#endif
