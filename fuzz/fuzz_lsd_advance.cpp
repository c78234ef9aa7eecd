// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// libFuzzer target: arbitrary bytes -> an image of arbitrary size, type and layout, a parameter
// set (through read(), so that every persisted parameter takes part, with bad values too), a few
// frames of detect() (every output overload; the KeyLines described by computeLBD),
// processSegments() on arbitrary floats, computeLBD on arbitrary KeyLines, and the evaluation API.
// Bad input may only throw cv::Exception; anything else (another exception, a crash, a sanitizer
// report, a broken output invariant, computeLBD's descriptors other than line_descriptor's
// BinaryDescriptor::compute's) aborts and is a finding.
// Build and run: scripts/fuzz.sh.

#include "opencv2/lsd_advance.hpp"
#include "opencv2/lsd_advance/evaluation.hpp"
#include "opencv2/imgproc.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "opencv2/line_descriptor.hpp"
#endif

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::ximgproc;
using namespace cv::ximgproc::line_evaluation;

namespace {

void fail(const char* what, double value = 0)
{
    std::fprintf(stderr, "fuzz_lsd_advance: invariant broken: %s (%g)\n", what, value);
    std::abort();
}

// The persisted parameters as (map, key) pairs, map "" for the top level, read from what write()
// produces: new parameters take part without changing this file.
const std::vector<std::pair<std::string, std::string> >& parameterKeys()
{
    static const std::vector<std::pair<std::string, std::string> > keys = [] {
        FileStorage out("params.yml", FileStorage::WRITE | FileStorage::MEMORY);
        createLSDAdvance()->write(out);
        const String text = out.releaseAndGetString();
        FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
        std::vector<std::pair<std::string, std::string> > found;
        for (const FileNode& node : in.root())
            if (node.isMap())
                for (const FileNode& child : node)
                    found.push_back(std::make_pair(node.name(), child.name()));
            else
                found.push_back(std::make_pair(std::string(), node.name()));
        return found;
    }();
    return keys;
}

// A YAML value for a parameter: mostly small numbers near the valid ranges, sometimes special
// values or the wrong type.
std::string fuzzedValue(FuzzedDataProvider& in)
{
    switch (in.ConsumeIntegralInRange<int>(0, 9))
    {
    case 0: return ".nan";
    case 1: return in.ConsumeBool() ? ".inf" : "-.inf";
    case 2: return format("%d", in.ConsumeIntegral<int>());
    case 3: return format("%.17g", in.ConsumeFloatingPoint<double>());
    case 4: return in.ConsumeBool() ? "\"text\"" : "LENGTH_FILTER_COUNT_TRACKING";
    case 5: return "[ 1, 2 ]";
    case 6: return format("%d", in.ConsumeIntegralInRange<int>(-2, 12));
    default: return format("%.6g", in.ConsumeFloatingPointInRange<double>(-2.0, 120.0));
    }
}

// Image types: the accepted ones most of the time.
int fuzzedType(FuzzedDataProvider& in)
{
    static const int types[] = { CV_8UC1, CV_8UC1, CV_8UC3, CV_8UC4, CV_8UC2, CV_16UC1, CV_32FC1, CV_64FC1, CV_8SC1, CV_16SC3 };
    return types[in.ConsumeIntegralInRange<size_t>(0, sizeof(types) / sizeof(types[0]) - 1)];
}

Mat fuzzedImage(FuzzedDataProvider& in)
{
    const int rows = in.ConsumeIntegralInRange<int>(0, 160), cols = in.ConsumeIntegralInRange<int>(0, 160);
    const int type = fuzzedType(in);
    // Sometimes a non-continuous view into a larger image.
    const bool view = in.ConsumeBool();
    const int pad = view ? in.ConsumeIntegralInRange<int>(1, 7) : 0;
    Mat full(rows + 2 * pad, cols + 2 * pad, type);
    const int pattern = in.ConsumeIntegralInRange<int>(0, 3);
    if (pattern == 0)
        full.setTo(Scalar::all(in.ConsumeIntegral<uint8_t>()));
    else if (pattern == 1)
    {
        // Rectangles of fuzzed position and intensity on a fuzzed background: real edges.
        full.setTo(Scalar::all(in.ConsumeIntegral<uint8_t>()));
        for (int k = in.ConsumeIntegralInRange<int>(1, 6); k > 0; k--)
        {
            const Point a(in.ConsumeIntegralInRange<int>(-5, full.cols + 5), in.ConsumeIntegralInRange<int>(-5, full.rows + 5));
            const Point b(in.ConsumeIntegralInRange<int>(-5, full.cols + 5), in.ConsumeIntegralInRange<int>(-5, full.rows + 5));
            rectangle(full, a, b, Scalar::all(in.ConsumeIntegral<uint8_t>()), in.ConsumeBool() ? FILLED : 1);
        }
    }
    else if (pattern == 2 && !full.empty())
        RNG(in.ConsumeIntegral<uint32_t>()).fill(full, RNG::UNIFORM, 0, 256);
    else
    {
        // Raw bytes, repeated over the buffer.
        const std::vector<uint8_t> bytes = in.ConsumeBytes<uint8_t>(in.ConsumeIntegralInRange<size_t>(1, 512));
        if (!full.empty() && !bytes.empty())
            for (int y = 0; y < full.rows; y++)
            {
                uint8_t* row = full.ptr<uint8_t>(y);
                const size_t n = full.cols * full.elemSize();
                for (size_t i = 0; i < n; i++)
                    row[i] = bytes[(y * n + i) % bytes.size()];
            }
    }
    return view ? full(Rect(pad, pad, cols, rows)) : full;
}

// A mask for an image: none most of the time, else of the image's size (all zero, all set,
// rectangles of zeros, or random bits) and sometimes of another type or size.
Mat fuzzedMask(FuzzedDataProvider& in, const Size& imageSize)
{
    const int kind = in.ConsumeIntegralInRange<int>(0, 7);
    if (kind <= 2)
        return Mat();
    if (kind == 7)
    {
        const bool wrongType = in.ConsumeBool();
        const Size size = wrongType ? imageSize : Size(imageSize.width + in.ConsumeIntegralInRange<int>(1, 3), imageSize.height);
        return Mat(size, wrongType ? fuzzedType(in) : CV_8UC1, Scalar::all(1));
    }
    Mat mask(imageSize, CV_8UC1, Scalar(kind == 3 ? 0 : 255));
    if (kind == 5)
        for (int k = in.ConsumeIntegralInRange<int>(1, 6); k > 0; k--)
        {
            const Point a(in.ConsumeIntegralInRange<int>(-5, mask.cols + 5), in.ConsumeIntegralInRange<int>(-5, mask.rows + 5));
            const Point b(in.ConsumeIntegralInRange<int>(-5, mask.cols + 5), in.ConsumeIntegralInRange<int>(-5, mask.rows + 5));
            rectangle(mask, a, b, Scalar(0), FILLED);
        }
    else if (kind == 6 && !mask.empty())
        RNG(in.ConsumeIntegral<uint32_t>()).fill(mask, RNG::UNIFORM, 0, 2);
    return mask;
}

// clampedKeyLines: the lines are KeyLines' endpoints, which linesToKeyLines clamps as LSDDetector
// does (and which may then have no length).
void checkLines(const std::vector<Vec4f>& lines, const Size& image, const LSDAdvance& detector,
                bool clampedKeyLines = false)
{
    const LSDAdvanceStats stats = detector.getLastStats();
    if ((int)lines.size() != stats.outputSegments)
        fail("lines.size() == stats.outputSegments", (double)lines.size());
    if (stats.outputSegments > stats.baseSegments)
        fail("outputSegments <= baseSegments", stats.outputSegments);
    if (!(stats.alpha >= 0.8 && stats.alpha <= 1.2))
        fail("alpha in [0.8, 1.2]", stats.alpha);
    if (!(std::isfinite(stats.minLength) && stats.minLength >= 0))
        fail("finite minLength >= 0", stats.minLength);
    // Every segment lies inside the image domain [-0.5, W-0.5] x [-0.5, H-0.5] and has a length.
    for (const Vec4f& l : lines)
    {
        for (int i = 0; i < 4; i++)
        {
            const double extent = (i % 2 == 0 ? image.width : image.height) - 0.5;
            if (!std::isfinite(l[i]) || l[i] < -0.5 || l[i] > extent)
                fail("coordinates inside the image domain", l[i]);
        }
        if (!clampedKeyLines && l[0] == l[2] && l[1] == l[3])
            fail("segments of positive length", l[0]);
    }
    // Each line has its sources, distinct base segments.
    std::vector<std::vector<int> > sources;
    detector.getLastSources(sources);
    if (sources.size() != lines.size())
        fail("a list of sources per line", (double)sources.size());
    std::vector<char> used(stats.baseSegments, 0);
    for (const std::vector<int>& list : sources)
    {
        if (list.empty())
            fail("every line has a source");
        for (int i : list)
        {
            if (i < 0 || i >= stats.baseSegments || used[i])
                fail("sources are distinct base segments", i);
            used[i] = 1;
        }
    }
}

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
// computeLBD of accepted input: the descriptors of line_descriptor's BinaryDescriptor::compute.
void checkDescriptors(const Mat& image, const std::vector<line_descriptor::KeyLine>& keylines)
{
    Mat descriptors;
    computeLBD(image, keylines, descriptors);
    if (descriptors.rows != (int)keylines.size() || descriptors.cols != 32 || descriptors.type() != CV_8UC1)
        fail("computeLBD gives N x 32 CV_8U", descriptors.rows);
    if (keylines.empty())
        return;
    std::vector<line_descriptor::KeyLine> numbered = keylines;  // one class_id per KeyLine
    for (size_t i = 0; i < numbered.size(); i++)
        numbered[i].class_id = (int)i;
    Mat expected;
    line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(image, numbered, expected);
    if (norm(descriptors, expected, NORM_HAMMING) != 0)
        fail("computeLBD's descriptors are BinaryDescriptor::compute's", norm(descriptors, expected, NORM_HAMMING));
}

// computeLBD on KeyLines of fuzzed fields: valid ones (KeyLines of segments in and around the
// image) and broken ones (another octave, non-finite, outside, of zero length, a support length
// out of range, octave copies elsewhere). Exactly the broken ones and images of another type throw.
void fuzzLbd(FuzzedDataProvider& in)
{
    const Mat image = fuzzedImage(in);
    const Size size = image.size();
    const int type = image.type();
    bool valid = !image.empty() && (type == CV_8UC1 || type == CV_8UC3 || type == CV_8UC4);
    std::vector<line_descriptor::KeyLine> keylines;
    for (size_t k = in.ConsumeIntegralInRange<size_t>(0, 12); k > 0 && !size.empty(); k--)
    {
        const auto coordinate = [&](int side) { return in.ConsumeFloatingPointInRange<float>(-1.f, (float)side); };
        const Vec4f s(coordinate(size.width), coordinate(size.height), coordinate(size.width), coordinate(size.height));
        std::vector<line_descriptor::KeyLine> one;
        linesToKeyLines(std::vector<Vec4f>(1, s), size, one);
        line_descriptor::KeyLine kl = one[0];
        kl.startPointX = kl.sPointInOctaveX = s[0];  // the accepted box: [-1, W] x [-1, H]
        kl.startPointY = kl.sPointInOctaveY = s[1];
        const float special[] = { std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                                  -1.5f, (float)size.width + 1.5f, 1e9f };
        const float bad = special[in.ConsumeIntegralInRange<int>(0, 4)];
        switch (in.ConsumeIntegralInRange<int>(0, 15))
        {
        case 0: kl.octave = in.ConsumeIntegralInRange<int>(1, 5); break;
        case 1: kl.endPointX = kl.ePointInOctaveX = bad; break;
        case 2: kl.startPointY = kl.sPointInOctaveY = bad; break;
        case 3: kl.angle = in.ConsumeBool() ? special[in.ConsumeIntegralInRange<int>(0, 1)] : in.ConsumeFloatingPoint<float>(); break;
        case 4: kl.numOfPixels = in.ConsumeBool() ? in.ConsumeIntegralInRange<int>(-5, 0) : in.ConsumeIntegral<int>(); break;
        case 5:
            kl.endPointX = kl.ePointInOctaveX = kl.startPointX;
            kl.endPointY = kl.ePointInOctaveY = kl.startPointY;
            break;
        case 6: kl.sPointInOctaveX += 1.f; break;
        case 7: kl.numOfPixels = in.ConsumeIntegralInRange<int>(1, 2048); break;
        case 8: kl.angle = in.ConsumeFloatingPointInRange<float>(-10.f, 10.f); break;
        default: break;
        }
        const float fields[] = { kl.startPointX, kl.startPointY, kl.endPointX, kl.endPointY, kl.angle };
        bool ok = kl.octave == 0 && kl.numOfPixels >= 1 && kl.numOfPixels <= 32767 &&
                  kl.sPointInOctaveX == kl.startPointX && kl.sPointInOctaveY == kl.startPointY &&
                  kl.ePointInOctaveX == kl.endPointX && kl.ePointInOctaveY == kl.endPointY &&
                  !(kl.startPointX == kl.endPointX && kl.startPointY == kl.endPointY);
        for (int i = 0; i < 5; i++)
            ok = ok && std::isfinite(fields[i]) &&
                 (i == 4 || (fields[i] >= -1.f && fields[i] <= (float)(i % 2 == 0 ? size.width : size.height)));
        valid = valid && ok;
        keylines.push_back(kl);
    }
    try
    {
        if (valid)
            checkDescriptors(image, keylines);
        else
        {
            Mat descriptors;
            computeLBD(image, keylines, descriptors);
            fail("computeLBD accepted a bad image or KeyLine");
        }
    }
    catch (const cv::Exception&)
    {
        if (valid)
            fail("computeLBD rejected valid input", (double)keylines.size());
    }
}
#endif

void fuzzDetector(FuzzedDataProvider& in)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    // Parameters through read(): valid, out of range, non-finite or of the wrong type, by name
    // for the enumerated ones.
    std::string yaml = "%YAML:1.0\n---\n";
    for (const auto& key : parameterKeys())
        if (in.ConsumeIntegralInRange<int>(0, 3) == 0)
            yaml += (key.first.empty() ? key.second : key.first + ": { " + key.second) + ": " + fuzzedValue(in) +
                    (key.first.empty() ? "\n" : " }\n");
    try
    {
        FileStorage fs(yaml, FileStorage::READ | FileStorage::MEMORY);
        detector->read(fs.root());
    }
    catch (const cv::Exception&)
    {
    }

    const int frames = in.ConsumeIntegralInRange<int>(1, 4);
    for (int f = 0; f < frames && in.remaining_bytes() > 0; f++)
    {
        const Mat image = fuzzedImage(in);
        const Mat mask = fuzzedMask(in, image.size());
        const bool maskValid = mask.empty() || (mask.type() == CV_8UC1 && mask.size() == image.size());
        const int overload = in.ConsumeIntegralInRange<int>(0, 2);
        try
        {
            std::vector<Vec4f> lines;
            if (overload == 0)
                detector->detect(image, lines, mask);
            else if (overload == 1)
            {
                Mat out;
                detector->detect(image, out, mask);
                if (!out.empty() && (out.type() != CV_32FC4 || out.cols != 1))
                    fail("Mat output is N x 1 CV_32FC4", out.type());
                if (!out.empty())
                    out.copyTo(lines);
            }
            else
            {
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
                std::vector<line_descriptor::KeyLine> keylines;
                detector->detect(image, keylines, mask);
                for (const line_descriptor::KeyLine& k : keylines)
                    lines.push_back(Vec4f(k.startPointX, k.startPointY, k.endPointX, k.endPointY));
                // The detector's KeyLines are computeLBD's to describe, but for a segment that
                // the clamping made a point.
                keylines.erase(std::remove_if(keylines.begin(), keylines.end(), [](const line_descriptor::KeyLine& k) {
                                   return k.startPointX == k.endPointX && k.startPointY == k.endPointY;
                               }),
                               keylines.end());
                checkDescriptors(image, keylines);
#else
                detector->detect(image, lines, mask);
#endif
            }
            if (!maskValid)
                fail("a mask of another type or size was accepted");
            checkLines(lines, image.size(), *detector, overload == 2);
            if (!mask.empty() && countNonZero(mask) == 0 && !lines.empty())
                fail("an all-zero mask gave lines", (double)lines.size());
        }
        catch (const cv::Exception&)
        {
            const int type = image.type();
            if (!image.empty() && (type == CV_8UC1 || type == CV_8UC3 || type == CV_8UC4) && maskValid)
                fail("an accepted image was rejected", type);
        }
    }

    // processSegments on arbitrary floats: anything non-finite or beyond 1e7 throws.
    const size_t count = in.ConsumeIntegralInRange<size_t>(0, 64);
    std::vector<Vec4f> segments;
    bool valid = true;
    for (size_t k = 0; k < count; k++)
    {
        Vec4f s;
        for (int i = 0; i < 4; i++)
        {
            s[i] = in.ConsumeBool() ? in.ConsumeFloatingPoint<float>() : in.ConsumeFloatingPointInRange<float>(-5.f, 200.f);
            valid = valid && std::isfinite(s[i]) && std::abs(s[i]) < 1e7f;
        }
        segments.push_back(s);
    }
    // Clipped to a fuzzed image size, or not clipped.
    const Size imageSize = in.ConsumeBool() ? Size() : Size(in.ConsumeIntegralInRange<int>(1, 300),
                                                              in.ConsumeIntegralInRange<int>(1, 300));
    // Sometimes with a mask of that size (an image size of 0 x 0 takes the mask's, of 1 to 300).
    const Size maskSize = imageSize.empty() ? Size(in.ConsumeIntegralInRange<int>(1, 300), in.ConsumeIntegralInRange<int>(1, 300))
                                            : imageSize;
    const Mat mask = in.ConsumeBool() ? Mat() : fuzzedMask(in, maskSize);
    valid = valid && (mask.empty() || (mask.type() == CV_8UC1 && (imageSize.empty() || mask.size() == imageSize)));
    try
    {
        std::vector<Vec4f> lines;
        detector->processSegments(segments, lines, imageSize, mask);
        const LSDAdvanceStats stats = detector->getLastStats();
        if (!valid)
            fail("invalid segments were accepted");
        // The cut at a mask may make several pieces of a segment.
        if ((int)lines.size() != stats.outputSegments || (mask.empty() && stats.outputSegments > (int)segments.size()))
            fail("processSegments output count", (double)lines.size());
        for (const Vec4f& l : lines)
            for (int i = 0; i < 4; i++)
                if (!std::isfinite(l[i]))
                    fail("finite processSegments output", l[i]);
        if (!imageSize.empty() || !mask.empty())
            checkLines(lines, mask.empty() ? imageSize : mask.size(), *detector);
    }
    catch (const cv::Exception&)
    {
        if (valid)
            fail("valid segments were rejected");
    }
}

void fuzzEvaluation(FuzzedDataProvider& in)
{
    std::vector<Vec4f> detections, groundTruth;
    bool bounded = true;
    for (std::vector<Vec4f>* set : { &detections, &groundTruth })
        for (size_t k = in.ConsumeIntegralInRange<size_t>(0, 16); k > 0; k--)
        {
            Vec4f s;
            for (int i = 0; i < 4; i++)
            {
                s[i] = in.ConsumeBool() ? in.ConsumeFloatingPoint<float>() : in.ConsumeFloatingPointInRange<float>(0.f, 64.f);
                bounded = bounded && std::isfinite(s[i]) && std::abs(s[i]) <= 1e6f;
            }
            set->push_back(s);
        }
    StructuralMatchParams params;
    if (in.ConsumeBool())
    {
        params.maxDistance = in.ConsumeFloatingPoint<double>();
        params.maxAngle = in.ConsumeFloatingPoint<double>();
        params.minCoverage = in.ConsumeFloatingPoint<double>();
        params.offset = in.ConsumeFloatingPointInRange<double>(-1e6, 1e6);
    }
    try
    {
        const StructuralScore s = evaluateStructural(detections, groundTruth, params);
        // With bounded finite input the scores are ratios of lengths.
        if (bounded && !(s.precision >= 0 && s.precision <= 1 + 1e-9 && s.recall >= 0 && s.recall <= 1 + 1e-9))
            fail("precision and recall in [0, 1]", s.precision);
        if (s.found > s.groundTruthCount)
            fail("found <= groundTruthCount", s.found);
    }
    catch (const cv::Exception&)
    {
    }
    const double share = longSegmentShare(detections, in.ConsumeFloatingPointInRange<double>(0.0, 100.0));
    if (!(share >= 0 && share <= 1))
        fail("longSegmentShare in [0, 1]", share);
    const double f = fScore(in.ConsumeProbability<double>(), in.ConsumeProbability<double>());
    if (!(f >= 0 && f <= 1))
        fail("fScore in [0, 1]", f);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    // OpenCV's own threads are not instrumented; keep every call on this one.
    static const bool singleThread = (setNumThreads(0), true);
    (void)singleThread;
    FuzzedDataProvider in(data, size);
    if (in.ConsumeBool())
        fuzzEvaluation(in);
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0)
    {
        fuzzLbd(in);
        return 0;
    }
#endif
    fuzzDetector(in);
    return 0;
}
