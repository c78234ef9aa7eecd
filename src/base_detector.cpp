// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, the base detectors: OpenCV's LSD (from imgproc or ximgproc, opencv_lsd.hpp),
// FastLineDetector and EDLines (EdgeDrawing), used as they are, and the module's own LSD
// (fast_lsd/fast_lsd.cpp).

#include "precomp.hpp"
#include "fast_lsd/fast_lsd.hpp"
#include "opencv2/ximgproc/edge_drawing.hpp"
#include "opencv2/ximgproc/fast_line_detector.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

namespace {

class LsdBase CV_FINAL : public BaseSegmentDetector
{
public:
    explicit LsdBase(const LSDAdvance::LSDParams& p)
        : lsd(createOpenCVLineSegmentDetector(p.refine, p.scale, p.sigmaScale, p.quant, p.angleTolerance,
                                              p.logEps, p.densityThreshold, p.numBins)),
          scale(p.scale), fullScaleSmoothing(p.fullScaleSigma, p.fullScaleSmoothing)
    {}
    void detect(const Mat& gray, std::vector<Vec4f>& segments) CV_OVERRIDE
    {
        // LSD's resize throws on an image that scales to no pixel; such an image has no segment.
        if (saturate_cast<int>(gray.cols * scale) <= 0 || saturate_cast<int>(gray.rows * scale) <= 0)
            segments.clear();
        else if (scale == 1.0 && !fullScaleSmoothing.isIdentity())
            lsd->detect(fullScaleSmoothing.apply(gray), segments);
        else if (scale != 1.0 && gray.isSubmatrix())
            lsd->detect(gray.clone(), segments);  // LSD's Gaussian would read the pixels around the view
        else
            lsd->detect(gray, segments);
        toFullResolution(segments, scale);
    }

private:
    Ptr<OpenCVLineSegmentDetector> lsd;
    double scale;
    FullScaleSmoothing fullScaleSmoothing;
};

class FastLsdBase CV_FINAL : public BaseSegmentDetector
{
public:
    explicit FastLsdBase(const LSDAdvance::LSDParams& p) : lsd(p), scale(p.scale) {}
    void detect(const Mat& gray, std::vector<Vec4f>& segments) CV_OVERRIDE
    {
        lsd.detect(gray, segments);
        toFullResolution(segments, scale);
    }

protected:
    void detectReadingMask(const Mat& gray, const Mat& mask, std::vector<Vec4f>& segments) CV_OVERRIDE
    {
        lsd.detect(gray, segments, mask);
        toFullResolution(segments, scale);
    }

private:
    FastLsd lsd;
    double scale;
};

// FastLineDetector orients its segments brighter side on the left, like LSD.
class FldBase CV_FINAL : public BaseSegmentDetector
{
public:
    explicit FldBase(const LSDAdvance::FLDParams& p)
        : fld(createFastLineDetector(p.lengthThreshold, (float)p.distanceThreshold, p.cannyThreshold1,
                                     p.cannyThreshold2, p.cannyApertureSize, p.doMerge))
    {}
    void detect(const Mat& gray, std::vector<Vec4f>& segments) CV_OVERRIDE
    {
        // FastLineDetector blanks a 6 x 6 corner of its edge map and fails on a smaller image;
        // such an image has no segment.
        if (gray.cols < kMinSide || gray.rows < kMinSide)
            segments.clear();
        else
            fld->detect(gray, segments);
    }

private:
    static constexpr int kMinSide = 6;
    Ptr<FastLineDetector> fld;
};

// EDLines orients a segment along the edge it traced, either way.
class EdLinesBase CV_FINAL : public BaseSegmentDetector
{
public:
    explicit EdLinesBase(const EdgeDrawing::Params& p) : ed(createEdgeDrawing()) { ed->setParams(p); }
    void detect(const Mat& gray, std::vector<Vec4f>& segments) CV_OVERRIDE
    {
        ed->detectEdges(gray);
        ed->detectLines(segments);
        orientBrighterLeft(gray, segments);
    }

private:
    Ptr<EdgeDrawing> ed;
};

} // namespace

Ptr<BaseSegmentDetector> createBaseDetector(int kind, const LSDAdvance::LSDParams& lsd,
                                            const LSDAdvance::FLDParams& fld, const EdgeDrawing::Params& edLines)
{
    switch (kind)
    {
    case LSDAdvance::BASE_LSD:
        return makePtr<LsdBase>(lsd);
    case LSDAdvance::BASE_FLD:
        return makePtr<FldBase>(fld);
    case LSDAdvance::BASE_EDLINES:
        return makePtr<EdLinesBase>(edLines);
    case LSDAdvance::BASE_FAST_LSD:
        return makePtr<FastLsdBase>(lsd);
    default:
        CV_Error_(Error::StsOutOfRange, ("unknown base detector %d", kind));
    }
}

void toFullResolution(std::vector<Vec4f>& segments, double scale)
{
    if (scale == 1.0)
        return;
    // resize() centres pixel i of the scaled image at (i + 0.5) / scale - 0.5 of the full one.
    const float shift = (float)(0.5 / scale - 0.5);
    for (Vec4f& s : segments)
        s += Vec4f::all(shift);
}

void orientBrighterLeft(const Mat& gray, std::vector<Vec4f>& segments)
{
    CV_CheckTypeEQ(gray.type(), CV_8UC1, "orientBrighterLeft samples a gray image");
    constexpr double kSide = 2.0;  // px either side: off the edge for LSD's and EDLines' placements
    const Rect inside(0, 0, gray.cols, gray.rows);
    for (Vec4f& s : segments)
    {
        const Point2d a(s[0], s[1]), d(s[2] - s[0], s[3] - s[1]);
        const double len = std::sqrt(d.dot(d));
        if (len <= 0)
            continue;
        const Point2d left = Point2d(d.y, -d.x) * (kSide / len);  // left of d with y pointing down
        int balance = 0;
        for (int k = 0; k < 5; k++)
        {
            const Point2d m = a + d * (0.1 + 0.2 * k);
            const Point l(cvRound(m.x + left.x), cvRound(m.y + left.y));
            const Point r(cvRound(m.x - left.x), cvRound(m.y - left.y));
            if (inside.contains(l) && inside.contains(r))
                balance += (int)gray.at<uchar>(l) - (int)gray.at<uchar>(r);
        }
        if (balance < 0)
            s = Vec4f(s[2], s[3], s[0], s[1]);
    }
}

}}} // namespace cv::ximgproc::lsda
