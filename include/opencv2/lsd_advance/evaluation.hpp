// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_EVALUATION_HPP
#define OPENCV_LSD_ADVANCE_EVALUATION_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace ximgproc {

//! @addtogroup lsd_advance
//! @{

/** @brief Thresholds of the structural precision/recall protocol (YorkUrban-LineSegment).

A detection is a candidate for a ground-truth segment g when its centre lies within
maxDistance of g's supporting line and its undirected angle differs from g's by at most
maxAngle. The candidates are projected on g and clipped to it; g is found when the union of
these intervals covers at least minCoverage of g's length.
*/
struct CV_EXPORTS_W_SIMPLE StructuralMatchParams
{
    StructuralMatchParams() : maxDistance(1.0), maxAngle(5.0), minCoverage(0.75), offset(0.5) {}

    CV_PROP_RW double maxDistance;  //!< pixels, from a detection's centre to g's line. Default 1.
    CV_PROP_RW double maxAngle;     //!< degrees, between undirected directions. Default 5.
    CV_PROP_RW double minCoverage;  //!< share of g's length the candidates must cover, in (0, 1]. Default 0.75.
    /** Added to every detected coordinate before matching, pixels. Default 0.5: OpenCV's
    detectors put pixel centres at integer coordinates, while YorkUrban's ground truth is in
    continuous coordinates where the image spans [0, W] x [0, H]. */
    CV_PROP_RW double offset;
};

/** @brief Structural precision and recall of one image. */
struct CV_EXPORTS_W_SIMPLE StructuralScore
{
    StructuralScore()
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
@param params Thresholds and coordinate offset.

Duplicated detections on the same ground truth each count as matched (the protocol sums the
clipped candidate lengths); a detection that is a candidate of several ground-truth segments
counts at most its own length. Zero-length ground-truth segments are ignored.
*/
CV_EXPORTS_W StructuralScore evaluateStructural(InputArray detections, InputArray groundTruth,
                                                const StructuralMatchParams& params = StructuralMatchParams());

/** @brief F-score of mean precision and mean recall: 2 AP AR / (AP + AR), 0 when both are 0. */
CV_EXPORTS_W double fScore(double averagePrecision, double averageRecall);

/** @brief Share of segments at least minLength pixels long (0 for no segments). */
CV_EXPORTS_W double longSegmentShare(InputArray lines, double minLength = 60.0);

/** @brief Reads segments from a text file, one `x1 y1 x2 y2` per line (spaces or commas).
Blank lines and lines starting with '#' are skipped; any other malformed line throws. */
CV_EXPORTS_W std::vector<Vec4f> readSegments(const String& path);

/** @brief Writes segments to a text file, one `x1 y1 x2 y2` per line with 3 decimals. */
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
*/
CV_EXPORTS_W std::vector<LabelledImage> loadYorkUrban(const String& folder);

/** @brief A KITTI-odometry-style sequence: left images, projection matrices and poses. */
struct CV_EXPORTS_W_SIMPLE SequenceData
{
    CV_PROP_RW std::vector<String> imagePaths;  //!< frames in name order
    CV_PROP_RW Mat P0;                          //!< 3x4 CV_64F projection matrix of the left camera
    CV_PROP_RW Mat P1;                          //!< 3x4 CV_64F projection matrix of the right camera (empty if absent)
    CV_PROP_RW std::vector<Mat> poses;          //!< 3x4 CV_64F [R|t] of each frame in the first frame's coordinates (empty if absent)
};

/** @brief Loads a sequence folder: `image_l/` (or `image_0/`, or the folder itself) with its
images in name order, `calib.txt` (rows of 12 numbers, optionally prefixed `P0:`) and
`poses.txt` (12 numbers per frame), both optional. Throws when no image is found, or when
`poses.txt` exists with a row count different from the number of images.
*/
CV_EXPORTS_W SequenceData loadSequence(const String& folder);

//! @} lsd_advance

}} // namespace cv::ximgproc

#endif
