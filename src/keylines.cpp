// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Output as line_descriptor KeyLines, so that LBD (BinaryDescriptor) and its matcher take
// LSDAdvance's segments as they take LSDDetector's.

#include "precomp.hpp"

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

namespace cv {
namespace ximgproc {

using line_descriptor::KeyLine;

namespace {

// LSDDetector's bounds: below 0 -> 0, at or beyond the side -> side - 1 (so a coordinate in
// [side - 1, side) is kept as it is).
float clampedCoordinate(float v, int side)
{
    return v < 0 ? 0.f : (v >= (float)side ? (float)(side - 1) : v);
}

// The digital line LBD samples, counted the way LSDDetector counts it: its endpoints rounded to
// pixels, the line clipped to the image. A line along the last column or row whose endpoints both
// round to just outside the image would count 0, a region LBD cannot sample: it counts the pixels
// of the line between the nearest pixels inside instead.
int supportLength(Size imageSize, float x1, float y1, float x2, float y2)
{
    const int count = LineIterator(imageSize, Point2f(x1, y1), Point2f(x2, y2)).count;
    if (count > 0)
        return count;
    const auto inside = [](float v, int side) { return std::min(cvRound(v), side - 1); };
    return LineIterator(imageSize, Point(inside(x1, imageSize.width), inside(y1, imageSize.height)),
                        Point(inside(x2, imageSize.width), inside(y2, imageSize.height))).count;
}

} // namespace

void LSDAdvance::detect(InputArray image, std::vector<KeyLine>& keylines, InputArray mask)
{
    CV_INSTRUMENT_REGION();
    std::vector<Vec4f> lines;
    detect(image, lines, mask);
    linesToKeyLines(lines, image.size(), keylines);
    std::vector<float> responses;
    getLastResponses(responses);  // detect() computed them: its order
    CV_Assert(responses.size() == keylines.size());
    for (size_t i = 0; i < keylines.size(); i++)
        keylines[i].response = responses[i];
}

void keepStrongestKeyLines(const std::vector<KeyLine>& keylines, int maxLines, std::vector<KeyLine>& kept)
{
    CV_INSTRUMENT_REGION();
    CV_CheckGE(maxLines, 0, "keepStrongestKeyLines: maxLines must be 0 (all) or positive");
    std::vector<float> responses(keylines.size());
    std::vector<int> order(keylines.size());
    for (size_t i = 0; i < keylines.size(); i++)
    {
        responses[i] = keylines[i].response;
        order[i] = (int)i;
    }
    lsda::strongestFirst(responses, maxLines, order);
    std::vector<KeyLine> result(order.size());  // keylines may be kept itself
    for (size_t j = 0; j < order.size(); j++)
    {
        result[j] = keylines[order[j]];
        result[j].class_id = (int)j;
    }
    kept.swap(result);
}

void linesToKeyLines(InputArray linesIn, Size imageSize, std::vector<KeyLine>& keylines)
{
    CV_INSTRUMENT_REGION();
    CV_CheckGE(imageSize.width, 1, "linesToKeyLines: imageSize must be at least 1 x 1 px");
    CV_CheckGE(imageSize.height, 1, "linesToKeyLines: imageSize must be at least 1 x 1 px");
    const std::vector<Vec4f> lines = lsda::toSegments(linesIn, "linesToKeyLines: lines");
    if (!lines.empty() && !checkRange(Mat(lines), true))
        CV_Error(Error::StsOutOfRange, "linesToKeyLines: segment coordinates must be finite");

    const float longerSide = (float)std::max(imageSize.width, imageSize.height);
    keylines.clear();
    keylines.reserve(lines.size());
    for (size_t i = 0; i < lines.size(); i++)
    {
        const float x1 = clampedCoordinate(lines[i][0], imageSize.width);
        const float y1 = clampedCoordinate(lines[i][1], imageSize.height);
        const float x2 = clampedCoordinate(lines[i][2], imageSize.width);
        const float y2 = clampedCoordinate(lines[i][3], imageSize.height);
        KeyLine kl;
        kl.startPointX = kl.sPointInOctaveX = x1;
        kl.startPointY = kl.sPointInOctaveY = y1;
        kl.endPointX = kl.ePointInOctaveX = x2;
        kl.endPointY = kl.ePointInOctaveY = y2;
        kl.lineLength = (float)std::sqrt((double)(x2 - x1) * (x2 - x1) + (double)(y2 - y1) * (y2 - y1));
        kl.numOfPixels = supportLength(imageSize, x1, y1, x2, y2);
        kl.angle = std::atan2(y2 - y1, x2 - x1);
        kl.class_id = (int)i;
        kl.octave = 0;
        kl.size = (x2 - x1) * (y2 - y1);
        kl.response = kl.lineLength / longerSide;
        kl.pt = Point2f((x1 + x2) / 2, (y1 + y2) / 2);
        keylines.push_back(kl);
    }
}

void keyLinesToLines(const std::vector<KeyLine>& keylines, OutputArray lines)
{
    CV_INSTRUMENT_REGION();
    std::vector<Vec4f> segments;
    segments.reserve(keylines.size());
    for (const KeyLine& kl : keylines)
        segments.push_back(Vec4f(kl.startPointX, kl.startPointY, kl.endPointX, kl.endPointY));
    Mat(segments).copyTo(lines);
}

}} // namespace cv::ximgproc

#endif
