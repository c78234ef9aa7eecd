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

CV_EXPORTS Ptr<LineSegmentDetector> createBaseLsd(const LsdParams& params);

//! Segments of an N x 1 or 1 x N CV_32FC4 array (empty for an empty one); throws on any other
//! layout, naming `what` in the message.
CV_EXPORTS std::vector<Vec4f> toSegments(InputArray lines, const char* what);

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

//! Merges each group; output keeps group order, and member order inside a group.
CV_EXPORTS void mergeGroups(const std::vector<Vec4f>& segments, const SegmentGroups& groups,
                            const MergeParams& params, std::vector<Vec4f>& merged);

}}} // namespace cv::ximgproc::lsda

#endif
