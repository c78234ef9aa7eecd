// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_EVALUATION_HPP
#define OPENCV_LSD_ADVANCE_EVALUATION_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace ximgproc {
/** @brief The evaluation behind LSDAdvance's documented results: the structural precision/recall
protocol, line matching under a homography and between posed frames, and the loaders of the data
sets they run on (YorkUrban-LineSegment, KITTI-style sequences, HPatches-style folders).

Python: cv2.ximgproc.line_evaluation (in-tree) and lsd_advance.line_evaluation (standalone).
contrib's datasets module is not used: it reads none of these layouts (its SLAM_kitti wants
KITTI's whole odometry tree, sequences/NN/image_0 with poses/NN.txt apart, where a sequence
folder here holds image_l/, calib.txt and poses.txt; its IR_affine wants the Oxford naming
img1.ppm and H1to2p, not HPatches' 1.ppm and H_1_2; it has no YorkUrban reader), and its
loaders have no Python bindings.
*/
namespace line_evaluation {

//! @addtogroup lsd_advance
//! @{

/** @brief Thresholds of the structural precision/recall protocol (YorkUrban-LineSegment: the
images of the York Urban DB @cite Denis2008 with the line-segment annotations of @cite Cho2018).

A detection is a candidate for a ground-truth segment g when its centre lies within
maxDistance of g's supporting line and its undirected angle differs from g's by at most
maxAngle. The candidates are projected on g and clipped to it; g is found when the union of
these intervals covers at least minCoverage of g's length.
*/
struct CV_EXPORTS_W_SIMPLE StructuralMatchParams
{
    CV_WRAP StructuralMatchParams() : maxDistance(1.0), maxAngle(5.0), minCoverage(0.75), offset(0.5) {}

    CV_PROP_RW double maxDistance;  //!< pixels, from a detection's centre to g's line, >= 0. Default 1.
    CV_PROP_RW double maxAngle;     //!< degrees, between undirected directions, in [0, 90]. Default 5.
    CV_PROP_RW double minCoverage;  //!< share of g's length the candidates must cover, in (0, 1]. Default 0.75.
    /** Added to every detected coordinate before matching, pixels, finite. Default 0.5: OpenCV's
    detectors put pixel centres at integer coordinates, while YorkUrban's ground truth is in
    continuous coordinates where the image spans [0, W] x [0, H]. */
    CV_PROP_RW double offset;
};

/** @brief Structural precision and recall of one image. */
struct CV_EXPORTS_W_SIMPLE StructuralScore
{
    CV_WRAP StructuralScore()
        : precision(0), recall(0), matchedLength(0), detectedLength(0), coveredLength(0),
          groundTruthLength(0), found(0), groundTruthCount(0)
    {}

    CV_PROP_RW double precision;         //!< matchedLength / detectedLength (0 without detections)
    CV_PROP_RW double recall;            //!< coveredLength / groundTruthLength (0 without ground truth)
    CV_PROP_RW double matchedLength;     //!< sum over found g of the clipped lengths of g's candidates, each detection counted at most its own length
    CV_PROP_RW double detectedLength;    //!< total length of the detections
    CV_PROP_RW double coveredLength;     //!< sum over found g of the length of g covered by the union of its candidates
    CV_PROP_RW double groundTruthLength; //!< total length of the ground truth
    CV_PROP_RW int found;                //!< ground-truth segments found
    CV_PROP_RW int groundTruthCount;     //!< ground-truth segments
};

/** @brief Scores detections against ground truth with the structural protocol.

@param detections Detected segments, N x 1 (or 1 x N) CV_32FC4 or std::vector<Vec4f>, (x1, y1, x2, y2)
in OpenCV's pixel-centre convention (params.offset is added to them).
@param groundTruth Ground-truth segments in the same layout, in the data set's coordinates.
@param params Thresholds and coordinate offset. Default StructuralMatchParams() (1 px, 5 deg,
75 %, +0.5 px).
@return Precision, recall and the lengths and counts behind them, for this image.

Duplicated detections on the same ground truth each count as matched (the protocol sums the
clipped candidate lengths); a detection that is a candidate of several ground-truth segments
counts at most its own length. Zero-length ground-truth segments are ignored.
*/
CV_EXPORTS_W StructuralScore evaluateStructural(InputArray detections, InputArray groundTruth,
                                                const StructuralMatchParams& params = StructuralMatchParams());

/** @brief F-score of mean precision and mean recall.
@param averagePrecision AP, the mean of the per-image precisions, in [0, 1].
@param averageRecall AR, the mean of the per-image recalls, in [0, 1].
@return 2 AP AR / (AP + AR), 0 when both are 0. */
CV_EXPORTS_W double fScore(double averagePrecision, double averageRecall);

/** @brief Share of long segments ("long-line ratio").
@param lines Segments, N x 1 or 1 x N CV_32FC4 (std::vector<Vec4f>).
@param minLength Pixels. Default 60 (the long-line length of the evaluation protocol).
@return Share of the segments at least minLength long, in [0, 1] (0 for no segments). */
CV_EXPORTS_W double longSegmentShare(InputArray lines, double minLength = 60.0);

/** @brief Reads segments from a text file, one `x1 y1 x2 y2` per line (spaces or commas).
Blank lines and lines starting with '#' are skipped; any other malformed line throws.
@param path Path of the file.
@return The segments in file order. */
CV_EXPORTS_W std::vector<Vec4f> readSegments(const String& path);

/** @brief Writes segments to a text file, one `x1 y1 x2 y2` per line with 3 decimals.
@param path Path of the file, created or overwritten; throws when it cannot be written.
@param lines Segments, N x 1 or 1 x N CV_32FC4 (std::vector<Vec4f>). */
CV_EXPORTS_W void writeSegments(const String& path, InputArray lines);

/** @brief One image of a line-segment data set and its ground truth. */
struct CV_EXPORTS_W_SIMPLE LabelledImage
{
    CV_PROP_RW String imagePath;               //!< path of the image file
    CV_PROP_RW std::vector<Vec4f> groundTruth; //!< ground-truth segments (x1, y1, x2, y2) in the data set's coordinates
};

/** @brief Loads a YorkUrban-LineSegment folder: `images/NAME.jpg` with `gt/NAME_gt.txt`.

The images listed in `list.txt` (one NAME per line) are loaded in that order when the file
exists, otherwise every JPEG image of `images/` in name order. Throws when the folder, an image or its
ground truth is missing.
@param folder The data set's folder, holding `images/`, `gt/` and optionally `list.txt`
(@cite Denis2008, @cite Cho2018).
@return The images with their ground truth, in the order above.
*/
CV_EXPORTS_W std::vector<LabelledImage> loadYorkUrban(const String& folder);

/** @brief A KITTI-odometry-style sequence (@cite Geiger2012): left images, projection matrices
and poses. */
struct CV_EXPORTS_W_SIMPLE SequenceData
{
    CV_PROP_RW std::vector<String> imagePaths;  //!< frames in name order (the left camera's of a stereo sequence)
    CV_PROP_RW std::vector<String> rightImagePaths;  //!< the right camera's frames of the same names (empty if absent)
    CV_PROP_RW Mat P0;                          //!< 3x4 CV_64F projection matrix of the left camera (empty if absent)
    CV_PROP_RW Mat P1;                          //!< 3x4 CV_64F projection matrix of the right camera (empty if absent)
    CV_PROP_RW std::vector<Mat> poses;          //!< 3x4 CV_64F [R|t] of each frame in the first frame's coordinates (empty if absent)
};

/** @brief Loads a sequence folder: `image_l/` (or `image_0/`, or `cam0/data/` as in EuRoC
@cite Burri2016, or the folder itself, the first that holds images) with its PNG, JPEG, PPM,
PGM or BMP images in name order, the right camera's frames of the same names in `image_r/`
(`image_1/`, `cam1/data/`) when that folder exists, `calib.txt` (rows of 12 numbers, optionally
prefixed `P0:`) and `poses.txt` (12 numbers per frame), both optional. Throws when no image is
found, when the right folder lacks a frame of the left one, or when `poses.txt` exists with a row
count different from the number of images.
@param folder The sequence's folder.
@return The image paths, and the matrices and poses that the folder holds.
*/
CV_EXPORTS_W SequenceData loadSequence(const String& folder);

/** @brief Line matching under a known homography: match precision, repeatability and
localisation error (doc/matching.md), as on the planar scenes of HPatches @cite Balntas2017.

A segment a of image 1 and a segment b of image 2 correspond when a, mapped by H, lies within
maxDistance of b: both mapped endpoints are at most maxDistance from b's supporting line, and
the mapped segment and b overlap along that line (their projections on it share a positive
length).
*/
struct CV_EXPORTS_W_SIMPLE HomographyMatchScore
{
    CV_WRAP HomographyMatchScore()
        : matches(0), correct(0), precision(0), repeatability(0), localisationError(0), repeated(0),
          visible(0)
    {}

    CV_PROP_RW int matches;               //!< matches evaluated
    CV_PROP_RW int correct;               //!< matches whose two segments correspond
    CV_PROP_RW double precision;          //!< correct / matches (0 without matches)
    /** share of the visible segments (those whose mapped endpoints both fall inside the other
    image) of both images that have a corresponding segment in the other image (0 when none is
    visible) */
    CV_PROP_RW double repeatability;
    /** mean, over the repeated segments, of the smallest mean perpendicular distance of the two
    mapped endpoints to a corresponding segment's line, pixels (0 when none is repeated) */
    CV_PROP_RW double localisationError;
    CV_PROP_RW int repeated;              //!< visible segments, of both images, with a counterpart
    CV_PROP_RW int visible;               //!< visible segments of both images
};

/** @brief Whether segment a of image 1, mapped by the homography H (image 1 -> image 2),
corresponds to segment b of image 2 (see HomographyMatchScore).

@param a Segment (x1, y1, x2, y2) of image 1. @param b Segment of image 2.
@param H 3x3 homography, CV_32F or CV_64F, mapping image 1 to image 2.
@param maxDistance Largest perpendicular distance of a mapped endpoint to b's line, pixels, >= 0. Default 3.
@return true when they correspond. A zero-length b, or an endpoint of a that H sends to
infinity, never corresponds.
*/
CV_EXPORTS_W bool correspondUnderHomography(const Vec4f& a, const Vec4f& b, InputArray H, double maxDistance = 3.0);

/** @brief Scores line matches between two images related by a homography, with the repeatability
and localisation error of the two segment sets (the HPatches line protocol, @cite Balntas2017,
doc/matching.md).

@param segments1 Segments of image 1, N x 1 CV_32FC4 (std::vector<Vec4f>).
@param segments2 Segments of image 2.
@param matches Matches, queryIdx into segments1 and trainIdx into segments2 (what
BinaryDescriptorMatcher::match returns for query = image 1); indices out of range throw.
@param H 3x3 homography (CV_32F or CV_64F) mapping image 1 to image 2, invertible.
@param imageSize1 Size of image 1. @param imageSize2 Size of image 2.
@param maxDistance Correspondence distance in pixels (correspondUnderHomography), >= 0. Default 3.
@return Match precision, repeatability, localisation error and the counts behind them.
*/
CV_EXPORTS_W HomographyMatchScore evaluateHomographyMatches(InputArray segments1, InputArray segments2,
                                                            const std::vector<DMatch>& matches, InputArray H,
                                                            Size imageSize1, Size imageSize2,
                                                            double maxDistance = 3.0);

/** @brief Verdict of the epipolar check of a line match (checkEpipolar). */
enum EpipolarVerdict
{
    EPIPOLAR_CONSISTENT = 0,    //!< the epipolar interval of a overlaps b
    EPIPOLAR_INCONSISTENT = 1,  //!< it does not: the match is wrong
    /** b runs along the epipolar lines (or a's endpoints are the epipole): the intersections
    are ill-conditioned and the pair cannot be decided */
    EPIPOLAR_UNDECIDABLE = 2
};

/** @brief Epipolar consistency of a match between segment a of frame 1 and segment b of frame 2.

The epipolar lines F a1 and F a2 of a's endpoints cut b's supporting line at two points; the
match is consistent when the interval between them overlaps b, extended by tolerance pixels at
both ends. When the direction of b is within minAngle of either epipolar line, the pair is
undecidable. A consistent pair is not proven right: a wrong segment on the same epipolar band
passes too (doc/matching.md).

@param a Segment of frame 1. @param b Segment of frame 2.
@param F 3x3 fundamental matrix (CV_32F or CV_64F) with x2^T F x1 = 0.
@param tolerance Pixels, >= 0. Default 2. @param minAngle Degrees, in [0, 90). Default 5.
@return One of EpipolarVerdict.
*/
CV_EXPORTS_W int checkEpipolar(const Vec4f& a, const Vec4f& b, InputArray F, double tolerance = 2.0,
                               double minAngle = 5.0);

/** @brief Fundamental matrix between two frames of a calibrated sequence (KITTI odometry format).

@param P 3x4 projection matrix K [I | 0] of the camera (SequenceData::P0); its left 3x3 block is K.
@param pose1 3x4 [R | t] of frame 1: camera-1 coordinates to world coordinates.
@param pose2 3x4 [R | t] of frame 2.
@return F (CV_64F) such that x2^T F x1 = 0 for the pixels x1, x2 of one world point. Throws
when the two poses share their camera centre (F is then undefined).
*/
CV_EXPORTS_W Mat fundamentalFromPoses(InputArray P, InputArray pose1, InputArray pose2);

/** @brief Epipolar scores of line matches between two frames (checkEpipolar on each match). */
struct CV_EXPORTS_W_SIMPLE EpipolarMatchScore
{
    CV_WRAP EpipolarMatchScore() : matches(0), consistent(0), inconsistent(0), undecidable(0), precision(0) {}

    CV_PROP_RW int matches;       //!< matches evaluated
    CV_PROP_RW int consistent;    //!< EPIPOLAR_CONSISTENT
    CV_PROP_RW int inconsistent;  //!< EPIPOLAR_INCONSISTENT
    CV_PROP_RW int undecidable;   //!< EPIPOLAR_UNDECIDABLE, counted apart
    CV_PROP_RW double precision;  //!< consistent / (consistent + inconsistent), 0 when both are 0
};

/** @brief Scores matches between two frames with checkEpipolar.

@param segments1 Segments of frame 1, N x 1 CV_32FC4 (std::vector<Vec4f>).
@param segments2 Segments of frame 2.
@param matches Matches, queryIdx into segments1 and trainIdx into segments2; indices out of
range throw.
@param F 3x3 fundamental matrix (CV_32F or CV_64F) with x2^T F x1 = 0, e.g. from
fundamentalFromPoses() on a KITTI sequence (@cite Geiger2012).
@param tolerance Pixels, >= 0. Default 2 (as checkEpipolar).
@param minAngle Degrees, in [0, 90). Default 5 (as checkEpipolar).
@return The counts of each verdict and the precision over the decided matches.
*/
CV_EXPORTS_W EpipolarMatchScore evaluateEpipolarMatches(InputArray segments1, InputArray segments2,
                                                        const std::vector<DMatch>& matches, InputArray F,
                                                        double tolerance = 2.0, double minAngle = 5.0);

/** @brief Reads a 3x3 homography: a text file of 9 numbers (3 rows, HPatches' `H_1_k`), or an
OpenCV FileStorage file (.xml, .yml, .yaml, .json) whose first top-level node is the 3x3 matrix
(OpenCV's `H1to3p.xml`).
@param path Path of the file; the extension (case-insensitive) selects the format.
@return The 3x3 homography, CV_64F; throws on anything else or on a non-finite value. */
CV_EXPORTS_W Mat readHomography(const String& path);

/** @brief A pair of images related by a homography. */
struct CV_EXPORTS_W_SIMPLE HomographyPair
{
    CV_PROP_RW String image1Path;  //!< reference image
    CV_PROP_RW String image2Path;  //!< transformed image
    CV_PROP_RW Mat H;              //!< 3x3 CV_64F, maps image 1 to image 2
};

/** @brief Loads an HPatches-style folder (@cite Balntas2017): `1.ppm` with `k.ppm` and `H_1_k`
for every k >= 2 that has both, in increasing k. Throws when `1.ppm` or every pair is missing.
@param folder The sequence's folder, e.g. an HPatches `v_*` sequence.
@return One pair (1.ppm, k.ppm, H_1_k) per k. */
CV_EXPORTS_W std::vector<HomographyPair> loadHomographyPairs(const String& folder);

//! @} lsd_advance

}}} // namespace cv::ximgproc::line_evaluation

#endif
