// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The pose of a camera from 2D-3D line and point correspondences (doc/pose.md): a minimal solver
// on three correspondences inside RANSAC, then a robust refinement with cv::LMSolver.
//
// Every correspondence is two constraints "the 3D point X projects onto the image line l": a line
// gives one per 3D endpoint (its 2D segment's line), a point two (the vertical and the horizontal
// line through its pixel). With L = K^T l and l scaled so that (l0, l1) is a unit vector, the
// constraint's residual for the pose (R, t) is the signed distance in pixels
//     r = L . Y / Y_z,  Y = R X + t,
// so that lines and points share one residual, one Jacobian and one solver.

#include "precomp.hpp"
#include "opencv2/calib3d.hpp"
#include "opencv2/lsd_advance/pose_evaluation.hpp"

namespace cv {
namespace ximgproc {
namespace line_evaluation {

namespace {

// A camera point closer than this to the image plane (in the reference's unit) is behind the camera.
constexpr double kMinDepth = 1e-9;
// The smallest singular value of a pose's normalised Jacobian, relative to the largest, below which
// its features leave a direction of the pose free: parallel lines in float coordinates give about
// 1e-5 (rounding), the inliers of every pose solved on KITTI and the fountain more than 5e-4.
constexpr double kMinSingularValue = 1e-4;
// The refinement's residual, in pixels, of a point that a trial step sent behind the camera.
constexpr double kBehindCameraResidual = 1e6;

struct Constraint
{
    Vec3d X;  //!< the 3D point, reference coordinates
    Vec3d L;  //!< K^T l of its image line
};

struct Pose
{
    Matx33d R = Matx33d::eye();
    Vec3d t;
};

// The correspondences as constraints: feature f (the lines first, then the points) owns
// constraints 2f and 2f + 1.
struct Correspondences
{
    std::vector<Constraint> constraints;
    int lines = 0, points = 0;

    int features() const { return lines + points; }
    bool isLine(int feature) const { return feature < lines; }
};

// The residual of constraint c for pose (R, t) and its gradient with respect to Y = R X + t; false
// when X is behind the camera.
inline bool residual(const Constraint& c, const Pose& pose, double& r, Vec3d* gradientY = nullptr)
{
    const Vec3d Y = pose.R * c.X + pose.t;
    if (!(Y[2] > kMinDepth))
        return false;
    r = c.L.dot(Y) / Y[2];
    if (gradientY)
        *gradientY = (c.L - Vec3d(0, 0, r)) * (1.0 / Y[2]);
    return true;
}

// The residual of constraint c for pose (R, t) and its gradient with respect to the pose turned on
// the left by a rotation vector w and moved by dt (Y = exp(w) R X + t + dt at w = dt = 0): dY/dw =
// -[R X]x and dY/dt = I, so dr/dw = (R X) x g and dr/dt = g, with g the gradient in Y. False when X
// is behind the camera.
inline bool jacobianRow(const Constraint& c, const Pose& pose, double& r, double row[6])
{
    Vec3d g;
    if (!residual(c, pose, r, &g))
        return false;
    const Vec3d wRow = (pose.R * c.X).cross(g);
    for (int j = 0; j < 3; j++)
    {
        row[j] = wRow[j];
        row[3 + j] = g[j];
    }
    return true;
}

// The feature's squared error: the larger endpoint distance of a line, the reprojection error of a
// point; DBL_MAX when a point of it is behind the camera.
double featureError(const Correspondences& data, int feature, const Pose& pose)
{
    double r0, r1;
    if (!residual(data.constraints[2 * feature], pose, r0) || !residual(data.constraints[2 * feature + 1], pose, r1))
        return DBL_MAX;
    return data.isLine(feature) ? std::max(r0 * r0, r1 * r1) : r0 * r0 + r1 * r1;
}

double thresholdOf(const Correspondences& data, int feature, const PoseEstimationParams& params)
{
    return data.isLine(feature) ? params.lineThreshold : params.pointThreshold;
}

// The truncated quadratic cost of a pose (MSAC) and the number of its inliers.
double poseCost(const Correspondences& data, const Pose& pose, const PoseEstimationParams& params, int& inliers)
{
    double cost = 0;
    inliers = 0;
    for (int f = 0; f < data.features(); f++)
    {
        const double th = thresholdOf(data, f, params), e = featureError(data, f, pose);
        inliers += e <= th * th;
        cost += std::min(e, th * th) / (th * th);
    }
    return cost;
}

// The pose with its rotation turned by the rotation vector w (on the left) and its translation
// moved by dt: Y = exp(w) R X + t + dt, the parametrisation of solveMinimal's Jacobian.
Pose updated(const Pose& pose, const Vec3d& w, const Vec3d& dt)
{
    Matx33d dR;
    Rodrigues(w, dR);
    Pose next;
    next.R = dR * pose.R;
    next.t = pose.t + dt;
    return next;
}

// Whether the sample's points are all in front of the camera of the pose.
bool inFront(const Correspondences& data, const int sample[3], const Pose& pose)
{
    double r;
    for (int k = 0; k < 6; k++)
        if (!residual(data.constraints[2 * sample[k / 2] + k % 2], pose, r))
            return false;
    return true;
}

// The pose that satisfies the six constraints of three features exactly: Newton's method from the
// identity pose, each step turning the pose on the left by a rotation vector, halved while it
// would send a point of the sample behind the camera. So it finds the solution nearest the
// reference frame: the reference should be a frame near the camera (the previous frame or a
// keyframe, as in tracking). False when the system is singular (a degenerate sample) or the
// steps do not converge.
bool solveMinimal(const Correspondences& data, const int sample[3], Pose& pose)
{
    pose = Pose();
    if (!inFront(data, sample, pose))
        return false;
    for (int iteration = 0; iteration < 12; iteration++)
    {
        Matx66d J;
        Vec6d r;
        double largest = 0;
        for (int k = 0; k < 6; k++)
        {
            jacobianRow(data.constraints[2 * sample[k / 2] + k % 2], pose, r[k], J.val + 6 * k);
            largest = std::max(largest, std::abs(r[k]));
        }
        if (largest < 1e-9)
            return true;
        Vec6d step;
        if (!solve(J, -r, step, DECOMP_LU) || !checkRange(step))
            return false;
        Pose next = updated(pose, Vec3d(step[0], step[1], step[2]), Vec3d(step[3], step[4], step[5]));
        for (int halvings = 0; !inFront(data, sample, next); halvings++)
        {
            if (halvings == 8)
                return false;
            step *= 0.5;
            next = updated(pose, Vec3d(step[0], step[1], step[2]), Vec3d(step[3], step[4], step[5]));
        }
        pose = next;
    }
    // Not converged to the last nanopixel: accept a pose that fits the sample to a micropixel.
    for (int k = 0; k < 6; k++)
    {
        double r;
        if (!residual(data.constraints[2 * sample[k / 2] + k % 2], pose, r) || std::abs(r) > 1e-6)
            return false;
    }
    return true;
}

// Whether the features determine the pose: the Jacobian of their residuals, its columns scaled to
// unit norm (rotation and translation have other units), has no null direction but rounding's. 3D
// lines that are all parallel, for one, leave the translation along them free: every pose along it
// fits them all.
bool determinesPose(const Correspondences& data, const std::vector<int>& features, const Pose& pose)
{
    Mat J(2 * (int)features.size(), 6, CV_64F);
    for (int i = 0; i < J.rows; i++)
    {
        double r;
        if (!jacobianRow(data.constraints[2 * features[i / 2] + i % 2], pose, r, J.ptr<double>(i)))
            return false;
    }
    for (int j = 0; j < 6; j++)
    {
        const double n = norm(J.col(j));
        if (!(n > 0))
            return false;
        J.col(j) *= 1.0 / n;
    }
    Mat singularValues;
    SVDecomp(J, singularValues, noArray(), noArray(), SVD::NO_UV);
    return singularValues.at<double>(5) > kMinSingularValue * singularValues.at<double>(0);
}

// RANSAC hypotheses needed to draw an all-inlier sample of three with the given confidence.
int iterationsNeeded(double inlierShare, double confidence, int maxIterations)
{
    const double allInliers = inlierShare * inlierShare * inlierShare;
    if (allInliers >= 1)
        return 1;
    if (allInliers <= 0)
        return maxIterations;
    const double needed = std::log(1 - confidence) / std::log(1 - allInliers);
    return needed >= maxIterations ? maxIterations : std::max(1, (int)std::ceil(needed));
}

// The Huber-weighted residuals of the given features for the pose Rodrigues(w) R0, t, and their
// Jacobian with respect to (w, t): cv::LMSolver's callback. The weights are fixed per run
// (iteratively reweighted least squares). A trial step that sends a point behind the camera gets a
// residual far beyond any inlier's, so that LMSolver rejects the step (it would stop the whole run
// on a callback that fails).
class RobustReprojection CV_FINAL : public LMSolver::Callback
{
public:
    RobustReprojection(const Correspondences& correspondences, const Pose& startPose, const std::vector<int>& refined,
                       double huberWidth)
        : data(correspondences), start(startPose), features(refined)
    {
        for (int f : features)
            for (int k = 0; k < 2; k++)
            {
                double r = 0;
                residual(data.constraints[2 * f + k], start, r);
                // Huber: weight 1 up to the width, width / |r| beyond (as the square root, on r).
                weights.push_back(std::abs(r) <= huberWidth ? 1.0 : std::sqrt(huberWidth / std::abs(r)));
            }
    }

    bool compute(InputArray paramIn, OutputArray errOut, OutputArray jacobianOut) const CV_OVERRIDE
    {
        const Mat param = paramIn.getMat();
        const Vec3d w(param.at<double>(0), param.at<double>(1), param.at<double>(2));
        Mat dRdw;
        const Pose pose = poseAt(param, &dRdw);
        const int rows = 2 * (int)features.size();
        errOut.create(rows, 1, CV_64F);
        Mat err = errOut.getMat();
        Mat J;
        if (jacobianOut.needed())
        {
            jacobianOut.create(rows, 6, CV_64F);
            J = jacobianOut.getMat();
        }
        for (int i = 0; i < rows; i++)
        {
            const Constraint& c = data.constraints[2 * features[i / 2] + i % 2];
            double r;
            Vec3d g;
            if (!residual(c, pose, r, &g))
            {
                if (!J.empty())  // never at a pose LMSolver accepted: each was in front
                    return false;
                r = kBehindCameraResidual;
            }
            err.at<double>(i) = weights[i] * r;
            if (J.empty())
                continue;
            // dY/dw_k = (dR/dw_k) R0 X, with dR/dw_k the k-th row of Rodrigues' 3x9 Jacobian.
            const Vec3d X0 = start.R * c.X;
            for (int k = 0; k < 3; k++)
            {
                const double* d = dRdw.ptr<double>(k);
                const Vec3d dY(d[0] * X0[0] + d[1] * X0[1] + d[2] * X0[2], d[3] * X0[0] + d[4] * X0[1] + d[5] * X0[2],
                               d[6] * X0[0] + d[7] * X0[1] + d[8] * X0[2]);
                J.at<double>(i, k) = weights[i] * g.dot(dY);
                J.at<double>(i, 3 + k) = weights[i] * g[k];
            }
        }
        return true;
    }

    // The pose of LMSolver's parameters (w, t); with dRdw, also Rodrigues' Jacobian of w.
    Pose poseAt(const Mat& param, Mat* dRdw = nullptr) const
    {
        Mat Rw;
        const Mat w = param.rowRange(0, 3);
        if (dRdw)
            Rodrigues(w, Rw, *dRdw);
        else
            Rodrigues(w, Rw);
        Pose pose;
        pose.R = Matx33d(Rw) * start.R;
        pose.t = Vec3d(param.at<double>(3), param.at<double>(4), param.at<double>(5));
        return pose;
    }

private:
    const Correspondences& data;
    const Pose start;
    const std::vector<int>& features;
    std::vector<double> weights;
};

std::vector<int> inliersOf(const Correspondences& data, const Pose& pose, const PoseEstimationParams& params)
{
    std::vector<int> inliers;
    for (int f = 0; f < data.features(); f++)
    {
        const double th = thresholdOf(data, f, params);
        if (featureError(data, f, pose) <= th * th)
            inliers.push_back(f);
    }
    return inliers;
}

// The pose refined on its inliers under the Huber loss; the inliers taken again and refined once more.
Pose refine(const Correspondences& data, const Pose& hypothesis, const PoseEstimationParams& params)
{
    Pose pose = hypothesis;
    for (int round = 0; round < 2; round++)
    {
        const std::vector<int> features = inliersOf(data, pose, params);
        if ((int)features.size() < 3)
            break;
        const Ptr<RobustReprojection> problem = makePtr<RobustReprojection>(data, pose, features, params.huberWidth);
        Mat param = (Mat_<double>(6, 1) << 0, 0, 0, pose.t[0], pose.t[1], pose.t[2]);
        if (LMSolver::create(problem, 50)->run(param) == -1)  // the callback failed: keep the pose
            break;
        const Pose refined = problem->poseAt(param);
        int before, after;
        // LM minimises the weighted squares; keep its pose unless it lost inliers (a rare drift).
        poseCost(data, pose, params, before);
        poseCost(data, refined, params, after);
        if (after < before)
            break;
        pose = refined;
    }
    return pose;
}

// Reads N x 1 C-channel or N x C one-channel arrays of float or double as rows of C doubles.
Mat rowsOf(InputArray array, int channels, const char* what)
{
    if (array.empty())
        return Mat(0, channels, CV_64F);
    const Mat m = array.getMat();
    const int depth = m.depth();
    const bool layoutOk = (m.channels() == channels && (m.rows == 1 || m.cols == 1)) ||
                          (m.channels() == 1 && m.cols == channels && m.dims == 2);
    if (!layoutOk || (depth != CV_32F && depth != CV_64F))
        CV_Error_(Error::StsBadArg, ("estimatePose: %s must be N x 1 with %d channels or N x %d, CV_32F or CV_64F; "
                                     "got %s %dx%d", what, channels, channels, typeToString(m.type()).c_str(), m.cols,
                                     m.rows));
    Mat rows;
    m.reshape(1, (int)(m.total() * m.channels() / channels)).convertTo(rows, CV_64F);
    if (!checkRange(rows))
        CV_Error_(Error::StsBadArg, ("estimatePose: %s holds a value that is not finite", what));
    return rows;
}

void checkParams(const PoseEstimationParams& p)
{
    const bool ok = p.maxIterations >= 1 && p.maxIterations <= 1000000 && p.confidence > 0 && p.confidence < 1 &&
                    p.lineThreshold > 0 && std::isfinite(p.lineThreshold) && p.pointThreshold > 0 &&
                    std::isfinite(p.pointThreshold) && p.huberWidth > 0 && std::isfinite(p.huberWidth) &&
                    p.minInliers >= 3;
    if (!ok)
        CV_Error_(Error::StsOutOfRange,
                  ("PoseEstimationParams: expected maxIterations in [1, 1000000], confidence in (0, 1), positive finite "
                   "lineThreshold, pointThreshold and huberWidth, minInliers >= 3; got %d, %g, %g, %g, %g, %d",
                   p.maxIterations, p.confidence, p.lineThreshold, p.pointThreshold, p.huberWidth, p.minInliers));
}

Correspondences correspondencesOf(const Matx33d& K, InputArray segments3dIn, InputArray segments2dIn,
                                  InputArray points3dIn, InputArray points2dIn)
{
    const Mat segments3d = rowsOf(segments3dIn, 6, "segments3d"), segments2d = rowsOf(segments2dIn, 4, "segments2d");
    const Mat points3d = rowsOf(points3dIn, 3, "points3d"), points2d = rowsOf(points2dIn, 2, "points2d");
    if (segments3d.rows != segments2d.rows || points3d.rows != points2d.rows)
        CV_Error_(Error::StsBadArg, ("estimatePose: %d 3D segments for %d 2D segments, %d 3D points for %d pixels: the "
                                     "counts of each pair must agree", segments3d.rows, segments2d.rows, points3d.rows,
                                     points2d.rows));
    Correspondences data;
    data.lines = segments3d.rows;
    data.points = points3d.rows;
    const Matx33d Kt = K.t();
    for (int i = 0; i < data.lines; i++)
    {
        const double* s = segments2d.ptr<double>(i);
        Vec3d l = Vec3d(s[0], s[1], 1).cross(Vec3d(s[2], s[3], 1));
        const double norm = std::hypot(l[0], l[1]);
        if (!(norm > 0))
            CV_Error_(Error::StsBadArg, ("estimatePose: 2D segment %d has zero length", i));
        l *= 1.0 / norm;
        const double* X = segments3d.ptr<double>(i);
        data.constraints.push_back({ Vec3d(X[0], X[1], X[2]), Kt * l });
        data.constraints.push_back({ Vec3d(X[3], X[4], X[5]), Kt * l });
    }
    for (int i = 0; i < data.points; i++)
    {
        const double* x = points2d.ptr<double>(i);
        const double* X = points3d.ptr<double>(i);
        data.constraints.push_back({ Vec3d(X[0], X[1], X[2]), Kt * Vec3d(1, 0, -x[0]) });
        data.constraints.push_back({ Vec3d(X[0], X[1], X[2]), Kt * Vec3d(0, 1, -x[1]) });
    }
    return data;
}

Matx33d cameraMatrixOf(InputArray cameraMatrix)
{
    Mat K;
    if (!cameraMatrix.empty())
        cameraMatrix.getMat().convertTo(K, CV_64F);
    if (K.rows != 3 || K.cols != 3 || !checkRange(K) || !(K.at<double>(0, 0) > 0) || !(K.at<double>(1, 1) > 0) ||
        K.at<double>(1, 0) != 0 || K.at<double>(2, 0) != 0 || K.at<double>(2, 1) != 0 || K.at<double>(2, 2) != 1)
        CV_Error(Error::StsBadArg, "estimatePose: cameraMatrix must be a finite 3x3 K = [fx s cx; 0 fy cy; 0 0 1] "
                                   "with fx, fy > 0");
    return Matx33d(K);
}

} // namespace

PoseEstimate estimatePose(InputArray cameraMatrix, InputArray segments3d, InputArray segments2d, InputArray points3d,
                          InputArray points2d, const PoseEstimationParams& params)
{
    CV_INSTRUMENT_REGION();
    checkParams(params);
    const Correspondences data =
        correspondencesOf(cameraMatrixOf(cameraMatrix), segments3d, segments2d, points3d, points2d);

    PoseEstimate estimate;
    estimate.R = Mat::eye(3, 3, CV_64F);
    estimate.t = Mat::zeros(3, 1, CV_64F);
    estimate.lineInlierMask.assign(data.lines, 0);
    estimate.pointInlierMask.assign(data.points, 0);
    const int n = data.features();
    if (n < 3)
        return estimate;

    RNG rng((uint64)(int64)params.seed + 0x9E3779B97F4A7C15ULL);
    Pose best;
    double bestCost = DBL_MAX;
    int bestInliers = 0, needed = params.maxIterations;
    for (estimate.iterations = 0; estimate.iterations < needed; estimate.iterations++)
    {
        int sample[3];
        sample[0] = rng.uniform(0, n);
        do
            sample[1] = rng.uniform(0, n);
        while (sample[1] == sample[0]);
        do
            sample[2] = rng.uniform(0, n);
        while (sample[2] == sample[0] || sample[2] == sample[1]);
        Pose hypothesis;
        if (!solveMinimal(data, sample, hypothesis))
            continue;
        int inliers;
        const double cost = poseCost(data, hypothesis, params, inliers);
        if (cost < bestCost)
        {
            bestCost = cost;
            best = hypothesis;
            bestInliers = inliers;
            needed = iterationsNeeded((double)inliers / n, params.confidence, params.maxIterations);
        }
    }
    if (bestInliers < 3)
        return estimate;

    const Pose pose = refine(data, best, params);
    const std::vector<int> inliers = inliersOf(data, pose, params);
    for (int f : inliers)
    {
        if (data.isLine(f))
            estimate.lineInlierMask[f] = 1, estimate.lineInliers++;
        else
            estimate.pointInlierMask[f - data.lines] = 1, estimate.pointInliers++;
    }
    estimate.solved =
        estimate.lineInliers + estimate.pointInliers >= params.minInliers && determinesPose(data, inliers, pose);
    if (estimate.solved)
    {
        Mat(pose.R).copyTo(estimate.R);
        Mat(pose.t).copyTo(estimate.t);
    }
    return estimate;
}

void poseError(InputArray R, InputArray t, InputArray Rgt, InputArray tgt, double& rotationError,
               double& translationError)
{
    CV_INSTRUMENT_REGION();
    Mat R1, t1, R2, t2;
    R.getMat().convertTo(R1, CV_64F);
    t.getMat().convertTo(t1, CV_64F);
    Rgt.getMat().convertTo(R2, CV_64F);
    tgt.getMat().convertTo(t2, CV_64F);
    if (R1.size() != Size(3, 3) || R2.size() != Size(3, 3) || t1.total() != 3 || t2.total() != 3)
        CV_Error(Error::StsBadArg, "poseError: expected 3x3 rotations and 3-element translations");
    Mat angleAxis;  // the rotation vector of R^T Rgt: its norm is the angle, accurate at small angles too
    Rodrigues(Mat(R1.t() * R2), angleAxis);
    rotationError = norm(angleAxis) * 180.0 / CV_PI;
    translationError = norm(t1.reshape(1, 3), t2.reshape(1, 3));
}

}}} // namespace cv::ximgproc::line_evaluation
