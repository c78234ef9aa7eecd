// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Internal interface of the LSDAdvance pipeline: one file per stage, plain data in and out, each
// stage with the parameters it reads only, so that each can be tested alone. This is the only
// internal header the tests include: the CV_EXPORTS functions below, which the module's tests call
// directly, and through fast_lsd/fast_lsd.hpp the class of BASE_FAST_LSD, whose tiles they check.

#ifndef OPENCV_LSD_ADVANCE_STAGES_HPP
#define OPENCV_LSD_ADVANCE_STAGES_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "fast_lsd/fast_lsd.hpp"
#include "opencv_lsd.hpp"
#include "primitives.hpp"
#include <algorithm>
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//--- the callers' arrays (segment_io.cpp)

//! Returns the image as CV_8UC1 (a view when it already is); throws on any other input, the
//! message starting with `what`.
Mat toGray8U(InputArray image, const char* what = "LSDAdvance");

//! Segments of an N x 1 or 1 x N CV_32FC4 array (empty for an empty one) into a caller's buffer;
//! throws on any other layout, naming `what` in the message.
void toSegments(InputArray lines, const char* what, std::vector<Vec4f>& segments);

//! The same into a new vector.
std::vector<Vec4f> toSegments(InputArray lines, const char* what);

//! Larger coordinates are not image coordinates; bounding them keeps the grouping grid's cells
//! within 32 bits.
constexpr double kMaxCoordinate = 1e7;

//! toSegments(), also throwing on a coordinate that is not finite or not within kMaxCoordinate.
void toImageSegments(InputArray lines, const char* what, std::vector<Vec4f>& segments);

//! LSDAdvance::drawSegments(): the segments in red, 1 px wide, on a gray (made BGR) or BGR image.
void drawSegments(InputOutputArray image, InputArray lines);

//--- the mask (image_mask.cpp)

//! The mask of a call as a CV_8UC1 view of imageSize, empty for none (an empty array); throws on
//! another type or size, naming `what`.
Mat toMask(InputArray mask, Size imageSize, const char* what);

//! Whether the mask is set at every sample from a to b (at most 1 px apart, both ends included;
//! each sample reads the pixel nearest to it, clamped into the image).
CV_EXPORTS bool inMask(const Mat& mask, const Point2d& a, const Point2d& b);

//! Cuts each segment at a non-empty mask, keeping its pieces on it, in order and orientation: the
//! segment's part inside the image (clipToDomain) is sampled as inMask() samples it, and each run
//! of two or more samples on the mask is a piece from its first sample to its last; a segment
//! wholly on the mask is kept unchanged. pieces is a buffer.
CV_EXPORTS void cutAtMask(const Mat& mask, std::vector<Vec4f>& segments, std::vector<Vec4f>& pieces);

//--- stage 0: base detection (base_detector.cpp)

//! Stage 0 behind one interface: OpenCV's detectors, constructed once and reused frame to frame.
//! Each takes any non-empty CV_8UC1 image: one its detector cannot read has no segment.
class BaseSegmentDetector
{
public:
    virtual ~BaseSegmentDetector() {}
    //! Segments of a CV_8UC1 image, oriented brighter side on the left.
    virtual void detect(const Mat& gray, std::vector<Vec4f>& segments) = 0;
    //! The segments on a mask (toMask(); empty for none), before the pipeline's cut at it
    //! (cutAtMask()): those of detect(), the detector reading the mask itself when it can
    //! (BASE_FAST_LSD: no segment crosses a masked-out pixel's gradient).
    virtual void detectReadingMask(const Mat& gray, const Mat& mask, std::vector<Vec4f>& segments)
    {
        CV_UNUSED(mask);
        detect(gray, segments);
    }
};

//! The detector of kind (LSDAdvance::BaseDetector) with its parameters (those of the other kinds
//! are not used).
CV_EXPORTS Ptr<BaseSegmentDetector> createBaseDetector(int kind, const LSDAdvance::LSDParams& lsd,
                                                       const LSDAdvance::FLDParams& fld, const EdgeDrawing::Params& edLines);

//! LSD's segments at LSDParams::scale (OpenCV's and FastLsd's) are the coordinates in the scaled
//! image divided by the scale; this moves them onto the full image's pixel-centre convention
//! (0.5 (1 / scale - 1) px along both axes: 0.5 px at scale 0.5). Both LSD bases call it.
CV_EXPORTS void toFullResolution(std::vector<Vec4f>& segments, double scale);

//! Turns round each segment on whose right the image is brighter than on its left (sum of 5
//! samples 2 px either side, nearest pixel, samples outside the image skipped).
CV_EXPORTS void orientBrighterLeft(const Mat& gray, std::vector<Vec4f>& segments);

//--- segment responses (line_response.cpp)

//! Response of each segment: length / max(width, height) * (mean contrast / 255)^2, times 0.1 when
//! an endpoint lies within 2 px of the image's edge or beyond it (computeLineResponses()).
CV_EXPORTS void lineResponses(const Mat& gray, const std::vector<Vec4f>& segments,
                              std::vector<float>& responses);

//! The responses (lineResponses()) known so far for the segments of the current stage of a call,
//! followed through the stages: a segment a stage hands on unchanged, bit for bit, keeps its
//! response, so that no segment is sampled twice in a call.
class KnownResponses
{
public:
    //! None known (a new call).
    void clear();
    //! After a stage that made each out[j] of in[keptFrom[j]] (kept, or clipped; -1: of none).
    void followKept(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out, const std::vector<int>& keptFrom);
    //! After a stage that made each in[i] part of out[mergedInto[i]].
    void followMerged(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out, const std::vector<int>& mergedInto);
    //! The responses of segments, the current stage's, on gray: those not known yet are computed.
    const std::vector<float>& complete(const Mat& gray, const std::vector<Vec4f>& segments);

private:
    std::vector<float> known;  //!< one per segment of the current stage, -1 when not known; empty: none
    std::vector<float> carried;
    std::vector<int> pieceOf;
};

//--- stage 1: adaptive length suppression (length_filter.cpp)

//! The rows of LSDAdvance::Params that stage 1 reads.
struct LengthFilterParams
{
    explicit LengthFilterParams(const LSDAdvance::Params& p = LSDAdvance::Params())
        : lengthFilterMode(p.lengthFilterMode), lengthThresholdRule(p.lengthThresholdRule),
          lengthThresholdScale(p.lengthThresholdScale), keepStrongSegments(p.keepStrongSegments)
    {}
    int lengthFilterMode, lengthThresholdRule;
    double lengthThresholdScale;
    bool keepStrongSegments;
};

//! What stage 1 kept in the two previous frames of a sequence: the state of the inter-frame modes.
struct KeptCounts
{
    int frames = 0;                          //!< frames of the sequence so far, counted up to 2
    int previous = 0, beforePrevious = 0;    //!< kept in frames k-1 and k-2
    void add(int kept)
    {
        beforePrevious = previous;
        previous = kept;
        frames = std::min(frames + 1, 2);
    }
};

CV_EXPORTS double segmentLength(const Vec4f& segment);

//! Wall-clock milliseconds since a getTickCount(): the stages' times in LSDAdvanceStats.
inline double elapsedMs(int64 since)
{
    return (double)(getTickCount() - since) * 1000.0 / getTickFrequency();
}

//! The paper's inter-frame factor from the kept counts of frames k-1 and k-2 (jumps at r = -0.1).
CV_EXPORTS double interFrameAlpha(int keptPrevious, int keptBeforePrevious);

//! The same rule made continuous at r = -0.1: 1 + 0.2 (r + 0.1) below, floored at 0.8.
CV_EXPORTS double continuousInterFrameAlpha(int keptPrevious, int keptBeforePrevious);

//! Count tracking: clamp(1 + 0.5 r, 0.8, 1.2) with r the relative difference between the count
//! this frame keeps with alpha = 1 and the mean kept count of frames k-1 and k-2 (1 when that is 0).
CV_EXPORTS double countTrackingAlpha(int provisional, int keptPrevious, int keptBeforePrevious);

//! Length threshold (LSDAdvance::LengthThresholdRule rule) of the segments' lengths (mean,
//! population std), times alpha; 0 for no segments.
CV_EXPORTS double adaptiveMinLength(const std::vector<Vec4f>& segments, double alpha,
                                    int rule = LSDAdvance::LENGTH_THRESHOLD_PAPER);

//! The same rule on responses (lineResponses): the threshold of stage 1's strong segments.
CV_EXPORTS double adaptiveMinResponse(const std::vector<float>& responses, double alpha, int rule);

//! Copies, in their order, the segments at least minLength long or, when responses (one per
//! segment) are given, with a response of at least minResponse: long or strong. keptFrom, when
//! given, gets the index in segments of each kept one.
CV_EXPORTS void keepLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                                 double minLength, double minResponse, std::vector<Vec4f>& kept,
                                 std::vector<int>* keptFrom = nullptr);

//! Number of segments keepLongOrStrong keeps.
CV_EXPORTS int countLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                                 double minLength, double minResponse);

//! Stage 1 of one frame. Its thresholds always come from the frame's base segments (after
//! merging, the lengths are no longer those of one detector's output), and every mode scales
//! them by the frame's alpha; it filters the base segments or what merging made of them.
class LengthFilter
{
public:
    //! The thresholds at alpha = 1 from the base segments: the rule on their lengths, times
    //! lengthThresholdScale, and with keepStrongSegments and an image, the same on their responses
    //! (computed into `known`, which follows the base segments). Without an image (processSegments)
    //! it keeps long segments only.
    void measure(const std::vector<Vec4f>& base, const Mat* gray, const LengthFilterParams& params,
                 KnownResponses& known, LSDAdvanceStats& stats);
    //! Keeps the long (or strong) segments of in, the base segments given to measure() or merging's
    //! output from them, with the alpha of this frame of the sequence history; the responses of in
    //! that `known` (which follows in) lacks are computed into it. keptFrom gets the index in `in` of
    //! each kept one. Fills stats' alpha, minLength, minResponse and filteredSegments; measure() and
    //! apply() add their time to stats.filterMs.
    void apply(const std::vector<Vec4f>& in, const Mat* gray, const KeptCounts& history, KnownResponses& known,
               std::vector<Vec4f>& kept, std::vector<int>& keptFrom, LSDAdvanceStats& stats);

private:
    LengthFilterParams params;
    bool strong = false;  //!< short segments of high response are kept
    double unitMinLength = 0, unitMinResponse = 0;
};

//--- stage 2: angle + endpoint grouping (segment_grouping.cpp)

//! The rows of LSDAdvance::Params that stage 2 reads.
struct GroupingParams
{
    explicit GroupingParams(const LSDAdvance::Params& p = LSDAdvance::Params())
        : angleBinWidth(p.angleBinWidth), angleBinning(p.angleBinning), endpointDistance(p.endpointDistance)
    {}
    double angleBinWidth;
    int angleBinning;
    double endpointDistance;
};

//! Merge groups in compressed form: the members of group g are
//! members[offsets[g]] .. members[offsets[g+1] - 1], in increasing index order; groups are
//! ordered by their smallest member. Every segment is in exactly one group.
struct SegmentGroups
{
    std::vector<int> members;
    std::vector<int> offsets;
    int count() const { return offsets.empty() ? 0 : (int)offsets.size() - 1; }
};

//! Undirected angle bin of a segment: floor(angle / width) for angle in [0, 180).
CV_EXPORTS int angleBin(const Vec4f& segment, double binWidth);

//! angleBin() of each segment into bins, without its atan2 for a segment clearly inside a bin
//! (a cheap guess checked against the directions of the bin's edges); edges is a buffer.
CV_EXPORTS void angleBins(const std::vector<Vec4f>& segments, double binWidth, std::vector<int>& bins,
                          std::vector<Point2d>& edges);

//! Buffers of stage 2, reused from call to call so that a sequence of frames does not allocate.
struct GroupingWorkspace
{
    std::vector<int> bin;             //!< angle bin of each segment
    std::vector<Point2d> binEdges;    //!< directions of the bins' edges
    std::vector<Point> endpointCell;  //!< grid cell (x, y) of each endpoint
    std::vector<int64> tableKeys;     //!< without a dense grid, open-addressing hash table: (bin, cell) key ...
    std::vector<int> tableCells;      //!< ... -> cell number (-1: empty slot)
    std::vector<int> cellOfEndpoint;  //!< (bin, cell) number of each endpoint (in the dense grid or the table)
    std::vector<int> cellStart;       //!< endpoints of cell c: cellEndpoints[cellStart[c] .. cellStart[c+1])
    std::vector<int> cellEndpoints;
    std::vector<int> filedCell;       //!< the cells, points and segments of the endpoints in the order of cellEndpoints
    std::vector<Point2d> filedPoint;
    std::vector<int> filedSegment;
    std::vector<int> queuedFrom, queuedTo;  //!< a batch of comparisons (filed positions) ...
    std::vector<Vec2i> pairs;         //!< ... and of adjacent segments
    UnionFind sets;                   //!< the segments adjacent through their endpoints
    std::vector<int> groupOf;
};

//! Groups in O(n) expected time (a grid of endpoints, dense or hashed, union-find). The parameters are in
//! their ranges (parameters.hpp).
CV_EXPORTS void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params,
                              SegmentGroups& groups, GroupingWorkspace& workspace);

//! The same with a temporary workspace.
inline void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params, SegmentGroups& groups)
{
    GroupingWorkspace workspace;
    groupSegments(segments, params, groups, workspace);
}

//! Number of groups of two or more segments (LSDAdvanceStats::mergeGroups).
int mergeGroupCount(const SegmentGroups& groups);

//! Each segment's number among the groups of two or more, numbered in group order; -1 alone.
void groupLabels(const SegmentGroups& groups, std::vector<int>& labels);

//--- stage 3: similarity-ordered merging (segment_merging.cpp)

//! The rows of LSDAdvance::Params that stage 3 reads.
struct MergingParams
{
    explicit MergingParams(const LSDAdvance::Params& p = LSDAdvance::Params())
        : mergeStrategy(p.mergeStrategy), baselineRatio(p.baselineRatio), directionWeight(p.directionWeight),
          proximityWeight(p.proximityWeight), lengthWeight(p.lengthWeight), proximityRatio(p.proximityRatio),
          mergeThreshold(p.mergeThreshold), maxPerpendicularOffset(p.maxPerpendicularOffset)
    {}
    int mergeStrategy;
    double baselineRatio, directionWeight, proximityWeight, lengthWeight, proximityRatio, mergeThreshold,
        maxPerpendicularOffset;
};

struct SimilarityTerms
{
    double direction;  //!< Sd
    double proximity;  //!< Sp
    double length;     //!< Sl
};

//! Shortest distance between two segments, as the smallest endpoint-to-segment distance.
CV_EXPORTS double segmentDistance(const Vec4f& a, const Vec4f& b);

//! Largest distance of the other segment's endpoints to the baseline's supporting line.
CV_EXPORTS double perpendicularOffset(const Vec4f& baseline, const Vec4f& other);

//! Sd, Sp and Sl of other against baseline (Sp reaches 0 at proximityRatio times their mean length).
CV_EXPORTS SimilarityTerms similarityTerms(const Vec4f& baseline, const Vec4f& other,
                                           double proximityRatio);

//! S = directionWeight Sd + proximityWeight Sp + lengthWeight Sl. The merging sweep's pruning
//! bound (Reach in segment_merging.cpp) is derived from this formula and from
//! similarityTerms(): a change of either must change the bound.
CV_EXPORTS double similarityScore(const SimilarityTerms& terms, const MergingParams& params);

//! Fuses other into baseline: the least-squares line of the two (as uniform masses along their
//! lengths) through their length-weighted centre, spanning the projections of the four
//! endpoints; the result keeps the baseline's orientation.
CV_EXPORTS Vec4f fuseSegments(const Vec4f& baseline, const Vec4f& other);

//! MERGE_LONGEST_FIRST compares each base with every shorter segment of a group of fewer segments,
//! and files a group of at least this many in a projection sweep (segment_merging.hpp), which
//! keeps the work near-linear: with the same result, the sweep's set-up costs more below it.
constexpr int kSweptGroupSize = 256;

//! Buffers of stage 3, reused from group to group and call to call (segment_merging.hpp).
struct MergeWorkspace;

//! Merges each group with params.mergeStrategy (not MERGE_NONE: MergeStage decides it) and the
//! score's parameters; output keeps group order, and member order inside a group; mergedInto gets,
//! for each segment, the index of the merged segment it is part of. The result is that of scoring
//! every pair of the group, computed with the sweep. With a mask (toMask()), two segments fuse only
//! when the gap between them along the line they fuse into is on the mask (inMask()).
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const MergingParams& params, std::vector<Vec4f>& merged,
                            std::vector<int>& mergedInto, MergeWorkspace& workspace, const Mat& mask = Mat());

//! The same with a temporary workspace, without mergedInto.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const MergingParams& params, std::vector<Vec4f>& merged, const Mat& mask = Mat());

//! Stages 2 and 3 of a call, with their buffers: the groups of the input, then each group merged;
//! with MERGE_NONE (decided here only) neither, every segment passed on as it is.
class CV_EXPORTS MergeStage
{
public:
    MergeStage();
    ~MergeStage();
    //! merged gets stage 3's output, mergedInto (for each input segment) the output it is part of;
    //! fills stats' mergeGroups, mergedSegments, groupingMs and mergingMs.
    void apply(const std::vector<Vec4f>& in, const GroupingParams& grouping, const MergingParams& merging,
               const Mat& mask, std::vector<Vec4f>& merged, LSDAdvanceStats& stats);
    //! groupLabels() of the last input's groups; empty with MERGE_NONE.
    void labels(std::vector<int>& groupLabels) const;
    const std::vector<int>& mergedInto() const { return into; }

private:
    bool isGrouped = false;
    SegmentGroups segmentGroups;
    std::vector<int> into;
    GroupingWorkspace groupingBuffers;
    Ptr<MergeWorkspace> mergingBuffers;
};

//--- after the stages: clipping to the image (image_clipping.cpp)

//! The part of segment inside the image domain [-0.5, W-0.5] x [-0.5, H-0.5], along its line and
//! in its direction: segment itself when it lies inside; false when nothing of positive length
//! is left (a point is dropped even inside).
CV_EXPORTS bool clipToDomain(const Vec4f& segment, const Size& imageSize, Vec4f& clipped);

//! clipToDomain() on each segment; keptFrom gets the index in segments of each one kept.
CV_EXPORTS void clipToImage(const std::vector<Vec4f>& segments, const Size& imageSize,
                            std::vector<Vec4f>& clipped, std::vector<int>& keptFrom);

//--- after the clipping: the front end's selection (line_selection.cpp)

//! The rows of LSDAdvance::Params that the selection reads.
struct SelectionParams
{
    explicit SelectionParams(const LSDAdvance::Params& p = LSDAdvance::Params())
        : minLineLength(p.minLineLength), minLineLengthRatio(p.minLineLengthRatio), maxLines(p.maxLines),
          lineOrder(p.lineOrder), directionBins(p.directionBins), gridCells(p.gridCells)
    {}
    double minLineLength, minLineLengthRatio;
    int maxLines, lineOrder, directionBins, gridCells;
};

//! The selection's length threshold: the larger of minLineLength and minLineLengthRatio times
//! min(W, H) of imageSize (the ratio is not used when imageSize is empty); 0 when both are off.
CV_EXPORTS double selectionMinLength(const SelectionParams& params, Size imageSize);

//! Orders keys (one per line) decreasing, equal keys in index order, and keeps the first maxLines
//! (0: all) of the lines in `order`, given as indices into the keys. order is sorted in place.
CV_EXPORTS void strongestFirst(const std::vector<float>& keys, int maxLines, std::vector<int>& order);

//! LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS: `order`, strongest first (strongestFirst() of all of
//! them), is ordered again by the rank of each line among those of its bin, equal ranks strongest
//! first, and cut to the first maxLines (0: all). A bin is one of `bins` bins of the undirected
//! direction (each 180 / bins degrees, the first centred on the horizontal) in one of the cells x
//! cells equal cells of `area` that hold the lines' midpoints (those outside it in the nearest
//! cell). rankInBin gets each line's rank.
CV_EXPORTS void acrossDirections(const std::vector<Vec4f>& lines, int bins, int cells, const Rect2f& area, int maxLines,
                                 std::vector<int>& order, std::vector<int>& rankInBin);

//! The selection of one call: lines shorter than selectionMinLength() are dropped; the others are
//! ordered by SelectionParams::lineOrder on their keys, the responses on gray when given (those
//! `known`, which follows lines, lacks are computed) or else the lengths, and the first maxLines
//! (0: all) are kept. keptFrom gets the index in lines of each kept one, in output order;
//! responses, with gray, their responses (else it is emptied).
class LineSelection
{
public:
    void apply(const std::vector<Vec4f>& lines, const Mat* gray, const SelectionParams& params, Size imageSize,
               KnownResponses& known, std::vector<Vec4f>& selected, std::vector<float>& responses,
               std::vector<int>& keptFrom);

private:
    std::vector<Vec4f> longEnough;
    std::vector<int> longFrom;
    std::vector<float> lengths;
    std::vector<int> order, rankInBin;
};

//--- LBD descriptors of KeyLines (lbd/)

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
//! The gradient computeLBD samples, over the whole image: CV_16SC2 (dx, dy) per pixel, those of
//! cv::Sobel (3 x 3, CV_16S) after cv::GaussianBlur (5 x 5, sigma 1) with their default borders.
CV_EXPORTS void lbdGradient(const Mat& gray, Mat& gradient);

//! computeLBD's descriptors before they are made binary: N x 72 CV_32F, those of
//! line_descriptor::BinaryDescriptor::compute with returnFloatDescr = true. The same checks.
CV_EXPORTS void lbdFloatDescriptors(InputArray image, const std::vector<line_descriptor::KeyLine>& keylines,
                                    OutputArray descriptors);
#endif

//--- through the stages: which returned line each base segment is part of (provenance.cpp)

//! Follows the base segments of a call through the stages for getLastSources(): each stage that
//! keeps a subsequence of its input (keptFrom) or fuses it (mergedInto) is followed in turn.
class SegmentProvenance
{
public:
    //! Each of the base segments is its own line.
    void start(size_t baseCount);
    //! After a stage that kept, of its inputSize segments, those of keptFrom (in order).
    void followKept(const std::vector<int>& keptFrom, size_t inputSize);
    //! After a stage that made of segment i of its input its segment mergedInto[i].
    void followMerged(const std::vector<int>& mergedInto);
    //! For each of the lineCount lines, the increasing indices of the base segments it is made of.
    void sources(int lineCount, OutputArrayOfArrays sources) const;

private:
    std::vector<int> lineOf;  //!< the line each base segment is part of (-1: none)
    std::vector<int> into;
};

//! What follows the segments of a call through its stages (provenance.cpp): the base segments each
//! is made of (getLastSources()) and the responses known so far (responses, which a stage that
//! needs them completes). The orchestrator updates it once after each stage.
class StageTrace
{
public:
    //! The base segments of a call, none of them with a known response.
    void start(const std::vector<Vec4f>& base);
    //! After a stage that made each out[j] of in[keptFrom[j]] (kept, or clipped).
    void followKept(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out, const std::vector<int>& keptFrom);
    //! After a stage that made each in[i] part of out[mergedInto[i]].
    void followMerged(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out, const std::vector<int>& mergedInto);
    //! After the selection, the last stage, which kept, of its inputSize lines, those of keptFrom:
    //! their responses are its output (it completes `responses` for the lines it ranks), the trace's
    //! are spent.
    void followSelected(const std::vector<int>& keptFrom, size_t inputSize);
    //! For each of the lineCount lines, the increasing indices of the base segments it is made of.
    void sources(int lineCount, OutputArrayOfArrays out) const { provenance.sources(lineCount, out); }

    KnownResponses responses;  //!< of the current stage's segments

private:
    SegmentProvenance provenance;
};

}}} // namespace cv::ximgproc::lsda

#endif
