// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Internal interface of the LSDAdvance pipeline: one pure function per stage, plain data in and
// out, so that each stage can be tested alone. Exported only for the module's own tests.

#ifndef OPENCV_LSD_ADVANCE_STAGES_HPP
#define OPENCV_LSD_ADVANCE_STAGES_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//--- stage 0: base detection (base_detector.cpp)

//! Returns the image as CV_8UC1 (a view when it already is); throws on any other input.
CV_EXPORTS Mat toGray8U(InputArray image);

//! Stage 0 behind one interface: OpenCV's detectors, constructed once and reused frame to frame.
class CV_EXPORTS BaseSegmentDetector
{
public:
    virtual ~BaseSegmentDetector() {}
    //! Segments of a CV_8UC1 image, oriented brighter side on the left.
    virtual void detect(const Mat& gray, std::vector<Vec4f>& segments) = 0;
};

//! The detector of kind (LSDAdvance::BaseDetector) with its parameters (those of the other kinds
//! are not used).
CV_EXPORTS Ptr<BaseSegmentDetector> createBaseDetector(int kind, const LSDAdvance::LSDParams& lsd,
                                                       const LSDAdvance::FLDParams& fld, const EdgeDrawing::Params& edLines);

//! Turns round each segment on whose right the image is brighter than on its left (sum of 5
//! samples 2 px either side, nearest pixel, samples outside the image skipped).
CV_EXPORTS void orientBrighterLeft(const Mat& gray, std::vector<Vec4f>& segments);

//! Segments of an N x 1 or 1 x N CV_32FC4 array (empty for an empty one); throws on any other
//! layout, naming `what` in the message.
CV_EXPORTS std::vector<Vec4f> toSegments(InputArray lines, const char* what);

//! The same into a caller's buffer (reused from call to call).
CV_EXPORTS void toSegments(InputArray lines, const char* what, std::vector<Vec4f>& segments);

//--- stage 1: adaptive length suppression (length_filter.cpp)

CV_EXPORTS double segmentLength(const Vec4f& segment);

//! The paper's inter-frame factor from the kept counts of frames k-1 and k-2 (jumps at r = -0.1).
CV_EXPORTS double interFrameAlpha(int keptPrevious, int keptBeforePrevious);

//! The same rule made continuous at r = -0.1: 1 + 0.2 (r + 0.1) below, floored at 0.8.
CV_EXPORTS double continuousInterFrameAlpha(int keptPrevious, int keptBeforePrevious);

//! Count tracking: clamp(1 + 0.5 r, 0.8, 1.2) with r the relative difference between the count
//! this frame keeps with alpha = 1 and the mean kept count of frames k-1 and k-2 (1 when that is 0).
CV_EXPORTS double countTrackingAlpha(int provisional, int keptPrevious, int keptBeforePrevious);

//! Number of segments at least minLength long.
CV_EXPORTS int countAtLeast(const std::vector<Vec4f>& segments, double minLength);

//! Length threshold (LSDAdvance::LengthThresholdRule rule) of the segments' lengths (mean,
//! population std), times alpha; 0 for no segments.
CV_EXPORTS double adaptiveMinLength(const std::vector<Vec4f>& segments, double alpha,
                                    int rule = LSDAdvance::LENGTH_THRESHOLD_PAPER);

//! The same rule on responses (lineResponses): the threshold of stage 1's strong segments.
CV_EXPORTS double adaptiveMinResponse(const std::vector<float>& responses, double alpha, int rule);

//! Copies the segments not shorter than minLength, in their order; keptFrom, when given, gets the
//! index in segments of each kept one.
CV_EXPORTS void dropShortSegments(const std::vector<Vec4f>& segments, double minLength,
                                  std::vector<Vec4f>& kept, std::vector<int>* keptFrom = nullptr);

//! Copies, in their order, the segments at least minLength long or, when responses (one per
//! segment) are given, with a response of at least minResponse: long or strong. keptFrom as for
//! dropShortSegments.
CV_EXPORTS void keepLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                                 double minLength, double minResponse, std::vector<Vec4f>& kept,
                                 std::vector<int>* keptFrom = nullptr);

//! Number of segments keepLongOrStrong keeps.
CV_EXPORTS int countLongOrStrong(const std::vector<Vec4f>& segments, const std::vector<float>& responses,
                                 double minLength, double minResponse);

//--- segment responses (line_response.cpp)

//! Mean gray-level step across the segment, its left (brighter) side minus its right side, 1 px
//! either side of its centre line, sampled at the centre of each unit step (bilinear, coordinates
//! clamped into the image); negative steps count 0. Gray levels, in [0, 255].
CV_EXPORTS double meanContrast(const Mat& gray, const Vec4f& segment);

//! Response of each segment: length / max(width, height) * (meanContrast / 255)^2, times 0.1 when
//! an endpoint lies within 2 px of the image's edge or beyond it (the frame cuts the segment).
CV_EXPORTS void lineResponses(const Mat& gray, const std::vector<Vec4f>& segments,
                              std::vector<float>& responses);

//--- stage 2: angle + endpoint grouping (segment_grouping.cpp)

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

//! Buffers of stage 2, reused from call to call so that a sequence of frames does not allocate.
struct GroupingWorkspace
{
    std::vector<int> bin;             //!< angle bin of each segment
    std::vector<int64> tableKeys;     //!< open-addressing hash table: grid cell key ...
    std::vector<int> tableCells;      //!< ... -> dense cell number (-1: empty slot)
    std::vector<int> cellOfEndpoint;  //!< dense cell number of each endpoint
    std::vector<int> cellStart;       //!< endpoints of cell c: cellEndpoints[cellStart[c] .. cellStart[c+1])
    std::vector<int> cellEndpoints;
    std::vector<int> parent;          //!< union-find forest over the segments
    std::vector<int> groupOf;
    std::vector<int> fill;
};

//! Groups in O(n) expected time (a hashed grid of endpoints, union-find).
//! Uses params.angleBinWidth, angleBinning and endpointDistance.
CV_EXPORTS void groupSegments(const std::vector<Vec4f>& segments, const LSDAdvance::Params& params,
                              SegmentGroups& groups, GroupingWorkspace& workspace);

//! The same with a temporary workspace.
CV_EXPORTS void groupSegments(const std::vector<Vec4f>& segments, const LSDAdvance::Params& params,
                              SegmentGroups& groups);

//--- stage 3: similarity-ordered merging (segment_merging.cpp)

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
CV_EXPORTS double similarityScore(const SimilarityTerms& terms, const LSDAdvance::Params& params);

//! Fuses other into baseline; the result keeps the baseline's orientation.
CV_EXPORTS Vec4f fuseSegments(const Vec4f& baseline, const Vec4f& other);

//! Buffers of stage 3, reused from group to group and call to call (segment_merging.hpp).
struct MergeWorkspace;

//! Merges each group with params.mergeStrategy (MERGE_NONE passes the segments on) and the score's parameters;
//! output keeps group order, and member order inside a group; mergedInto gets, for each segment,
//! the index of the merged segment it is part of. The result is that of scoring every pair of
//! the group, computed with the sweep.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const LSDAdvance::Params& params, std::vector<Vec4f>& merged,
                            std::vector<int>& mergedInto, MergeWorkspace& workspace);

//! The same with a temporary workspace, without mergedInto.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const LSDAdvance::Params& params, std::vector<Vec4f>& merged);

//--- after the stages: clipping to the image (image_clipping.cpp)

//! The part of segment inside the image domain [-0.5, W-0.5] x [-0.5, H-0.5], along its line and
//! in its direction: segment itself when it lies inside; false when nothing of positive length
//! is left (a point is dropped even inside).
CV_EXPORTS bool clipToDomain(const Vec4f& segment, const Size& imageSize, Vec4f& clipped);

//! clipToDomain() on each segment; keptFrom gets the index in segments of each one kept.
CV_EXPORTS void clipToImage(const std::vector<Vec4f>& segments, const Size& imageSize,
                            std::vector<Vec4f>& clipped, std::vector<int>& keptFrom);

}}} // namespace cv::ximgproc::lsda

#endif
