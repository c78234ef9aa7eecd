// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Internal interface of the LSDAdvance pipeline: one pure function per stage, plain data in and
// out, so that each stage can be tested alone. Exported only for the module's own tests.

#ifndef OPENCV_LSD_ADVANCE_STAGES_HPP
#define OPENCV_LSD_ADVANCE_STAGES_HPP

#include "opencv2/core.hpp"
#include "opencv2/imgproc.hpp"
#include <vector>

namespace cv {
namespace ximgproc {
namespace lsda {

//--- stage 0: base detection (base_detector.cpp)

//! Parameters of cv::createLineSegmentDetector, in its argument order. refine and scale
//! differ from LSD's defaults: chosen by measurement (doc/parameter_sweep.md).
struct LsdParams
{
    int refine = LSD_REFINE_NONE;
    double scale = 1.0;
    double sigmaScale = 0.6;
    double quant = 2.0;
    double angleTolerance = 22.5;
    double logEps = 0.0;
    double densityThreshold = 0.7;
    int numBins = 1024;
};

//! Returns the image as CV_8UC1 (a view when it already is); throws on any other input.
CV_EXPORTS Mat toGray8U(InputArray image);

//! Parameters of cv::ximgproc::createFastLineDetector, in its argument order, with its defaults.
struct FldParams
{
    int lengthThreshold = 10;
    double distanceThreshold = 1.414213562;
    double cannyThreshold1 = 50.0;
    double cannyThreshold2 = 50.0;
    int cannyApertureSize = 3;
    bool doMerge = false;
};

//! The EdgeDrawing::Params that matter for lines, with EdgeDrawing's defaults.
struct EdParams
{
    int gradientOperator = 0;  // EdgeDrawing::PREWITT
    int gradientThreshold = 20;
    int anchorThreshold = 0;
    int scanInterval = 1;
    int minPathLength = 10;
    double sigma = 1.0;
    bool nfaValidation = true;
    int minLineLength = -1;  // computed from the image size
    double lineFitErrorThreshold = 1.0;
    double maxDistanceBetweenTwoLines = 6.0;
    double maxErrorThreshold = 1.3;
};

enum class BaseKind
{
    LSD,
    FLD,
    EDLINES,
    FAST_LSD
};

//! Stage 0 behind one interface: OpenCV's detectors, constructed once and reused frame to frame.
class CV_EXPORTS BaseSegmentDetector
{
public:
    virtual ~BaseSegmentDetector() {}
    //! Segments of a CV_8UC1 image, oriented brighter side on the left.
    virtual void detect(const Mat& gray, std::vector<Vec4f>& segments) = 0;
};

CV_EXPORTS Ptr<BaseSegmentDetector> createBaseDetector(BaseKind kind, const LsdParams& lsd,
                                                       const FldParams& fld, const EdParams& ed);

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

enum class LengthThreshold
{
    PAPER,   //!< (1 - |mean - std| / mean) * mean * alpha, clamped at 0
    CAPPED   //!< min(mean, std) * alpha: the paper's value while std <= mean, then mean
};

//! Length threshold of the segments' lengths (mean, population std); 0 for no segments.
CV_EXPORTS double adaptiveMinLength(const std::vector<Vec4f>& segments, double alpha,
                                    LengthThreshold rule = LengthThreshold::PAPER);

//! Copies the segments not shorter than minLength, in their order.
CV_EXPORTS void dropShortSegments(const std::vector<Vec4f>& segments, double minLength,
                                  std::vector<Vec4f>& kept);

//--- stage 2: angle + endpoint grouping (segment_grouping.cpp)

struct GroupingParams
{
    double angleBinWidth = 10.0;      //!< degrees
    bool neighbourBins = true;        //!< pair bins k-1, k, k+1 (cyclic)
    double endpointDistance = 10.0;   //!< pixels
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
CV_EXPORTS void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params,
                              SegmentGroups& groups, GroupingWorkspace& workspace);

//! The same with a temporary workspace.
CV_EXPORTS void groupSegments(const std::vector<Vec4f>& segments, const GroupingParams& params,
                              SegmentGroups& groups);

//--- stage 3: similarity-ordered merging (segment_merging.cpp)

enum class MergeStrategy
{
    NONE,           //!< no fusion
    BASELINES,      //!< the paper: only segments shorter than baselineRatio x the longest fuse, into the longer ones
    LONGEST_FIRST   //!< every segment, longest first, absorbs the shorter ones that pass
};

struct MergeParams
{
    MergeStrategy strategy = MergeStrategy::LONGEST_FIRST;
    double baselineRatio = 0.8;
    double directionWeight = 0.4;
    double proximityWeight = 0.35;
    double lengthWeight = 0.2;
    double proximityRatio = 1.0;
    double mergeThreshold = 0.6;
    double maxPerpendicularOffset = 1.5;  //!< pixels
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

CV_EXPORTS SimilarityTerms similarityTerms(const Vec4f& baseline, const Vec4f& other,
                                           double proximityRatio);

CV_EXPORTS double similarityScore(const SimilarityTerms& terms, const MergeParams& params);

//! Fuses other into baseline; the result keeps the baseline's orientation.
CV_EXPORTS Vec4f fuseSegments(const Vec4f& baseline, const Vec4f& other);

//! The segments of one group that may still fuse, filed by the start of their projection on a
//! fixed direction, in lanes across it (by the position of their midpoint along the normal),
//! with removal. Two segments are at least as far apart as their projections, and a segment
//! within a perpendicular distance of a base's line has its midpoint in the few lanes that line
//! crosses: merging looks at the segments of those lanes whose projections come near the base's,
//! never at the whole group. This keeps a group of thousands of collinear pieces, or of
//! hundreds of parallel ones (a textured facade), near-linear.
class CV_EXPORTS ProjectionSweep
{
public:
    //! Files the segments geometry[ids[k]], projected on the unit vector direction, in lanes at
    //! least laneWidth px wide (wider when the group would need more lanes than segments).
    void build(const std::vector<Vec4f>& geometry, const std::vector<int>& ids, const Point2d& direction,
               double laneWidth);
    //! Interval [min, max] of the projection of a segment's endpoints on the direction.
    Vec2d project(const Vec4f& segment) const;
    //! Lanes [first, last] holding every segment whose midpoint projects into [low, high] and
    //! lies within maxOffset px of the line through base (all lanes for a point or a base
    //! steeper than 45 degrees to the direction).
    void lanesNear(const Vec4f& base, double low, double high, double maxOffset, int& first, int& last) const;
    //! Removes segment id (an index into geometry); it is no longer visited.
    void remove(int id);
    int lanes() const { return (int)laneStart.size() - 1; }
    //! Positions of lane l are laneBegin(l) .. laneEnd(l) - 1.
    int laneBegin(int lane) const { return laneStart[lane]; }
    int laneEnd(int lane) const { return laneStart[lane + 1]; }
    //! First filed position of the lane whose projection starts at or after value; at least
    //! laneEnd(lane) when none.
    int firstStartingFrom(int lane, double value);
    //! Last filed position of the lane whose projection starts before value; below
    //! laneBegin(lane) when none.
    int lastStartingBefore(int lane, double value);
    int next(int position) { return findNext(position + 1); }
    int previous(int position) { return findPrevious(position - 1); }
    int id(int position) const { return ids[position]; }
    double start(int position) const { return starts[position]; }
    double end(int position) const { return ends[position]; }

private:
    int findNext(int position);
    int findPrevious(int position);

    Point2d direction, normal;
    double laneOrigin = 0, laneSize = 1;
    std::vector<double> starts, ends;
    std::vector<int> ids;
    std::vector<int> laneStart;     //!< compressed rows: the positions of each lane
    std::vector<int> positionOf;    //!< position of each geometry index (-1: not filed)
    std::vector<int> nextFiled;     //!< union-find links to the next filed position (size() is a sentinel)
    std::vector<int> previousFiled; //!< the same backwards, shifted by one (0 is a sentinel)
    std::vector<std::pair<std::pair<int, double>, int> > sortBuffer;
    std::vector<double> across;
};

struct MergeCandidate
{
    double score;
    int segment;   //!< index into the group's members
    int baseline;  //!< index into the group's members; -1 for none
};

//! Buffers of stage 3, reused from group to group and call to call.
struct MergeWorkspace
{
    std::vector<Vec4f> geometry;  //!< the current group's segments, fused in place
    std::vector<char> consumed;
    std::vector<double> length;
    std::vector<int> order, rank, ids;
    std::vector<int> baselines, pending, changed;
    std::vector<char> dirty, isChanged;
    std::vector<MergeCandidate> candidates, bestOf;
    std::vector<std::pair<double, int> > baselineStarts;
    ProjectionSweep sweep;
};

//! Merges each group; output keeps group order, and member order inside a group. The result
//! is that of scoring every pair of the group, computed with the sweep.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const MergeParams& params, std::vector<Vec4f>& merged,
                            MergeWorkspace& workspace);

//! The same with a temporary workspace.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const MergeParams& params, std::vector<Vec4f>& merged);

}}} // namespace cv::ximgproc::lsda

#endif
