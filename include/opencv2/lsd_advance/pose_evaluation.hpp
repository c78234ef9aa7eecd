// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_LSD_ADVANCE_POSE_EVALUATION_HPP
#define OPENCV_LSD_ADVANCE_POSE_EVALUATION_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace ximgproc {

/** @brief The pose evaluation behind LSDAdvance's documented results: what SLAM users judge a line
detector by. Lines matched between calibrated views are lifted to 3D segments, matched into another
view, and that view's pose is estimated from the 2D-3D correspondences (lines, points, or both) and
compared with the ground truth (doc/pose.md). The ground truth of the estimated view never enters
the matching nor the estimation (the known cameras of the views the 3D segments are lifted from
do).

Conventions: a projection matrix P = K [R | t] maps world points to pixels in OpenCV's pixel-centre
convention; a pose (R, t) maps reference coordinates to camera coordinates, X_cam = R X_ref + t; a
3D segment is (X1, Y1, Z1, X2, Y2, Z2), a 2D segment (x1, y1, x2, y2).
*/
namespace line_evaluation {

//! @addtogroup lsd_advance
//! @{

/** @brief Views of a static scene with known cameras: the layout of Strecha et al.'s multi-view
benchmark @cite Strecha2008, `images/NAME.jpg` with `gt_dense_cameras/NAME.jpg.camera`. */
struct CV_EXPORTS_W_SIMPLE MultiViewData
{
    CV_PROP_RW std::vector<String> imagePaths;   //!< the views in name order
    CV_PROP_RW std::vector<Mat> cameraMatrices;  //!< 3x3 CV_64F K of each view
    /** 3x4 CV_64F [R | C] of each view, camera to world: X_world = R X_cam + C (C is the camera
    centre), the convention of SequenceData::poses */
    CV_PROP_RW std::vector<Mat> poses;
    CV_PROP_RW std::vector<Size> imageSizes;     //!< the size each camera was calibrated for
};

/** @brief Loads a Strecha-style multi-view folder.
Each `gt_dense_cameras/NAME.camera` file holds K (3 rows), the distortion (one row, which must be
zero: the images are undistorted), R (3 rows, camera to world), the camera centre C (one row) and
the image size W H, and names the image `images/NAME`. Throws, naming the file and what is wrong,
when the folder, an image or a camera file is missing or malformed (K not upper triangular with a
positive focal length, R not a rotation, a non-zero distortion).
@param folder The scene's folder, holding `images/` and `gt_dense_cameras/`.
@return The views in name order.
*/
CV_EXPORTS_W MultiViewData loadMultiView(const String& folder);

/** @brief Fundamental matrix between two views of known projection matrices.
@param P1 3x4 projection matrix of view 1 (CV_32F or CV_64F).
@param P2 3x4 projection matrix of view 2.
@return F (CV_64F) with x2^T F x1 = 0 for the pixels of one world point, scaled to unit norm.
Throws when the two views share their camera centre (F is then undefined). */
CV_EXPORTS_W Mat fundamentalFromProjections(InputArray P1, InputArray P2);

/** @brief Lifts matched segments of two views of known cameras to 3D segments.
Each match's 3D line is the intersection of the planes back-projected from its two segments; its
extent is where the rays of both segments' endpoints meet that line, clipped to the part both
segments observe (SPEC "Pose evaluation protocol"). On a rectified stereo pair this is the
intersection of the right segment with the rows of the left one's endpoints. A match is dropped
when a segment runs within minEpipolarAngle of the epipolar line through its midpoint (its depth is
then ill-conditioned: the near-horizontal lines of a stereo pair), when the observed parts overlap
by less than minOverlap of the shorter one, or when an endpoint lies behind a camera.
@param P1 3x4 projection matrix of view 1. @param P2 3x4 projection matrix of view 2.
@param segments1 Segments of view 1, N x 1 CV_32FC4 (std::vector<Vec4f>).
@param segments2 Segments of view 2.
@param matches queryIdx into segments1, trainIdx into segments2; indices out of range throw.
@param segments3d Output N x 1 CV_32FC(6): one 3D segment per kept match, in world coordinates,
from the end seen at segment 1's start to the end seen at its end.
@param kept Output: the index into matches of each 3D segment.
@param minEpipolarAngle Degrees, in [0, 90). Default 10.
@param minOverlap Share of the shorter observed extent, in [0, 1]. Default 0.5.
*/
CV_EXPORTS_W void triangulateSegments(InputArray P1, InputArray P2, InputArray segments1, InputArray segments2,
                                      const std::vector<DMatch>& matches, OutputArray segments3d,
                                      CV_OUT std::vector<int>& kept, double minEpipolarAngle = 10.0,
                                      double minOverlap = 0.5);

/** @brief Settings of estimatePose(). */
struct CV_EXPORTS_W_SIMPLE PoseEstimationParams
{
    CV_WRAP PoseEstimationParams()
        : maxIterations(2000), confidence(0.999), seed(0), lineThreshold(2.0), pointThreshold(2.0),
          huberWidth(1.0), minInliers(6)
    {}
    CV_PROP_RW int maxIterations;   //!< RANSAC hypotheses at most, in [1, 1000000]. Default 2000.
    /** RANSAC stops once a hypothesis with no more outliers than the best one's would have been drawn
    with this probability, in (0, 1). Default 0.999. */
    CV_PROP_RW double confidence;
    CV_PROP_RW int seed;            //!< seed of the random samples: the same inputs and seed give the same pose. Default 0.
    /** a line is an inlier when both projected 3D endpoints lie within this distance of its 2D
    line, pixels, > 0. Default 2. */
    CV_PROP_RW double lineThreshold;
    CV_PROP_RW double pointThreshold; //!< a point is an inlier when it reprojects within this, pixels, > 0. Default 2.
    CV_PROP_RW double huberWidth;   //!< the robust refinement's Huber loss is quadratic up to this, pixels, > 0. Default 1.
    CV_PROP_RW int minInliers;      //!< inliers (lines plus points) needed to call the pose solved, >= 3. Default 6.
};

/** @brief Result of estimatePose(). */
struct CV_EXPORTS_W_SIMPLE PoseEstimate
{
    CV_WRAP PoseEstimate() : solved(false), lineInliers(0), pointInliers(0), iterations(0) {}
    CV_PROP_RW bool solved;        //!< a pose with at least PoseEstimationParams::minInliers inliers was found
    CV_PROP_RW Mat R;              //!< 3x3 CV_64F rotation, reference to camera (identity when not solved)
    CV_PROP_RW Mat t;              //!< 3x1 CV_64F translation, reference to camera (zero when not solved)
    //! lines within PoseEstimationParams::lineThreshold of the best pose found (also when too few to solve it)
    CV_PROP_RW int lineInliers;
    CV_PROP_RW int pointInliers;   //!< points within PoseEstimationParams::pointThreshold of that pose
    CV_PROP_RW int iterations;     //!< RANSAC hypotheses drawn
    CV_PROP_RW std::vector<uchar> lineInlierMask;   //!< 1 for each inlier line, in input order
    CV_PROP_RW std::vector<uchar> pointInlierMask;  //!< 1 for each inlier point, in input order
};

/** @brief Estimates the pose of a camera from 2D-3D line correspondences, point correspondences,
or both (doc/pose.md).
A minimal solver on three correspondences of either kind (each gives two equations; a few Newton
steps from the identity pose, with no motion prior but the nearest solution to the reference frame:
give the 3D features in the coordinates of a frame near the camera, such as the previous frame or a
keyframe, as tracking does) runs inside RANSAC with fixed seeds; the best
hypothesis (truncated quadratic cost) is refined on its inliers by Levenberg-Marquardt (cv::LMSolver)
under a Huber loss, on the distances of the projected 3D endpoints to their 2D lines and on the
reprojection errors of the points, in pixels; the inliers are then taken again and refined once more.
@param cameraMatrix 3x3 K = [fx s cx; 0 fy cy; 0 0 1] of the camera (CV_32F or CV_64F).
@param segments3d 3D segments in reference coordinates, N x 1 CV_32FC(6) or N x 6 CV_32F/CV_64F.
@param segments2d The 2D segment each 3D segment is seen as, N x 1 CV_32FC4 (std::vector<Vec4f>);
only its supporting line matters.
@param points3d 3D points in reference coordinates, M x 1 CV_32FC3 (std::vector<Point3f>) or M x 3
CV_32F/CV_64F; may be empty.
@param points2d The pixel each 3D point is seen at, M x 1 CV_32FC2 (std::vector<Point2f>).
@param params RANSAC and refinement settings.
@return The pose and its inliers. Fewer than 3 correspondences, none that agree, or inliers that
leave a direction of the pose free (3D lines that are all parallel, for one) give solved = false. Throws on mismatched counts, non-finite values, a zero-length 2D segment or a bad
setting.
*/
CV_EXPORTS_W PoseEstimate estimatePose(InputArray cameraMatrix, InputArray segments3d, InputArray segments2d,
                                       InputArray points3d = noArray(), InputArray points2d = noArray(),
                                       const PoseEstimationParams& params = PoseEstimationParams());

/** @brief Error of an estimated pose against the ground truth.
@param R Estimated rotation (3x3). @param t Estimated translation (3x1).
@param Rgt True rotation. @param tgt True translation (the same convention).
@param rotationError Output: the angle of R^T Rgt, degrees.
@param translationError Output: |t - tgt|, in the unit of t (the translation part of the
relative error of the two poses).
*/
CV_EXPORTS_W void poseError(InputArray R, InputArray t, InputArray Rgt, InputArray tgt, CV_OUT double& rotationError,
                            CV_OUT double& translationError);

//! @} lsd_advance

}}} // namespace cv::ximgproc::line_evaluation

#endif
