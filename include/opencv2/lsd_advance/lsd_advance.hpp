// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_LSD_ADVANCE_HPP
#define OPENCV_LSD_ADVANCE_LSD_ADVANCE_HPP

#include "opencv2/core.hpp"
#include "opencv2/imgproc.hpp"  // cv::LineSegmentDetectorModes for setLsdRefine
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "opencv2/line_descriptor.hpp"
#endif

namespace cv {
namespace ximgproc {

//! @addtogroup lsd_advance
//! @{

/** @brief Statistics of the last LSDAdvance::detect or LSDAdvance::processSegments call.

Counts are numbers of segments after each stage; times are wall-clock milliseconds of each stage
(stage 0 includes the conversion of a colour input to gray; it is 0 after processSegments).
*/
struct CV_EXPORTS_W_SIMPLE LSDAdvanceStats
{
    LSDAdvanceStats()
        : baseSegments(0), mergedSegments(0), filteredSegments(0), mergeGroups(0), outputSegments(0),
          minLength(0), alpha(1), baseMs(0), filterMs(0), groupingMs(0), mergingMs(0)
    {}

    CV_PROP_RW int baseSegments;     //!< segments returned by the base detector (stage 0)
    CV_PROP_RW int mergedSegments;   //!< segments after merging (stage 3)
    CV_PROP_RW int filteredSegments; //!< segments that survived the length filter (stage 1)
    CV_PROP_RW int mergeGroups;      //!< endpoint groups holding two or more segments (stage 2)
    CV_PROP_RW int outputSegments;   //!< segments returned
    CV_PROP_RW double minLength;     //!< length threshold of stage 1, in pixels (0 when the filter is off)
    CV_PROP_RW double alpha;         //!< inter-frame factor used by stage 1, in [0.8, 1.2] (1 when the filter is off)
    CV_PROP_RW double baseMs;        //!< time of stage 0, ms
    CV_PROP_RW double filterMs;      //!< time of stage 1, ms
    CV_PROP_RW double groupingMs;    //!< time of stage 2, ms
    CV_PROP_RW double mergingMs;     //!< time of stage 3, ms
};

/** @example samples/lsd_advance_demo.cpp
An example comparing LSDAdvance with OpenCV's LineSegmentDetector on building.jpg.
*/

/** @brief Line segment detector that returns fewer, longer segments than LSD (@cite Guan2026).

The segments of OpenCV's LineSegmentDetector (@cite Rafael12), or of FastLineDetector
(@cite Lee14) or EDLines (@cite akinlar2011edlines) (see BaseDetector), are post-processed in
three stages:
1. **Adaptive length suppression**: with @f$\mu@f$ and @f$\sigma@f$ the mean and population
   standard deviation of the segment lengths of the frame, segments shorter than
   @f$L_{min} = \alpha\,\mu\,(1 - |\mu - \sigma| / \mu)@f$ (the paper's rule; by default
   @f$\alpha \min(\mu, \sigma)@f$, see LengthThresholdRule; both times getLengthThresholdScale) are
   dropped. @f$\alpha@f$ is 1 for a
   single image; in a sequence it follows the change of the count of kept segments over the two
   previous frames (see LENGTH_FILTER_INTERFRAME).
2. **Grouping**: segments are binned by undirected angle (getAngleBinWidth), and two segments
   of the same (or, by default, a neighbouring) bin are connected when two of their endpoints
   are closer than getEndpointDistance. Connected components are the merge groups.
3. **Similarity-ordered merging**: in each group, a segment L is scored against a longer
   segment B (with MERGE_BASELINES, the paper's rule, only against the baselines: the segments
   at least getBaselineRatio times as long as the longest) with
   @f$S = w_d S_d + w_p S_p + w_l S_l@f$ (direction: cosine of the angle between the directed segments, clipped at 0; proximity: @f$1 - D_{min}/D_{th}@f$ clipped at 0,
   @f$D_{th}@f$ = getProximityRatio times the mean length of B and L; length:
   @f$1 - |l_B - l_L| / \max(l_B, l_L)@f$) and fused into B, best scores first, when
   @f$S \ge@f$ getMergeThreshold, @f$D_{min} < D_{th}@f$, and both of its endpoints lie within
   getMaxPerpendicularOffset of B's line. The fused segment passes through the
   length-weighted centre of B and L, along their length-weighted mean direction, and spans
   the projections of all four endpoints.

@note The defaults are not the paper's configuration; each was chosen by measurement on half of
YorkUrban-LineSegment and checked on the other half (doc/parameter_sweep.md): the base LSD reads
the image at full scale without refinement (LSD_REFINE_NONE, scale 1; OpenCV's LSD uses
LSD_REFINE_STD at scale 0.8 and is about 1.5 times faster), the length threshold is capped at
the mean length (LENGTH_THRESHOLD_CAPPED: the paper's rule falls to 0 on frames with a few very
long segments, which such a base detector often gives), merging runs before the length
filter (MERGE_THEN_FILTER: the paper's order drops pieces that merging would join), every
segment can absorb the shorter ones (MERGE_LONGEST_FIRST: the paper's baselines never join each
other), and the proximity term uses 1.0 times the mean length instead of 0.1. The paper's
configuration is LSD_REFINE_STD, scale 0.8, LENGTH_THRESHOLD_PAPER, FILTER_THEN_MERGE,
MERGE_BASELINES and proximityRatio 0.1.

@note Further differences from @cite Guan2026, each chosen to fix a gap of the paper: collinear pieces
that straddle an angle-bin edge (9.9 vs 10.1 deg, 179.9 vs 0.1 deg) are paired across it
(ANGLE_BINS_NEIGHBOURS); the centre of a fused segment drops the paper's extra factor 1/2; the
mean direction is computed on unit vectors, never as a mean of angles across the 0/180 wrap;
the merge threshold, the perpendicular-offset gate and the condition @f$D_{min} < D_{th}@f$ are
additions (the paper gives none; the gate keeps two parallel edges 2 px apart from fusing, the
distance condition keeps direction and length alone from joining pieces far apart); with MERGE_BASELINES, merging repeats
over the group until no score reaches the threshold, each score being computed against the
current (already grown) baseline, so that a chain of pieces joins a baseline piece by piece.

__Orientation.__ Like LSD, each segment (x1, y1, x2, y2) points from its start to its end so
that, on the image as displayed (y pointing down), the brighter side is on its left and the
darker side on its right. Fused segments keep the orientation of their baseline.

__Coordinates.__ OpenCV's pixel-centre convention: pixel (i, j) is centred at (i, j).

__Input.__ 8-bit images with 1 channel (gray), 3 channels (BGR) or 4 channels (BGRA, alpha
ignored), of any size from 1 x 1 and any layout (ROI views, UMat); colour images are converted
to gray. Images too small for a segment give none. Like OpenCV's LSD, other depths (8S, 16U,
16S, 32S, 16F, 32F, 64F) and 2-channel images are rejected, not converted: scale them to 8 bits
first (Mat::convertTo). An empty image or another type throws cv::Exception naming the type
received and the accepted ones. A rejected call (image, segments, setter or read()) changes
nothing: neither the parameters nor the sequence state.

__Output.__ Coordinates are finite. Like LSD's, endpoints may lie outside the image: LSD
extends a segment to the ends of its region's rectangle (measured: up to 8.5 px with the
defaults on the 203 frames of the evaluation data, where merging never reached farther out).

__Memory.__ The default base (LSD) needs about 32 bytes per pixel at lsdScale 1 (its copies of
the image, gradient angles and norms, and its ordered pixel list) and 20 at scale 0.8: a
10000 x 10000 image peaks at 3.2 GB resident (measured). Stages 1-3 need memory proportional
to the number of segments. Memory does not grow over a sequence: 20,000 frames through one
object keep resident memory flat after warm-up (test LSDAdvance_LongSequence).

__Threads.__ Separate instances may run on separate threads at once and give the results they
give one after the other; results do not depend on cv::setNumThreads (bit-identical). One
instance is NOT safe to use from two threads at once: it holds the sequence state (the kept
counts of the previous frames), its base detector and reused buffers. Give each thread its own
instance, or serialize the calls.

__Parameters.__ Each has a getter and a setter. A setter throws cv::Exception, naming the
parameter and its valid range, on a value that is out of range or not finite, and every setter
resets the sequence (reset()). write() saves every parameter to a cv::FileStorage under its
name (lowerCamelCase, e.g. `mergeThreshold`); read() restores them, keeping the current value of
a missing key.
*/
class CV_EXPORTS_W LSDAdvance : public Algorithm
{
public:
    /** @brief How stage 1 (adaptive length suppression) runs. */
    enum LengthFilterMode
    {
        LENGTH_FILTER_NONE = 0,       //!< keep every base segment
        LENGTH_FILTER_ADAPTIVE = 1,   //!< per-frame threshold with alpha = 1 (each call independent)
        /** per-frame threshold scaled by the inter-frame factor (default). For frame k of a sequence,
        with N the counts of segments kept by stage 1 and r = (N(k-1) - N(k-2)) / N(k-2) (0 when
        N(k-2) = 0): alpha = 1 - 0.2 (1 + r) when r < -0.1, 1 when |r| <= 0.1, and
        min(1 + 0.1 (r - 0.1), 1.2) when r > 0.1; alpha = 1 on the first two frames.
        @note This is the paper's printed rule (@cite Guan2026) as we read it: its signs were lost in
        typesetting, and this is the only reading that keeps alpha in (0, 1.2]. It jumps from 1 to
        0.82 at r = -0.1 and reacts one frame late: measured on KITTI (@cite Geiger2012), the
        standard deviation of the count over frames grows from 66 (alpha = 1) to 94; on a still
        camera (EuRoC, @cite Burri2016) the count never changes by 10 % and the rule never acts
        (README, "Results"). */
        LENGTH_FILTER_INTERFRAME = 2,
        /** the same rule made continuous: alpha = max(1 + 0.2 (r + 0.1), 0.8) when r < -0.1.
        @note Not in the paper: a variant without its jump at r = -0.1. */
        LENGTH_FILTER_INTERFRAME_CONTINUOUS = 3,
        /** count tracking: alpha = clamp(1 + 0.5 r', 0.8, 1.2), where r' compares the count this
        frame keeps with alpha = 1 with the mean kept count of the two previous frames, so that
        the threshold opposes the frame's own deviation instead of the previous one's. Measured
        standard deviation of the count over frames: EuRoC 6.3 -> 3.5, KITTI 66 -> 59 (alpha = 1 ->
        count tracking).
        @note Not in the paper: our alternative to its one-frame-late rule. */
        LENGTH_FILTER_COUNT_TRACKING = 4
    };

    /** @brief The rule of stage 1's length threshold, from the mean @f$\mu@f$ and the population
    standard deviation @f$\sigma@f$ of the base segments' lengths. */
    enum LengthThresholdRule
    {
        /** the paper's @f$\alpha\,\mu\,(1 - |\mu - \sigma| / \mu)@f$, clamped at 0: @f$\alpha\sigma@f$
        while @f$\sigma \le \mu@f$, then falling to 0 at @f$\sigma = 2\mu@f$, so a frame with a
        few very long segments among many short ones is hardly filtered (building.jpg with the
        default base: 1.7 px) */
        LENGTH_THRESHOLD_PAPER = 0,
        /** @f$\alpha \min(\mu, \sigma)@f$ (default): the paper's value while
        @f$\sigma \le \mu@f$, and @f$\alpha\mu@f$ beyond.
        @note Our default instead of the paper's rule: it keeps the filter working on frames where
        @f$\sigma > \mu@f$ (building.jpg: 395 instead of 1570 output segments) for 0.003 of F on
        the YorkUrban check half (doc/parameter_sweep.md). */
        LENGTH_THRESHOLD_CAPPED = 1
    };

    /** @brief How stage 3 fuses the segments of a group. */
    enum MergeStrategy
    {
        MERGE_NONE = 0,          //!< no fusion (stage 2 and 3 are skipped)
        /** the paper's rule (@cite Guan2026): segments at least getBaselineRatio times as long as
        the group's longest are baselines, which never fuse with each other; the others fuse into
        them.
        @note Where the paper is silent: the other segments fuse in decreasing order of their best
        score (not of their length), each into its best-scoring baseline, and merging repeats over
        the group until no score reaches getMergeThreshold, each score computed against the current
        (already grown) baseline, so that a chain of pieces joins a baseline piece by piece. */
        MERGE_BASELINES = 1,
        /** every segment, from the longest down, absorbs the shorter segments of its group that pass
        the gate and the threshold, best score first (default). Unlike MERGE_BASELINES, two long
        collinear pieces of one edge can join, and a chain of short pieces can join each other.
        @note Not in the paper: our default, chosen by measurement (doc/parameter_sweep.md: every
        one of the 20 best settings uses it). */
        MERGE_LONGEST_FIRST = 2
    };

    /** @brief Order of the stages. */
    enum StageOrder
    {
        FILTER_THEN_MERGE = 0,  //!< the paper's order: length filter, then grouping and merging
        /** grouping and merging first, then the length filter with the threshold computed on the
        base segments (default): pieces that merge into a long segment are not lost to the filter.
        @note Not the paper's order: our default, chosen by measurement (doc/parameter_sweep.md). */
        MERGE_THEN_FILTER = 1
    };

    /** @brief Which angle bins may be grouped together in stage 2. */
    enum AngleBinning
    {
        ANGLE_BINS_STRICT = 0,     //!< only segments of the same bin (the paper's rule)
        /** also the two neighbouring bins, wrapping 180 deg to 0 (default).
        @note Our fix of the paper's strict bins, where collinear pieces at 9.9 and 10.1 deg (or
        179.9 and 0.1 deg) could never merge. */
        ANGLE_BINS_NEIGHBOURS = 1
    };

    /** @brief The detector of stage 0, whose segments stages 1-3 post-process.

    Every base returns segments oriented brighter side on the left: LSD and FLD orient them so
    themselves; EDLines orients a segment along the edge it traced, so LSDAdvance turns each
    EDLines segment round when the image is brighter on its right (mean of 5 samples 2 px either
    side). The orientation matters to stage 3: its direction term is the cosine between the
    directed segments, so two pieces of one edge pointing opposite ways would not fuse. */
    enum BaseDetector
    {
        /** OpenCV's cv::LineSegmentDetector (@cite Rafael12) with the lsd* parameters, the base of
        the paper */
        BASE_LSD = 0,
        /** cv::ximgproc::FastLineDetector (@cite Lee14) with the fld* parameters: Canny edges and
        line fitting, a few times faster than LSD.
        @note Not in the paper, like BASE_EDLINES: stages 1-3 unchanged on a faster base
        (doc/performance.md). */
        BASE_FLD = 1,
        /** EDLines (@cite akinlar2011edlines) of cv::ximgproc::EdgeDrawing with the ed*
        parameters: edge drawing, then line fitting with NFA validation, the fastest of the three.
        @note EDLines orients a segment along the edge chain it traced, not by the gradient:
        LSDAdvance turns round each of its segments that is brighter on its right (see
        BaseDetector), so that stage 3 and the output keep LSD's orientation. */
        BASE_EDLINES = 2,
        /** The module's own implementation of the LSD algorithm (@cite Rafael12) with the lsd*
        parameters, written for speed (doc/performance.md); it gives OpenCV's LineSegmentDetector's
        segments (tested against it on real images) in a fraction of its time. With
        LSD_REFINE_ADV it validates every segment by its number of false alarms as the published
        algorithm does, where OpenCV's LineSegmentDetector keeps nearly all of them. The default. */
        BASE_FAST_LSD = 3
    };

    /** @brief Detects line segments.

    @param image 8-bit gray (CV_8UC1), BGR (CV_8UC3) or BGRA (CV_8UC4) image, not empty, any size
    and layout (see "Input." in the class description).
    @param lines Output N x 1 array of CV_32FC4 (std::vector<cv::Vec4f> works):
    (x1, y1, x2, y2) per segment, pixel-centre coordinates, oriented as LSD orients them (brighter
    side on the left, see the class description).

    Consecutive calls on one object form a sequence for the inter-frame modes of
    LengthFilterMode (LENGTH_FILTER_INTERFRAME, _INTERFRAME_CONTINUOUS, _COUNT_TRACKING); call
    reset() before an unrelated image.
    */
    CV_WRAP virtual void detect(InputArray image, OutputArray lines) = 0;

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    /** @brief Detects line segments as KeyLines for line_descriptor's LBD descriptor (@cite LBD)
    and matcher.

    @param image As for detect(InputArray, OutputArray).
    @param keylines Output: one KeyLine per segment that detect(InputArray, OutputArray) returns,
    in the same order, filled by linesToKeyLines() exactly as
    cv::line_descriptor::LSDDetector fills octave 0, so that
    cv::line_descriptor::BinaryDescriptor::compute() and BinaryDescriptorMatcher take them
    unchanged. `response` ranks them: sort by it, largest first, to keep the N longest lines.

    The call is a frame of the sequence, like detect(InputArray, OutputArray). Present when
    OpenCV's line_descriptor module is (HAVE_OPENCV_LINE_DESCRIPTOR).
    */
    void detect(InputArray image, std::vector<line_descriptor::KeyLine>& keylines);
#endif

    /** @brief Runs the stages after base detection on segments from any detector.

    @param segments Input segments, N x 1 or 1 x N CV_32FC4 (std::vector<cv::Vec4f>), oriented as
    LSD orients them when the orientation of the output matters.
    @param lines Output like detect(). The call is a frame of the sequence, like detect().

    Coordinates must be finite and within [-1e7, 1e7) px; anything else throws, and an empty
    array gives no lines.
    */
    CV_WRAP virtual void processSegments(InputArray segments, OutputArray lines) = 0;

    /** @brief Forgets the sequence: the next detect() is the first frame (alpha = 1).

    Every setter (and read()) also resets the sequence: each parameter can change the kept counts.
    */
    CV_WRAP virtual void reset() = 0;

    /** @brief Returns counts, the length threshold, alpha and stage times of the last detect().
    @return The statistics of the last detect() or processSegments() call that succeeded (all
    zero, alpha 1, before the first). */
    CV_WRAP virtual LSDAdvanceStats getLastStats() const = 0;

    /** @brief Returns the segments after each stage of the last detect() or processSegments(), to
    draw or inspect what each stage did (the detect sample's --draw=filter,groups,merge).

    @param baseSegments Output N0 x 1 CV_32FC4: the base detector's segments (stage 0; after
    processSegments, its input segments).
    @param filteredSegments Output CV_32FC4: stage 1's output, the segments of its input at least
    getLastStats().minLength long, in their order (its input unchanged with LENGTH_FILTER_NONE).
    With FILTER_THEN_MERGE stage 1's input is baseSegments; with MERGE_THEN_FILTER (default) it is
    mergedSegments, and filteredSegments are the lines detect() returned.
    @param groupLabels Output N2 x 1 CV_32S, one label per segment entering stage 2 (filteredSegments
    with FILTER_THEN_MERGE, baseSegments with MERGE_THEN_FILTER), in their order: -1 for a segment
    alone in its group, otherwise its group's number in [0, getLastStats().mergeGroups), groups
    numbered in the order of their first segment. Empty with MERGE_NONE (stages 2 and 3 skipped).
    @param mergedSegments Output CV_32FC4: stage 3's output, the fused segments group by group (its
    input unchanged with MERGE_NONE). With FILTER_THEN_MERGE these are the lines detect() returned.

    The arrays describe the last call that succeeded (a rejected call changes nothing) and are
    empty before the first. Counts match getLastStats(): baseSegments, filteredSegments and
    mergedSegments. Cost: detect() keeps these outputs in its reused buffers at no extra cost; this
    call copies them (and labels the groups) each time it is called, O(N0).
    */
    CV_WRAP virtual void getLastStageOutputs(OutputArray baseSegments, OutputArray filteredSegments,
                                             OutputArray groupLabels, OutputArray mergedSegments) const = 0;

    /** @brief Sets the refinement of the base LSD.
    @param refine One of cv::LineSegmentDetectorModes: LSD_REFINE_NONE, LSD_REFINE_STD or
    LSD_REFINE_ADV. Default LSD_REFINE_NONE.
    @note OpenCV's LSD, and the paper's base, use LSD_REFINE_STD at scale 0.8: LSD_REFINE_NONE at
    scale 1 scores a higher F on YorkUrban and costs about 1.4 times as much (see the class note,
    doc/parameter_sweep.md, doc/performance.md). */
    CV_WRAP virtual void setLsdRefine(int refine) = 0;
    /** @brief Returns the refinement of the base LSD (setLsdRefine()).
    @return One of cv::LineSegmentDetectorModes. */
    CV_WRAP virtual int getLsdRefine() const = 0;
    /** @brief Sets the scale at which the base LSD reads the image.
    @param scale Scale factor, in (0, 1]. Default 1.0 (OpenCV's LSD: 0.8, see setLsdRefine()). */
    CV_WRAP virtual void setLsdScale(double scale) = 0;
    /** @brief Returns the scale at which the base LSD reads the image (setLsdScale()).
    @return Scale factor, in (0, 1]. */
    CV_WRAP virtual double getLsdScale() const = 0;
    /** @brief Sets the Gaussian smoothing of the base LSD, used only when its scale is below 1.
    @param sigmaScale The Gaussian sigma is sigmaScale / scale, in pixels; in (0, 100]. Default 0.6
    (OpenCV's). */
    CV_WRAP virtual void setLsdSigmaScale(double sigmaScale) = 0;
    /** @brief Returns the sigma scale of the base LSD (setLsdSigmaScale()).
    @return sigmaScale, in (0, 100]. */
    CV_WRAP virtual double getLsdSigmaScale() const = 0;
    /** @brief Sets the bound to the quantization error on the gradient norm of the base LSD.
    @param quant Gray levels, in [0, 255]. Default 2.0 (OpenCV's). */
    CV_WRAP virtual void setLsdQuant(double quant) = 0;
    /** @brief Returns the quantization bound of the base LSD (setLsdQuant()).
    @return Gray levels, in [0, 255]. */
    CV_WRAP virtual double getLsdQuant() const = 0;
    /** @brief Sets the gradient angle tolerance of the base LSD's region growing.
    @param degrees Degrees, in (0, 180). Default 22.5 (OpenCV's). */
    CV_WRAP virtual void setLsdAngleTolerance(double degrees) = 0;
    /** @brief Returns the gradient angle tolerance of the base LSD (setLsdAngleTolerance()).
    @return Degrees, in (0, 180). */
    CV_WRAP virtual double getLsdAngleTolerance() const = 0;
    /** @brief Sets the detection threshold of the base LSD, used only with LSD_REFINE_ADV.
    @param logEps A segment is kept when -log10(NFA) > logEps; in [-1000, 1000]. Default 0
    (OpenCV's). */
    CV_WRAP virtual void setLsdLogEps(double logEps) = 0;
    /** @brief Returns the detection threshold of the base LSD (setLsdLogEps()).
    @return logEps, in [-1000, 1000]. */
    CV_WRAP virtual double getLsdLogEps() const = 0;
    /** @brief Sets the minimal density of aligned points in a region's rectangle, used with
    LSD_REFINE_STD and LSD_REFINE_ADV.
    @param density Share of the rectangle's points, in [0, 1). Default 0.7 (OpenCV's). */
    CV_WRAP virtual void setLsdDensityThreshold(double density) = 0;
    /** @brief Returns the density threshold of the base LSD (setLsdDensityThreshold()).
    @return Share, in [0, 1). */
    CV_WRAP virtual double getLsdDensityThreshold() const = 0;
    /** @brief Sets the number of bins in the base LSD's pseudo-ordering of the gradient modulus.
    @param bins Count, in [1, 65536]. Default 1024 (OpenCV's). */
    CV_WRAP virtual void setLsdNumBins(int bins) = 0;
    /** @brief Returns the number of gradient bins of the base LSD (setLsdNumBins()).
    @return Count, in [1, 65536]. */
    CV_WRAP virtual int getLsdNumBins() const = 0;

    /** @brief Sets the detector of stage 0.
    @param detector One of LSDAdvance::BaseDetector. Default BASE_FAST_LSD.

    Each base has its own parameters (lsd*, fld*, ed*); those of the other bases are kept but
    unused. */
    CV_WRAP virtual void setBaseDetector(int detector) = 0;
    /** @brief Returns the detector of stage 0 (setBaseDetector()).
    @return One of LSDAdvance::BaseDetector. */
    CV_WRAP virtual int getBaseDetector() const = 0;

    /** @brief BASE_FLD: sets the length below which FastLineDetector discards a segment.
    @param pixels Pixels, in [1, 100000]. Default 10 (FastLineDetector's). */
    CV_WRAP virtual void setFldLengthThreshold(int pixels) = 0;
    /** @brief BASE_FLD: returns FastLineDetector's length threshold (setFldLengthThreshold()).
    @return Pixels, in [1, 100000]. */
    CV_WRAP virtual int getFldLengthThreshold() const = 0;
    /** @brief BASE_FLD: sets the distance beyond which a point is an outlier of a hypothesis line.
    @param pixels Pixels, in (0, 100]. Default 1.414213562 (FastLineDetector's). */
    CV_WRAP virtual void setFldDistanceThreshold(double pixels) = 0;
    /** @brief BASE_FLD: returns FastLineDetector's outlier distance (setFldDistanceThreshold()).
    @return Pixels, in (0, 100]. */
    CV_WRAP virtual double getFldDistanceThreshold() const = 0;
    /** @brief BASE_FLD: sets the first hysteresis threshold of FastLineDetector's Canny.
    @param threshold Gradient magnitude, in (0, 100000]. Default 50 (FastLineDetector's). */
    CV_WRAP virtual void setFldCannyThreshold1(double threshold) = 0;
    /** @brief BASE_FLD: returns the first Canny threshold (setFldCannyThreshold1()).
    @return Gradient magnitude, in (0, 100000]. */
    CV_WRAP virtual double getFldCannyThreshold1() const = 0;
    /** @brief BASE_FLD: sets the second hysteresis threshold of FastLineDetector's Canny.
    @param threshold Gradient magnitude, in (0, 100000]. Default 50 (FastLineDetector's). */
    CV_WRAP virtual void setFldCannyThreshold2(double threshold) = 0;
    /** @brief BASE_FLD: returns the second Canny threshold (setFldCannyThreshold2()).
    @return Gradient magnitude, in (0, 100000]. */
    CV_WRAP virtual double getFldCannyThreshold2() const = 0;
    /** @brief BASE_FLD: sets the aperture of the Sobel operator of FastLineDetector's Canny.
    @param size 3, 5 or 7 (pixels). Default 3 (FastLineDetector's). */
    CV_WRAP virtual void setFldCannyApertureSize(int size) = 0;
    /** @brief BASE_FLD: returns the Sobel aperture of Canny (setFldCannyApertureSize()).
    @return 3, 5 or 7. */
    CV_WRAP virtual int getFldCannyApertureSize() const = 0;
    /** @brief BASE_FLD: switches FastLineDetector's own incremental merging of segments.
    @param merge true to let FastLineDetector merge. Default false (FastLineDetector's): stage 3
    merges, and FLD's merging costs about 20 times its detection (README, "Results"). */
    CV_WRAP virtual void setFldDoMerge(bool merge) = 0;
    /** @brief BASE_FLD: returns whether FastLineDetector merges (setFldDoMerge()).
    @return true when FastLineDetector's merging is on. */
    CV_WRAP virtual bool getFldDoMerge() const = 0;

    /** @brief BASE_EDLINES: sets EdgeDrawing's gradient operator.
    @param op One of cv::ximgproc::EdgeDrawing::GradientOperator: PREWITT = 0, SOBEL = 1,
    SCHARR = 2, LSD = 3. Default PREWITT (EdgeDrawing's). */
    CV_WRAP virtual void setEdGradientOperator(int op) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's gradient operator (setEdGradientOperator()).
    @return One of cv::ximgproc::EdgeDrawing::GradientOperator. */
    CV_WRAP virtual int getEdGradientOperator() const = 0;
    /** @brief BASE_EDLINES: sets the gradient below which a pixel is not an edge.
    @param threshold Gray levels summed over the operator, in [1, 10000]. Default 20
    (EdgeDrawing's). */
    CV_WRAP virtual void setEdGradientThreshold(int threshold) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's gradient threshold (setEdGradientThreshold()).
    @return Gray levels summed over the operator, in [1, 10000]. */
    CV_WRAP virtual int getEdGradientThreshold() const = 0;
    /** @brief BASE_EDLINES: sets by how much an anchor's gradient must exceed its neighbours'.
    @param threshold Gray levels summed over the operator, in [0, 10000]. Default 0
    (EdgeDrawing's). */
    CV_WRAP virtual void setEdAnchorThreshold(int threshold) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's anchor threshold (setEdAnchorThreshold()).
    @return Gray levels summed over the operator, in [0, 10000]. */
    CV_WRAP virtual int getEdAnchorThreshold() const = 0;
    /** @brief BASE_EDLINES: sets the rows and columns where anchors are sought.
    @param interval Every interval-th row and column, in [1, 100]. Default 1 (EdgeDrawing's). */
    CV_WRAP virtual void setEdScanInterval(int interval) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's anchor scan interval (setEdScanInterval()).
    @return Rows and columns, in [1, 100]. */
    CV_WRAP virtual int getEdScanInterval() const = 0;
    /** @brief BASE_EDLINES: sets the length of the shortest edge chain kept.
    @param pixels Pixels, in [2, 100000]. Default 10 (EdgeDrawing's). */
    CV_WRAP virtual void setEdMinPathLength(int pixels) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's shortest edge chain (setEdMinPathLength()).
    @return Pixels, in [2, 100000]. */
    CV_WRAP virtual int getEdMinPathLength() const = 0;
    /** @brief BASE_EDLINES: sets the sigma of the Gaussian smoothing before the gradient.
    @param sigma Pixels, in [0, 100]; below 1 the image is not smoothed. Default 1.0
    (EdgeDrawing's). */
    CV_WRAP virtual void setEdSigma(double sigma) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's smoothing sigma (setEdSigma()).
    @return Pixels, in [0, 100]. */
    CV_WRAP virtual double getEdSigma() const = 0;
    /** @brief BASE_EDLINES: sets whether only lines validated by the number of false alarms are kept.
    @param validate true to validate. Default true (EdgeDrawing's). */
    CV_WRAP virtual void setEdNfaValidation(bool validate) = 0;
    /** @brief BASE_EDLINES: returns whether EdgeDrawing validates lines (setEdNfaValidation()).
    @return true when NFA validation is on. */
    CV_WRAP virtual bool getEdNfaValidation() const = 0;
    /** @brief BASE_EDLINES: sets the length of the shortest line fitted.
    @param pixels -1 (default, EdgeDrawing's) computes it from the image size as EdgeDrawing does;
    otherwise pixels, in [9, 100000] (EdgeDrawing never fits shorter). */
    CV_WRAP virtual void setEdMinLineLength(int pixels) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's shortest line (setEdMinLineLength()).
    @return -1 (from the image size) or pixels, in [9, 100000]. */
    CV_WRAP virtual int getEdMinLineLength() const = 0;
    /** @brief BASE_EDLINES: sets the largest distance of an edge pixel to its fitted line.
    @param pixels Pixels, in (0, 100]. Default 1.0 (EdgeDrawing's). */
    CV_WRAP virtual void setEdLineFitErrorThreshold(double pixels) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's line fit error (setEdLineFitErrorThreshold()).
    @return Pixels, in (0, 100]. */
    CV_WRAP virtual double getEdLineFitErrorThreshold() const = 0;
    /** @brief BASE_EDLINES: EdgeDrawing joins two collinear lines whose ends are closer than this
    (and whose joined line fits both within getEdMaxErrorThreshold).
    @param pixels Pixels, in (0, 1000]. Default 6.0 (EdgeDrawing's). */
    CV_WRAP virtual void setEdMaxDistanceBetweenTwoLines(double pixels) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's joining distance
    (setEdMaxDistanceBetweenTwoLines()).
    @return Pixels, in (0, 1000]. */
    CV_WRAP virtual double getEdMaxDistanceBetweenTwoLines() const = 0;
    /** @brief BASE_EDLINES: EdgeDrawing joins two lines (see setEdMaxDistanceBetweenTwoLines) only
    when the joined line fits both within this error.
    @param pixels Pixels, in (0, 100]. Default 1.3 (EdgeDrawing's). */
    CV_WRAP virtual void setEdMaxErrorThreshold(double pixels) = 0;
    /** @brief BASE_EDLINES: returns EdgeDrawing's joining error (setEdMaxErrorThreshold()).
    @return Pixels, in (0, 100]. */
    CV_WRAP virtual double getEdMaxErrorThreshold() const = 0;

    /** @brief Sets how stage 1 (adaptive length suppression) runs.
    @param mode One of LSDAdvance::LengthFilterMode. Default LENGTH_FILTER_INTERFRAME (the
    paper's). */
    CV_WRAP virtual void setLengthFilterMode(int mode) = 0;
    /** @brief Returns the mode of stage 1 (setLengthFilterMode()).
    @return One of LSDAdvance::LengthFilterMode. */
    CV_WRAP virtual int getLengthFilterMode() const = 0;

    /** @brief Sets the rule of stage 1's length threshold.
    @param rule One of LSDAdvance::LengthThresholdRule. Default LENGTH_THRESHOLD_CAPPED.
    @note The paper's rule is LENGTH_THRESHOLD_PAPER; see LENGTH_THRESHOLD_CAPPED for why the
    default differs. */
    CV_WRAP virtual void setLengthThreshold(int rule) = 0;
    /** @brief Returns the rule of stage 1's length threshold (setLengthThreshold()).
    @return One of LSDAdvance::LengthThresholdRule. */
    CV_WRAP virtual int getLengthThreshold() const = 0;
    /** @brief Sets the factor applied to stage 1's threshold (before @f$\alpha@f$).
    @param scale In (0, 10]. Default 1. Below 1 the filter keeps more, shorter segments: for LBD line
    matching 0.5 doubles the correct matches at the defaults' matching precision, with about twice
    the segments (doc/matching.md); LENGTH_FILTER_NONE keeps all of them. */
    CV_WRAP virtual void setLengthThresholdScale(double scale) = 0;
    /** @brief Returns the factor applied to stage 1's threshold (setLengthThresholdScale()).
    @return Factor, in (0, 10]. */
    CV_WRAP virtual double getLengthThresholdScale() const = 0;

    /** @brief Sets how stage 3 fuses the segments of a group.
    @param strategy One of LSDAdvance::MergeStrategy. Default MERGE_LONGEST_FIRST.
    @note The paper's rule is MERGE_BASELINES. */
    CV_WRAP virtual void setMergeStrategy(int strategy) = 0;
    /** @brief Returns the strategy of stage 3 (setMergeStrategy()).
    @return One of LSDAdvance::MergeStrategy. */
    CV_WRAP virtual int getMergeStrategy() const = 0;
    /** @brief Sets the order of the stages.
    @param order One of LSDAdvance::StageOrder. Default MERGE_THEN_FILTER.
    @note The paper's order is FILTER_THEN_MERGE. */
    CV_WRAP virtual void setStageOrder(int order) = 0;
    /** @brief Returns the order of the stages (setStageOrder()).
    @return One of LSDAdvance::StageOrder. */
    CV_WRAP virtual int getStageOrder() const = 0;

    /** @brief Sets the width of the angle bins of stage 2.
    @param degrees Degrees, in [1, 90]. Default 10 (the paper's).

    The undirected angle range [0, 180) is cut into ceil(180 / width) bins; when the width
    does not divide 180 the last bin is narrower. */
    CV_WRAP virtual void setAngleBinWidth(double degrees) = 0;
    /** @brief Returns the width of the angle bins (setAngleBinWidth()).
    @return Degrees, in [1, 90]. */
    CV_WRAP virtual double getAngleBinWidth() const = 0;
    /** @brief Sets which angle bins group together in stage 2.
    @param binning One of LSDAdvance::AngleBinning. Default ANGLE_BINS_NEIGHBOURS.
    @note The paper's rule is ANGLE_BINS_STRICT; see ANGLE_BINS_NEIGHBOURS. */
    CV_WRAP virtual void setAngleBinning(int binning) = 0;
    /** @brief Returns which angle bins group together (setAngleBinning()).
    @return One of LSDAdvance::AngleBinning. */
    CV_WRAP virtual int getAngleBinning() const = 0;
    /** @brief Sets the endpoint distance of stage 2: two segments (of the same or a paired angle
    bin) are adjacent when an endpoint of one is closer than this to an endpoint of the other.
    @param pixels Pixels, in [0.1, 200]. Default 10.
    @note The paper gives no value: 10 px was chosen by measurement (doc/parameter_sweep.md). */
    CV_WRAP virtual void setEndpointDistance(double pixels) = 0;
    /** @brief Returns the endpoint distance of stage 2 (setEndpointDistance()).
    @return Pixels, in [0.1, 200]. */
    CV_WRAP virtual double getEndpointDistance() const = 0;

    /** @brief With MERGE_BASELINES, sets which segments of a group are baselines: those at least
    this share of the group's longest. Unused by the other strategies.
    @param ratio Share of the longest segment's length, in (0, 1]. Default 0.8 (the paper's). */
    CV_WRAP virtual void setBaselineRatio(double ratio) = 0;
    /** @brief Returns the baseline ratio (setBaselineRatio()).
    @return Share of the longest segment's length, in (0, 1]. */
    CV_WRAP virtual double getBaselineRatio() const = 0;
    /** @brief Sets the weight @f$w_d@f$ of the direction term of stage 3's score.
    @param weight In [0, 1]. Default 0.4 (the paper's). The weights need not sum to 1: the
    highest score is their sum (0.95 by default). */
    CV_WRAP virtual void setDirectionWeight(double weight) = 0;
    /** @brief Returns the weight of the direction term (setDirectionWeight()).
    @return In [0, 1]. */
    CV_WRAP virtual double getDirectionWeight() const = 0;
    /** @brief Sets the weight @f$w_p@f$ of the proximity term of stage 3's score.
    @param weight In [0, 1]. Default 0.35 (the paper's). */
    CV_WRAP virtual void setProximityWeight(double weight) = 0;
    /** @brief Returns the weight of the proximity term (setProximityWeight()).
    @return In [0, 1]. */
    CV_WRAP virtual double getProximityWeight() const = 0;
    /** @brief Sets the weight @f$w_l@f$ of the length term of stage 3's score.
    @param weight In [0, 1]. Default 0.2 (the paper's). */
    CV_WRAP virtual void setLengthWeight(double weight) = 0;
    /** @brief Returns the weight of the length term (setLengthWeight()).
    @return In [0, 1]. */
    CV_WRAP virtual double getLengthWeight() const = 0;
    /** @brief Sets the proximity distance of stage 3: @f$D_{th}@f$ = ratio times the mean length
    of the two segments; the proximity term @f$1 - D_{min}/D_{th}@f$ reaches 0 there, and
    farther segments never fuse.
    @param ratio Share of the pair's mean length, in (0, 10]. Default 1.0.
    @note The paper uses 0.1; 1.0 was chosen by measurement (doc/parameter_sweep.md). */
    CV_WRAP virtual void setProximityRatio(double ratio) = 0;
    /** @brief Returns the proximity ratio (setProximityRatio()).
    @return Share of the pair's mean length, in (0, 10]. */
    CV_WRAP virtual double getProximityRatio() const = 0;
    /** @brief Sets the merge threshold: a segment fuses into a longer one (its baseline with
    MERGE_BASELINES) when its score reaches this, it lies closer than @f$D_{th}@f$
    (setProximityRatio()) and it passes the gate of setMaxPerpendicularOffset().
    @param threshold Score, in [0, 1]. Default 0.6.
    @note Not in the paper, which gives neither a threshold nor the distance condition
    @f$D_{min} < D_{th}@f$: 0.6 was chosen by measurement (doc/parameter_sweep.md), and the
    distance condition keeps direction and length alone (up to 0.6 with the default weights) from
    joining pieces far apart. */
    CV_WRAP virtual void setMergeThreshold(double threshold) = 0;
    /** @brief Returns the merge threshold (setMergeThreshold()).
    @return Score, in [0, 1]. */
    CV_WRAP virtual double getMergeThreshold() const = 0;
    /** @brief Sets the perpendicular gate of stage 3: a segment fuses into a longer one only when
    both its endpoints lie within this distance of the longer one's supporting line.
    @param pixels Pixels, in [0, 100]. Default 1.5.
    @note Not in the paper: the gate keeps two parallel edges 2 px apart from fusing; 1.5 px was
    chosen by measurement (doc/parameter_sweep.md). */
    CV_WRAP virtual void setMaxPerpendicularOffset(double pixels) = 0;
    /** @brief Returns the perpendicular gate of stage 3 (setMaxPerpendicularOffset()).
    @return Pixels, in [0, 100]. */
    CV_WRAP virtual double getMaxPerpendicularOffset() const = 0;
};

/** @brief Creates an LSDAdvance detector; every other parameter has its documented default.

@param lengthFilterMode Stage 1 mode, one of LSDAdvance::LengthFilterMode. Default LENGTH_FILTER_INTERFRAME.
@param endpointDistance Endpoint adjacency distance of stage 2, pixels, in [0.1, 200]. Default 10.
@param mergeThreshold Score a segment needs to fuse into a longer one, in [0, 1]. Default 0.6.
@return A new detector with an empty sequence. Throws cv::Exception, naming the parameter and
its valid range, when an argument is out of range.
*/
CV_EXPORTS_W Ptr<LSDAdvance> createLSDAdvance(int lengthFilterMode = LSDAdvance::LENGTH_FILTER_INTERFRAME,
                                              double endpointDistance = 10.0,
                                              double mergeThreshold = 0.6);

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
/** @brief Converts segments to KeyLines of octave 0, field by field as
cv::line_descriptor::LSDDetector does, for the LBD descriptor (@cite LBD) and its matcher.

@param lines Segments, N x 1 or 1 x N CV_32FC4 (std::vector<cv::Vec4f>), (x1, y1, x2, y2) in
pixels, finite.
@param imageSize Size of the image they were detected in, both sides at least 1 px.
@param keylines Output, one KeyLine per segment in the same order. Each coordinate is first clamped
as LSDDetector clamps it: below 0 it becomes 0, at or beyond the width (height) it becomes
width - 1 (height - 1); then `startPoint*` and
`sPointInOctave*` are the first endpoint, `endPoint*` and `ePointInOctave*` the second, `pt` the
midpoint, `lineLength` the length in pixels, `angle` = atan2(dy, dx) in radians in (-pi, pi],
`size` = dx * dy (LSDDetector's definition, signed), `numOfPixels` the number of pixels of the
8-connected digital line between the endpoints, `octave` 0, `class_id` the index of the segment,
and `response` = lineLength / max(width, height), in [0, sqrt(2)]: the longer the line, the
higher, so it ranks lines by the length that makes them stable to track and distinctive to
describe.
*/
CV_EXPORTS void linesToKeyLines(InputArray lines, Size imageSize, std::vector<line_descriptor::KeyLine>& keylines);

/** @brief Converts KeyLines back to segments.

@param keylines KeyLines of any octave.
@param lines Output N x 1 CV_32FC4 (std::vector<cv::Vec4f> works), in the same order:
(x1, y1, x2, y2) = (startPointX, startPointY, endPointX, endPointY), pixels. The octave copies
are ignored: the full-resolution endpoints are used whatever the octave. */
CV_EXPORTS void keyLinesToLines(const std::vector<line_descriptor::KeyLine>& keylines, OutputArray lines);
#endif

//! @} lsd_advance

}} // namespace cv::ximgproc

#endif
