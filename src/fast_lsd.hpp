// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 0, BASE_FAST_LSD: the module's own implementation of the LSD algorithm (Grompone von
// Gioi, Jakubowicz, Morel, Randall, "LSD: a Line Segment Detector", IPOL 2012), written for
// speed from the published description. OpenCV's LineSegmentDetector is its test oracle.

#ifndef OPENCV_LSD_ADVANCE_FAST_LSD_HPP
#define OPENCV_LSD_ADVANCE_FAST_LSD_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//! The LSD algorithm with OpenCV's LineSegmentDetector parameters and output convention (segments
//! (x1, y1, x2, y2), pixel centres at integer coordinates, brighter side on the left). Every buffer
//! is kept by the object and reused, so that a sequence of frames of one size allocates nothing
//! once warm. Not safe to call from two threads at once.
class FastLsd
{
public:
    explicit FastLsd(const LSDAdvance::LSDParams& params);
    //! Segments of a CV_8UC1 image.
    void detect(const Mat& gray, std::vector<Vec4f>& segments);

private:
    //! A rectangle approximating a region (IPOL's "rect"): the segment (x1, y1)-(x2, y2) with its
    //! centre, unit direction, width, and the angle tolerance (radians) and probability used to
    //! validate it.
    struct Rect
    {
        double x1, y1, x2, y2, width, x, y, dx, dy, prec, p;
    };

    class GradientRows;
    void computeGradient(const Mat& image);
    void orderPixels();
    //! cos(tolerance) in the scale of the level-line vectors: growRegion's argument.
    static float alignmentLimit(double tolerance);
    void growRegion(int seed, float cosUnit);
    template <bool acute> void growRegionFrom(int seed, float cosUnit);
    void regionToRect(double prec, double p, Rect& rect);
    bool refineRegion(Rect& rect);
    bool shrinkRegionRadius(Rect& rect, double density);
    double rectLogNfa(const Rect& rect) const;
    double improveRect(Rect& rect) const;
    double logNfa(int n, int k, double p) const;
    double logFactorial(int n) const;

    // Parameters (LSD's), resolved to what the loops use.
    int refine;
    double scale, sigmaScale, quant, angleTolerance, logEps, densityThreshold;
    int numBins;

    // Per-frame state, sized for the largest frame seen (row stride = width + 1; one border row
    // and column of "undefined" pixels above and left, so that the 8 neighbours of any pixel with
    // a defined gradient are inside the buffers).
    Mat blurred, scaled, analysed;  //!< the image smoothed, at the analysis scale; a header of the one analysed
    int width = 0, height = 0, stride = 0;
    int threshold = 0;              //!< a pixel's gradient is defined when gx^2 + gy^2 > threshold
    //! Unit level-line vector (-gy, gx) / |g| of each free pixel, times kUnit; (0, 0) for a pixel
    //! without a defined gradient or already in a region.
    std::vector<Vec2s> level;
    std::vector<float> gradNorm;    //!< gradient norm |g| / 2 per pixel
    std::vector<int> rowMaxNorm2, rowDefined;
    std::vector<int> binStart;
    std::vector<int> ordered;      //!< defined pixels, highest bin first
    int definedCount = 0;
    double logNT = 0;

    // The current region: the buffer indices of its pixels (regionSize of them; the seed first;
    // before the regions, the defined pixels in raster order), their vectors (which level no
    // longer holds), their coordinates (filled by regionToRect), and the sum of their vectors.
    std::vector<int> regionIndex;
    std::vector<Vec2s> regionVector;
    std::vector<Point> regionPixel;
    int regionSize = 0;
    Point2f regionSum;
    mutable std::vector<double> logFactorials;  //!< log(n!) for n < size(), grown on demand
};

}}} // namespace cv::ximgproc::lsda

#endif
