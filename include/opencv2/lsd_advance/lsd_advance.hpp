// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_LSD_ADVANCE_HPP
#define OPENCV_LSD_ADVANCE_LSD_ADVANCE_HPP

#include "opencv2/core.hpp"
#include "opencv2/ximgproc/edge_drawing.hpp"  // EdgeDrawing::Params: the parameters of BASE_EDLINES

#include <vector>

namespace cv {

//! @cond IGNORED
// LSDAdvance::detect(InputArray, std::vector<KeyLine>&) names KeyLine only: this header does not
// include line_descriptor (opencv2/lsd_advance/keylines.hpp does), so that it compiles with or
// without it, before or after a client's own copy of it.
namespace line_descriptor {
struct KeyLine;
}
//! @endcond

namespace ximgproc {

//! @addtogroup lsd_advance
//! @{

/** @brief Statistics of the last LSDAdvance::detect or LSDAdvance::processSegments call: segments
after each stage, and wall-clock times (stage 0's includes the conversion to gray). */
struct CV_EXPORTS_W_SIMPLE LSDAdvanceStats
{
    CV_WRAP LSDAdvanceStats()
        : baseSegments(0), mergedSegments(0), filteredSegments(0), mergeGroups(0), outputSegments(0),
          minLength(0), minResponse(0), alpha(1), baseMs(0), filterMs(0), groupingMs(0), mergingMs(0),
          selectionMs(0), frameInSequence(0)
    {}

    CV_PROP_RW int baseSegments;     //!< segments returned by the base detector (stage 0)
    CV_PROP_RW int mergedSegments;   //!< segments after merging (stage 3)
    CV_PROP_RW int filteredSegments; //!< segments that survived the length filter (stage 1)
    CV_PROP_RW int mergeGroups;      //!< endpoint groups holding two or more segments (stage 2)
    CV_PROP_RW int outputSegments;   //!< segments returned (after clipping to the image and the selection: Params::minLineLength, Params::minLineLengthRatio, Params::maxLines)
    CV_PROP_RW double minLength;     //!< length threshold of stage 1, in pixels (0 when the filter is off)
    CV_PROP_RW double minResponse;   //!< response threshold of stage 1's strong segments (0 unless Params::keepStrongSegments acts)
    CV_PROP_RW double alpha;         //!< inter-frame factor used by stage 1, in [0.8, 1.2] (1 when the filter is off)
    CV_PROP_RW double baseMs;        //!< time of stage 0, ms
    CV_PROP_RW double filterMs;      //!< time of stage 1, ms
    CV_PROP_RW double groupingMs;    //!< time of stage 2, ms
    CV_PROP_RW double mergingMs;     //!< time of stage 3, ms
    CV_PROP_RW double selectionMs;   //!< time of the selection (minimum length, responses, order, budget), ms
    /** frames of the current sequence before this call: 0 on the first call after createLSDAdvance(),
    reset(), read() or a setter, then 1, 2, ... An inter-frame LengthFilterMode (PRESET_SEQUENCE) acts
    from frame 2 on: a detector made anew for each frame always reports 0 and never leaves alpha = 1. */
    CV_PROP_RW int frameInSequence;
};

/** @brief Line segment detector that returns fewer, longer segments than LSD (@cite Guan2026).

The segments of a base detector (BaseDetector: the LSD algorithm @cite Rafael12 by default,
FastLineDetector @cite Lee14 or EDLines @cite akinlar2011edlines) pass three stages:
1. **length filter**: segments shorter than a threshold computed from the mean and standard
   deviation of the frame's segment lengths are dropped (LengthFilterMode, LengthThresholdRule),
   unless strong (Params::keepStrongSegments);
2. **grouping**: segments of the same (or a neighbouring) angle bin whose endpoints are close form
   groups (AngleBinning);
3. **merging**: in each group, pieces are fused into longer segments, best
   direction/proximity/length score first, behind a perpendicular gate (MergeStrategy).

Params lists every parameter with its unit, range and default; createLSDAdvance() takes a Preset.
The formulas, where and why we differ from the paper, and the measurements behind the defaults
are in doc/algorithm.md and doc/parameter_sweep.md.

__Orientation.__ Like LSD, each segment (x1, y1, x2, y2) points from its start to its end so
that, on the image as displayed (y pointing down), the brighter side is on its left. Fused
segments keep the orientation of the longer piece.

__Coordinates.__ Pixels; pixel (i, j) is centred at (i, j): the image covers [-0.5, W-0.5] x [-0.5, H-0.5].

__Input.__ 8-bit images with 1 channel (gray), 3 (BGR) or 4 (BGRA, alpha ignored), of any size
and layout (ROI views, UMat). Other types and empty images throw cv::Exception naming the type
received and the accepted ones. A rejected call (image, segments, setter, read()) changes nothing.

__Output.__ N x 1 CV_32FC4 (std::vector<cv::Vec4f>), finite, inside the image: a segment reaching
past it is clipped along its own line, keeping its direction, and dropped when nothing is left.

__Order and selection.__ detect() returns its lines strongest first: by decreasing response
(computeLineResponses(), the KeyLine::response of detect(InputArray, std::vector<KeyLine>&); equal
responses keep the stages' order). processSegments(), which has no image, returns them longest
first. With Params::lineOrder LINE_ORDER_ACROSS_DIRECTIONS, that order is taken across bins of
direction (Params::directionBins) in each cell of a grid on the image (Params::gridCells) instead:
the strongest of each bin first, then the second of each, and so on. After the
clipping, lines shorter than the larger of Params::minLineLength and Params::minLineLengthRatio
times min(W, H) are dropped, then the first Params::maxLines are kept: a front end's budget (all
three off by default, where the lines are the same set as without them); in either order the
first N lines are the selection of a budget of N. The responses are computed only when something
uses them: detect() always does (it orders by them; getLastResponses() returns them), after the
minimum length, on the lines that pass it; processSegments() never.

__Mask.__ detect() and processSegments() take an optional mask: CV_8UC1 of the image's size,
zero where the image must be ignored (a car's hood, the robot's body, dynamic objects); another
type or size throws cv::Exception naming what was received and what is accepted. Stricter than
cv::line_descriptor::LSDDetector's test of the endpoints alone, no returned segment passes over a
masked-out pixel, and no segment grows from or into masked-out pixels:
- every base's segments are cut at the mask: each segment's part inside the image is sampled at
  most 1 px apart (from one end to the other, both included; each sample reads the mask at its
  nearest pixel), and each run of two or more samples on the mask is kept as a piece, from its
  first sample to its last, in the segment's orientation (a segment wholly on the mask is kept
  as it is; the pieces then pass stages 1-3 like any base segment);
- BASE_FAST_LSD also reads the mask in its gradient pass: a pixel whose 2x2 gradient reads a
  masked-out pixel has no defined gradient, so it neither seeds a region nor joins one (nor counts
  as aligned in a rectangle), and a region never grows across a masked-out area. Below
  LSDParams::scale 1 the mask is sub-sampled as the image is, each analysed pixel taking the mask
  at the full-resolution pixel nearest its centre; the Gaussian before the sub-sampling still
  mixes in up to 3 sigma of the pixels beside the mask (the cut then removes what crosses it);
- stage 3 fuses two segments only when the gap between them along the line they fuse into is on
  the mask, sampled as above: no merged line bridges a masked-out area.

An all-zero mask gives no segment; a mask that is all non-zero gives the lines of no mask.

__State.__ By default detect() is stateless, like LSD. The inter-frame modes of LengthFilterMode
(PRESET_SEQUENCE) make consecutive calls a sequence; reset() and every setter start a new one. A
sequence lives in one detector object: create it once and call it on every frame
(LSDAdvanceStats::frameInSequence counts the frames it has seen).

__Threads.__ Separate instances may run on separate threads at once; results do not depend on
cv::setNumThreads. One instance must not be used from two threads at once.

__Parameters.__ Params (getParams(), setParams(), a getter/setter per field) and one struct per base
(setLSDParams(), setFLDParams(), setEDLinesParams()). Setters throw cv::Exception naming the
parameter and its range, and change nothing. write() saves them all (modes by name); read()
takes names or numbers, keeps what a file lacks and warns about an unknown key.
*/
class CV_EXPORTS_W LSDAdvance : public Algorithm
{
public:
    /** @brief How stage 1 (the length filter) runs. */
    enum LengthFilterMode
    {
        LENGTH_FILTER_NONE = 0,     //!< keep every segment
        LENGTH_FILTER_ADAPTIVE = 1, //!< the frame's own threshold, alpha = 1: stateless (default)
        /** the paper's inter-frame rule: alpha from the change r of the kept count over the two
        previous frames (1 - 0.2 (1 + r) below r = -0.1, 1 up to 0.1, then 1 + 0.1 (r - 0.1), <= 1.2) */
        LENGTH_FILTER_INTERFRAME = 2,
        LENGTH_FILTER_INTERFRAME_CONTINUOUS = 3, //!< the same rule without its jump at r = -0.1 (ours)
        LENGTH_FILTER_COUNT_TRACKING = 4 //!< count tracking (ours): alpha opposes the frame's own count change
    };

    /** @brief The rule of stage 1's threshold, from the mean @f$\mu@f$ and population standard
    deviation @f$\sigma@f$ of the base segments' lengths, times alpha and lengthThresholdScale. */
    enum LengthThresholdRule
    {
        LENGTH_THRESHOLD_PAPER = 0, //!< @f$\mu (1 - |\mu - \sigma| / \mu)@f$ clamped at 0 (the paper's)
        LENGTH_THRESHOLD_CAPPED = 1 //!< @f$\min(\mu, \sigma)@f$: the same while @f$\sigma \le \mu@f$ (default)
    };

    /** @brief How stage 3 fuses the segments of a group. */
    enum MergeStrategy
    {
        MERGE_NONE = 0,          //!< no fusion (stages 2 and 3 are skipped)
        /** the paper's: segments at least Params::baselineRatio times the group's longest are
        baselines, which never fuse with each other; the others fuse into them */
        MERGE_BASELINES = 1,
        MERGE_LONGEST_FIRST = 2  //!< every segment, longest first, absorbs the shorter ones that pass (default)
    };

    /** @brief Order of the stages. */
    enum StageOrder
    {
        FILTER_THEN_MERGE = 0, //!< the paper's: length filter, then grouping and merging
        MERGE_THEN_FILTER = 1  //!< merging first, then the filter with the base segments' threshold (default)
    };

    /** @brief Which angle bins group together in stage 2. */
    enum AngleBinning
    {
        ANGLE_BINS_STRICT = 0,    //!< only segments of the same bin (the paper's)
        ANGLE_BINS_NEIGHBOURS = 1 //!< also the two neighbouring bins, wrapping 180 deg to 0 (default)
    };

    /** @brief The order of the lines detect() and processSegments() return, in which Params::maxLines
    keeps the first: the first N lines are the selection of a budget of N. */
    enum LineOrder
    {
        LINE_ORDER_STRONGEST = 0, //!< by decreasing response (processSegments(): length) (default)
        /** the strongest line of each bin, strongest first, then the second strongest of each bin,
        and so on; a bin holds the lines of one of Params::directionBins bins of direction whose
        midpoints lie in one of the Params::gridCells x Params::gridCells cells of the image. A budget
        spread over the directions and the image, as ORB-SLAM spreads its keypoints: its lines
        constrain a camera pose better than as many lines of a few directions or of one repeated
        structure (doc/pose.md) */
        LINE_ORDER_ACROSS_DIRECTIONS = 1
    };

    /** @brief How BASE_FAST_LSD grows a region (LSDParams::regionGrowth): when the region's direction,
    against which a pixel's level-line angle is tested, takes in the pixels that have joined. */
    enum RegionGrowth
    {
        GROWTH_PER_PIXEL = 0,        //!< after every pixel that joins, as the LSD algorithm
        /** after the 8 neighbours of a pixel of the region have all been tested against the direction
        before any of them joined, at once (default) */
        GROWTH_PER_NEIGHBOURHOOD = 1
    };

    /** @brief Which images LSDParams::fullScaleSigma's Gaussian smooths before an LSD base reads them
    at scale 1 (LSDParams::fullScaleSmoothing). */
    enum FullScaleSmoothing
    {
        SMOOTH_EVERY_IMAGE = 0,   //!< every image
        /** only an image whose edges are mostly steps of one pixel, as where it was drawn or rendered
        without anti-aliasing or enlarged without interpolation (the test: doc/algorithm.md, "Base
        detectors"); a photograph, whose optics spread its edges over more pixels, is read as it is,
        as with fullScaleSigma 0 (default) */
        SMOOTH_ALIASED_IMAGES = 1
    };

    /** @brief The detector of stage 0. Every base gives segments oriented brighter side on the
    left (EDLines' are turned round where needed). */
    enum BaseDetector
    {
        /** the LSD algorithm, OpenCV's cv::LineSegmentDetector (or cv::ximgproc::LineSegmentDetector,
        where opencv#29349 moves it), with LSDParams (at scale 1 after
        LSDParams::fullScaleSigma's Gaussian); on an OpenCV with neither, detect() throws
        cv::Exception (StsNotImplemented) naming BASE_FAST_LSD (doc/building.md) */
        BASE_LSD = 0,
        BASE_FLD = 1,     //!< cv::ximgproc::FastLineDetector with FLDParams
        BASE_EDLINES = 2, //!< EDLines of cv::ximgproc::EdgeDrawing with its EdgeDrawing::Params
        /** the LSD algorithm, the module's own implementation written for speed, with LSDParams: with
        LSDParams::seedGradientRatio 1, LSDParams::seedAlignedNeighbours 0, LSDParams::tileHeight 0 and
        LSDParams::regionGrowth GROWTH_PER_PIXEL it gives BASE_LSD's segments, and with LSDParams::fullScaleSigma 0 too those of OpenCV's
        LineSegmentDetector (doc/performance.md). The default. */
        BASE_FAST_LSD = 3
    };

    /** @brief Named configurations for createLSDAdvance() (doc/algorithm.md, "Presets"). */
    enum Preset
    {
        PRESET_MOST_ACCURATE = 0, //!< the defaults: the highest F on YorkUrban
        PRESET_FASTEST = 1,       //!< the defaults with the base at LSDParams::scale 0.8 (OpenCV LSD's scale)
        /** the paper's: OpenCV's LSD set-up (LSD_REFINE_STD, scale 0.8), LENGTH_THRESHOLD_PAPER,
        LENGTH_FILTER_INTERFRAME, FILTER_THEN_MERGE, MERGE_BASELINES, proximityRatio 0.1 */
        PRESET_PAPER = 2,
        /** video, SLAM: PRESET_MOST_ACCURATE with LENGTH_FILTER_COUNT_TRACKING and keepStrongSegments.
        Its state is the sequence: one detector object kept across the frames (see "State"). */
        PRESET_SEQUENCE = 3,
        /** a point-line SLAM front end that keeps a budget of lines for LBD: PRESET_MOST_ACCURATE with
        Params::maxLines 60 in LINE_ORDER_ACROSS_DIRECTIONS (the 60 strongest lines spread over the
        horizontal, the vertical and the two diagonals in each quarter of the image: Params::gridCells
        2) and LSDParams::fullScaleSmoothing
        SMOOTH_EVERY_IMAGE: the lines that gave the best poses, doc/pose.md. Stateless, unlike
        PRESET_SEQUENCE. */
        PRESET_FRONT_END = 4
    };

    /** @brief LSDAdvance's own parameters (those of stages 1-3 and the choice of base). */
    struct CV_EXPORTS_W_SIMPLE Params
    {
        CV_WRAP Params(); //!< the defaults (PRESET_MOST_ACCURATE)
        CV_PROP_RW int baseDetector;            //!< stage 0, one of BaseDetector. Default BASE_FAST_LSD.
        CV_PROP_RW int lengthFilterMode;        //!< stage 1, one of LengthFilterMode. Default LENGTH_FILTER_ADAPTIVE.
        CV_PROP_RW int lengthThresholdRule;     //!< stage 1, one of LengthThresholdRule. Default LENGTH_THRESHOLD_CAPPED.
        CV_PROP_RW double lengthThresholdScale; //!< factor on stage 1's threshold (below 1 keeps shorter segments), in (0, 10]. Default 0.95.
        CV_PROP_RW bool keepStrongSegments;     //!< stage 1 also keeps a shorter segment whose response (computeLineResponses) reaches the same rule on the base segments' responses: short lines of high contrast, which LBD matches again; costs the responses (processSegments: by length alone; on in PRESET_SEQUENCE). Default false.
        CV_PROP_RW int stageOrder;              //!< one of StageOrder. Default MERGE_THEN_FILTER.
        CV_PROP_RW double angleBinWidth;        //!< stage 2's angle bins, degrees, in [1, 90]. Default 10.
        CV_PROP_RW int angleBinning;            //!< stage 2, one of AngleBinning. Default ANGLE_BINS_NEIGHBOURS.
        CV_PROP_RW double endpointDistance;     //!< stage 2: segments with two endpoints closer than this are adjacent, pixels, in [0.1, 200]. Default 15.
        CV_PROP_RW int mergeStrategy;           //!< stage 3, one of MergeStrategy. Default MERGE_LONGEST_FIRST.
        CV_PROP_RW double baselineRatio;        //!< MERGE_BASELINES: baselines are at least this share of the longest, in (0, 1]. Default 0.8.
        CV_PROP_RW double directionWeight;      //!< weight of the score's direction term, in [0, 1]. Default 0.4.
        CV_PROP_RW double proximityWeight;      //!< weight of the score's proximity term, in [0, 1]. Default 0.35.
        CV_PROP_RW double lengthWeight;         //!< weight of the score's length term, in [0, 1]. Default 0.2.
        CV_PROP_RW double proximityRatio;       //!< segments farther apart than this times their mean length never fuse, in (0, 10]. Default 1.
        CV_PROP_RW double mergeThreshold;       //!< score a segment needs to fuse into a longer one, in [0, 1]. Default 0.6.
        CV_PROP_RW double maxPerpendicularOffset; //!< both endpoints must lie this close to the longer one's line, pixels, in [0, 100]. Default 1.5.
        CV_PROP_RW double minLineLength;        //!< selection: lines shorter than this are dropped (0: off), pixels, in [0, 100000]. Default 0.
        CV_PROP_RW double minLineLengthRatio;   //!< selection: lines shorter than this times min(W, H) are dropped (0: off; with minLineLength too, the larger threshold applies; not used by processSegments without imageSize), in [0, 1]. Default 0.
        CV_PROP_RW int maxLines;                //!< selection: the line budget, the first maxLines lines of the order (lineOrder) are kept, in 0 (all) or [1, 100000]. Default 0.
        CV_PROP_RW int lineOrder;               //!< selection: one of LineOrder, the order of the lines and of the budget. Default LINE_ORDER_STRONGEST.
        CV_PROP_RW int directionBins;           //!< selection with LINE_ORDER_ACROSS_DIRECTIONS: the undirected directions in this many equal bins, the first centred on the horizontal (4: horizontal, vertical and the two diagonals, each +-22.5 deg), in [2, 180]. Default 4.
        CV_PROP_RW int gridCells;               //!< selection with LINE_ORDER_ACROSS_DIRECTIONS: the image (processSegments() without imageSize: the lines' bounding box) in this many equal columns and as many rows, a line in the cell of its midpoint, each cell with its own direction bins (1: the whole image), in [1, 32]. Default 1.
    };

    /** @brief The LSD algorithm's parameters (@cite Rafael12), used by BASE_LSD (OpenCV's
    LineSegmentDetector) and BASE_FAST_LSD, with the meaning of cv::createLineSegmentDetector's arguments,
    a pre-smoothing at scale 1 for both (fullScaleSigma, fullScaleSmoothing), and four of BASE_FAST_LSD's own
    (seedGradientRatio, seedAlignedNeighbours, tileHeight, regionGrowth). */
    struct CV_EXPORTS_W_SIMPLE LSDParams
    {
        CV_WRAP LSDParams(); //!< the defaults (OpenCV's LSD uses LSD_REFINE_STD at scale 0.8)
        CV_PROP_RW int refine;              //!< one of cv::LineSegmentDetectorModes. Default LSD_REFINE_NONE.
        CV_PROP_RW double scale;            //!< scale at which the image is read; the segments are returned in the full image's coordinates (pixel centres, see "Coordinates": unlike OpenCV's LSD below scale 1), in (0, 1]. Default 1.
        CV_PROP_RW double sigmaScale;       //!< Gaussian sigma = sigmaScale / scale, used when scale < 1, in (0, 100]. Default 0.6.
        CV_PROP_RW double fullScaleSigma;   //!< sigma of a Gaussian applied at scale 1 to the images of fullScaleSmoothing (at scale < 1 the one of sigmaScale smooths), pixels: more of the gradients of staircase edges (lines drawn without anti-aliasing, rendered frames) then agree within angleTolerance; 0 reads every image as the LSD algorithm does, in [0, 3]. Default 0.5.
        CV_PROP_RW int fullScaleSmoothing;  //!< one of LSDAdvance::FullScaleSmoothing: the images fullScaleSigma smooths (SMOOTH_ALIASED_IMAGES reads a photograph as it is). Default SMOOTH_ALIASED_IMAGES.
        CV_PROP_RW double quant;            //!< bound to the gradient quantization error, gray levels, in [0, 255]. Default 2.
        CV_PROP_RW double angleTolerance;   //!< gradient angle tolerance, degrees, in (0, 180). Default 22.5.
        CV_PROP_RW double logEps;           //!< detection threshold -log10(NFA) with LSD_REFINE_ADV, in [-1000, 1000]. Default 0.
        CV_PROP_RW double densityThreshold; //!< least share of aligned points in a rectangle, in [0, 1). Default 0.7.
        CV_PROP_RW int numBins;             //!< bins of the gradient pseudo-ordering, in [1, 65536]. Default 1024.
        CV_PROP_RW double seedGradientRatio; //!< BASE_FAST_LSD only: regions are seeded only at pixels whose gradient norm is at least this times LSD's threshold quant / sin(angleTolerance), and weaker ones only join them, in [1, 100]; 1 seeds everywhere, as the LSD algorithm. Default 2.5.
        CV_PROP_RW int seedAlignedNeighbours; //!< BASE_FAST_LSD only: regions are seeded only at pixels with at least this many of their two 8-neighbours along their level line aligned with them (an edge, not texture), in [0, 2]; 0 as the LSD algorithm. Default 2.
        CV_PROP_RW int tileHeight;          //!< BASE_FAST_LSD only: regions grow in parallel in horizontal tiles of about this many rows at the analysis scale, laid out from the image size alone, and are joined across them (without tiles, as the LSD algorithm), in 0 (no tiles) or [16, 100000]. Default 64.
        CV_PROP_RW int regionGrowth;        //!< BASE_FAST_LSD only: one of LSDAdvance::RegionGrowth, when a region's direction takes in the pixels that join it (GROWTH_PER_PIXEL as the LSD algorithm). Default GROWTH_PER_NEIGHBOURHOOD.
    };

    /** @brief FastLineDetector's parameters (@cite Lee14), used by BASE_FLD, with the meaning of
    cv::ximgproc::createFastLineDetector's arguments. */
    struct CV_EXPORTS_W_SIMPLE FLDParams
    {
        CV_WRAP FLDParams(); //!< the defaults (FastLineDetector's)
        CV_PROP_RW int lengthThreshold;     //!< shortest segment kept, pixels, in [1, 100000]. Default 10.
        CV_PROP_RW double distanceThreshold; //!< outlier distance to a hypothesis line, pixels, in (0, 100]. Default 1.414213562.
        CV_PROP_RW double cannyThreshold1;  //!< first hysteresis threshold of Canny, in (0, 100000]. Default 50.
        CV_PROP_RW double cannyThreshold2;  //!< second hysteresis threshold of Canny, in (0, 100000]. Default 50.
        CV_PROP_RW int cannyApertureSize;   //!< Sobel aperture of Canny, 3, 5 or 7. Default 3.
        CV_PROP_RW bool doMerge;            //!< FastLineDetector's own merging (20 times its cost). Default false.
    };

    /** @brief Detects line segments (with an inter-frame LengthFilterMode: the next frame).
    @param image 8-bit gray, BGR or BGRA image (see "Input").
    @param lines Output N x 1 CV_32FC4: (x1, y1, x2, y2) per segment (see "Output").
    @param mask Optional CV_8UC1 mask of the image's size: no segment is detected on, nor passes
    over, its zero pixels (see "Mask"). Default: none. */
    CV_WRAP virtual void detect(InputArray image, OutputArray lines, InputArray mask = noArray()) = 0;

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    /** @brief Detects line segments as KeyLines for line_descriptor's LBD (@cite LBD).
    Include opencv2/lsd_advance/keylines.hpp (or opencv2/lsd_advance.hpp) to call it: this header
    only names KeyLine.
    @param image As for detect(InputArray, OutputArray).
    @param keylines Output: one KeyLine per segment detect() returns, in the same order (strongest
    first, after the minimum length and the budget), filled by linesToKeyLines() as
    cv::line_descriptor::LSDDetector fills octave 0 (`class_id` 0..N-1), except `response`:
    getLastResponses()' (computeLineResponses()), the length weighted by the squared contrast.
    keepStrongestKeyLines() cuts them to a smaller budget. In Python: detectKeyLines(image[, mask]) -> keylines.
    @param mask As for detect(InputArray, OutputArray, InputArray). */
    CV_WRAP_AS(detectKeyLines) void detect(InputArray image, CV_OUT std::vector<line_descriptor::KeyLine>& keylines,
                                           InputArray mask = noArray());

    /** @brief Detects line segments as KeyLines and computes their binary LBD descriptors: detect(image,
    keylines, mask), then computeLBD() on the same image (the descriptors of
    cv::line_descriptor::BinaryDescriptor::compute, byte for byte). Include
    opencv2/lsd_advance/keylines.hpp (or opencv2/lsd_advance.hpp) to call it.
    @param image As for detect(InputArray, OutputArray).
    @param keylines Output: as detect(InputArray, std::vector<KeyLine>&, InputArray) gives them.
    @param descriptors Output N x 32 CV_8U, row i the descriptor of keylines[i].
    @param mask As for detect(InputArray, OutputArray, InputArray).
    In Python: detectAndCompute(image[, mask]) -> keylines, descriptors. */
    CV_WRAP void detectAndCompute(InputArray image, CV_OUT std::vector<line_descriptor::KeyLine>& keylines,
                                  OutputArray descriptors, InputArray mask = noArray());
#endif

    /** @brief Runs stages 1-3 on segments from any detector; the call is a frame like detect().
    @param segments N x 1 or 1 x N CV_32FC4, finite, within [-1e7, 1e7) px, oriented as LSD's.
    @param lines Output like detect(), longest first (there is no image to compute responses on),
    after Params::minLineLength, Params::minLineLengthRatio (with imageSize only) and Params::maxLines.
    @param imageSize When not empty, the lines are clipped to this image as detect() clips them;
    when empty (default), not clipped (a fused segment may reach a little beyond its pieces), or
    clipped to the mask's size when there is a mask.
    @param mask Optional CV_8UC1 mask of the image's size (imageSize when given): the segments are
    cut at it and stage 3 fuses none across it, as in detect() (see "Mask"). Default: none. */
    CV_WRAP virtual void processSegments(InputArray segments, OutputArray lines, Size imageSize = Size(),
                                         InputArray mask = noArray()) = 0;

    /** @brief Draws segments on an image, as LineSegmentDetector::drawSegments does.
    @param image 8-bit image with 1 or 3 channels; a gray one is converted to BGR in place.
    @param lines segments (x1, y1, x2, y2) as detect() writes them, CV_32F or CV_32S: std::vector<Vec4f> or
    std::vector<Vec4i>, an N x 1 (or 1 x N) 4-channel or an N x 4 1-channel Mat; drawn in red, 1 px wide. */
    CV_WRAP virtual void drawSegments(InputOutputArray image, InputArray lines) = 0;

    /** @brief Starts a new sequence: the next call is the first frame (alpha = 1). */
    CV_WRAP virtual void reset() = 0;
    /** @brief Returns the statistics of the last call.
    @return Those of the last call that succeeded (zeros, alpha 1, before the first). */
    CV_WRAP virtual LSDAdvanceStats getLastStats() const = 0;

    /** @brief Returns the responses of the lines of the last call.
    @param responses Output N x 1 CV_32FC1, computeLineResponses() of each line the last detect()
    returned, in its order (decreasing); empty after processSegments() and before the first call. */
    CV_WRAP virtual void getLastResponses(OutputArray responses) const = 0;

    /** @brief Returns the segments after each stage of the last call, before the clipping.
    Each output may be noArray(): only those asked for are filled.
    @param baseSegments Output CV_32FC4: the base detector's segments (processSegments' input),
    after the cut at the mask.
    @param filteredSegments Output CV_32FC4: stage 1's output (its input with LENGTH_FILTER_NONE),
    from baseSegments with FILTER_THEN_MERGE, from mergedSegments with MERGE_THEN_FILTER.
    @param groupLabels Output CV_32S, one per segment entering stage 2: -1 alone, else its group in
    [0, getLastStats().mergeGroups), numbered by first segment. Empty with MERGE_NONE.
    @param mergedSegments Output CV_32FC4: stage 3's output (its input with MERGE_NONE). */
    CV_WRAP virtual void getLastStageOutputs(OutputArray baseSegments, OutputArray filteredSegments,
                                             OutputArray groupLabels, OutputArray mergedSegments) const = 0;

    /** @brief Returns, for each line of the last call, the base segments it was made from.
    @param sources Output, one CV_32S array (std::vector<int>) per returned line, in order: the
    increasing indices into getLastStageOutputs()' baseSegments of the segments fused into it. */
    CV_WRAP virtual void getLastSources(OutputArrayOfArrays sources) const = 0;

    CV_WRAP virtual LSDAdvance::Params getParams() const = 0; //!< @brief Returns Params. @return Every field.
    /** @brief Sets Params. @param params Every field, all validated before any changes. */
    CV_WRAP virtual void setParams(const LSDAdvance::Params& params) = 0;
    CV_WRAP virtual LSDAdvance::LSDParams getLSDParams() const = 0; //!< @brief Returns BASE_LSD's and BASE_FAST_LSD's. @return Every field.
    /** @brief Sets those of BASE_LSD and BASE_FAST_LSD. @param params Every field, all validated first. */
    CV_WRAP virtual void setLSDParams(const LSDAdvance::LSDParams& params) = 0;
    CV_WRAP virtual LSDAdvance::FLDParams getFLDParams() const = 0; //!< @brief Returns BASE_FLD's. @return Every field.
    /** @brief Sets the parameters of BASE_FLD. @param params Every field, all validated first. */
    CV_WRAP virtual void setFLDParams(const LSDAdvance::FLDParams& params) = 0;
    /** @brief Returns BASE_EDLINES'. @return Every field (EdgeDrawing's defaults unless set). */
    CV_WRAP virtual EdgeDrawing::Params getEDLinesParams() const = 0;
    /** @brief Sets the parameters of BASE_EDLINES. @param params Every field, all validated first:
    GradientThresholdValue [1, 10000], AnchorThresholdValue [0, 10000], ScanInterval [1, 100],
    MinPathLength [2, 100000] px, Sigma [0, 100] px, MinLineLength -1 (from the image size) or
    [9, 100000] px, MaxDistanceBetweenTwoLines (0, 1000] px, LineFitErrorThreshold [0.5, 100] px,
    MaxErrorThreshold (0, 100] px. */
    CV_WRAP virtual void setEDLinesParams(const EdgeDrawing::Params& params) = 0;

    CV_WRAP virtual void setBaseDetector(int detector) = 0;            //!< @brief Sets Params::baseDetector. @param detector The new value.
    CV_WRAP virtual int getBaseDetector() const = 0;                   //!< @brief Returns Params::baseDetector. @return The value.
    CV_WRAP virtual void setLengthFilterMode(int mode) = 0;            //!< @brief Sets Params::lengthFilterMode. @param mode The new value.
    CV_WRAP virtual int getLengthFilterMode() const = 0;               //!< @brief Returns Params::lengthFilterMode. @return The value.
    CV_WRAP virtual void setLengthThresholdRule(int rule) = 0;         //!< @brief Sets Params::lengthThresholdRule. @param rule The new value.
    CV_WRAP virtual int getLengthThresholdRule() const = 0;            //!< @brief Returns Params::lengthThresholdRule. @return The value.
    CV_WRAP virtual void setLengthThresholdScale(double scale) = 0;    //!< @brief Sets Params::lengthThresholdScale. @param scale The new value.
    CV_WRAP virtual double getLengthThresholdScale() const = 0;        //!< @brief Returns Params::lengthThresholdScale. @return The value.
    CV_WRAP virtual void setKeepStrongSegments(bool keep) = 0;         //!< @brief Sets Params::keepStrongSegments. @param keep The new value.
    CV_WRAP virtual bool getKeepStrongSegments() const = 0;            //!< @brief Returns Params::keepStrongSegments. @return The value.
    CV_WRAP virtual void setStageOrder(int order) = 0;                 //!< @brief Sets Params::stageOrder. @param order The new value.
    CV_WRAP virtual int getStageOrder() const = 0;                     //!< @brief Returns Params::stageOrder. @return The value.
    CV_WRAP virtual void setAngleBinWidth(double degrees) = 0;         //!< @brief Sets Params::angleBinWidth. @param degrees The new value.
    CV_WRAP virtual double getAngleBinWidth() const = 0;               //!< @brief Returns Params::angleBinWidth. @return The value.
    CV_WRAP virtual void setAngleBinning(int binning) = 0;             //!< @brief Sets Params::angleBinning. @param binning The new value.
    CV_WRAP virtual int getAngleBinning() const = 0;                   //!< @brief Returns Params::angleBinning. @return The value.
    CV_WRAP virtual void setEndpointDistance(double pixels) = 0;       //!< @brief Sets Params::endpointDistance. @param pixels The new value.
    CV_WRAP virtual double getEndpointDistance() const = 0;            //!< @brief Returns Params::endpointDistance. @return The value.
    CV_WRAP virtual void setMergeStrategy(int strategy) = 0;           //!< @brief Sets Params::mergeStrategy. @param strategy The new value.
    CV_WRAP virtual int getMergeStrategy() const = 0;                  //!< @brief Returns Params::mergeStrategy. @return The value.
    CV_WRAP virtual void setBaselineRatio(double ratio) = 0;           //!< @brief Sets Params::baselineRatio. @param ratio The new value.
    CV_WRAP virtual double getBaselineRatio() const = 0;               //!< @brief Returns Params::baselineRatio. @return The value.
    CV_WRAP virtual void setDirectionWeight(double weight) = 0;        //!< @brief Sets Params::directionWeight. @param weight The new value.
    CV_WRAP virtual double getDirectionWeight() const = 0;             //!< @brief Returns Params::directionWeight. @return The value.
    CV_WRAP virtual void setProximityWeight(double weight) = 0;        //!< @brief Sets Params::proximityWeight. @param weight The new value.
    CV_WRAP virtual double getProximityWeight() const = 0;             //!< @brief Returns Params::proximityWeight. @return The value.
    CV_WRAP virtual void setLengthWeight(double weight) = 0;           //!< @brief Sets Params::lengthWeight. @param weight The new value.
    CV_WRAP virtual double getLengthWeight() const = 0;                //!< @brief Returns Params::lengthWeight. @return The value.
    CV_WRAP virtual void setProximityRatio(double ratio) = 0;          //!< @brief Sets Params::proximityRatio. @param ratio The new value.
    CV_WRAP virtual double getProximityRatio() const = 0;              //!< @brief Returns Params::proximityRatio. @return The value.
    CV_WRAP virtual void setMergeThreshold(double threshold) = 0;      //!< @brief Sets Params::mergeThreshold. @param threshold The new value.
    CV_WRAP virtual double getMergeThreshold() const = 0;              //!< @brief Returns Params::mergeThreshold. @return The value.
    CV_WRAP virtual void setMaxPerpendicularOffset(double pixels) = 0; //!< @brief Sets Params::maxPerpendicularOffset. @param pixels The new value.
    CV_WRAP virtual double getMaxPerpendicularOffset() const = 0;      //!< @brief Returns Params::maxPerpendicularOffset. @return The value.
    CV_WRAP virtual void setMinLineLength(double pixels) = 0;          //!< @brief Sets Params::minLineLength. @param pixels The new value.
    CV_WRAP virtual double getMinLineLength() const = 0;               //!< @brief Returns Params::minLineLength. @return The value.
    CV_WRAP virtual void setMinLineLengthRatio(double ratio) = 0;      //!< @brief Sets Params::minLineLengthRatio. @param ratio The new value.
    CV_WRAP virtual double getMinLineLengthRatio() const = 0;          //!< @brief Returns Params::minLineLengthRatio. @return The value.
    CV_WRAP virtual void setMaxLines(int lines) = 0;                   //!< @brief Sets Params::maxLines. @param lines The new value.
    CV_WRAP virtual int getMaxLines() const = 0;                       //!< @brief Returns Params::maxLines. @return The value.
    CV_WRAP virtual void setLineOrder(int order) = 0;                  //!< @brief Sets Params::lineOrder. @param order The new value.
    CV_WRAP virtual int getLineOrder() const = 0;                      //!< @brief Returns Params::lineOrder. @return The value.
    CV_WRAP virtual void setDirectionBins(int bins) = 0;               //!< @brief Sets Params::directionBins. @param bins The new value.
    CV_WRAP virtual int getDirectionBins() const = 0;                  //!< @brief Returns Params::directionBins. @return The value.
    CV_WRAP virtual void setGridCells(int cells) = 0;                  //!< @brief Sets Params::gridCells. @param cells The new value.
    CV_WRAP virtual int getGridCells() const = 0;                      //!< @brief Returns Params::gridCells. @return The value.
};

/** @brief Creates an LSDAdvance detector.
@param preset One of LSDAdvance::Preset. Default PRESET_MOST_ACCURATE (every parameter at its default).
@return A new detector with an empty sequence. Throws cv::Exception on an unknown preset. */
CV_EXPORTS_W Ptr<LSDAdvance> createLSDAdvance(LSDAdvance::Preset preset = LSDAdvance::PRESET_MOST_ACCURATE);

//! @} lsd_advance

}} // namespace cv::ximgproc

#endif
