// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "opencv2/calib3d.hpp"

namespace opencv_test {
namespace {

const Matx33d kK(700, 0, 600, 0, 700, 180, 0, 0, 1);
const Size kImage(1200, 360);

struct TruePose
{
    Matx33d R;
    Vec3d t;
};

TruePose poseOf(const Vec3d& rotationVectorDeg, const Vec3d& t)
{
    TruePose pose;
    Rodrigues(rotationVectorDeg * (CV_PI / 180.0), pose.R);
    pose.t = t;
    return pose;
}

Point2d project(const Matx33d& K, const TruePose& pose, const Vec3d& X)
{
    const Vec3d p = K * (pose.R * X + pose.t);
    return Point2d(p[0] / p[2], p[1] / p[2]);
}

// A 3D point in front of both the reference camera and the moved one, inside both images.
Vec3d pointInView(RNG& rng, const TruePose& pose)
{
    for (;;)
    {
        const double z = rng.uniform(4.0, 30.0);
        const Vec3d X((rng.uniform(40.0, 1160.0) - 600) * z / 700, (rng.uniform(20.0, 340.0) - 180) * z / 700, z);
        const Vec3d Y = pose.R * X + pose.t;
        const Point2d p = project(kK, pose, X);
        if (Y[2] > 1 && p.inside(Rect2d(0, 0, kImage.width, kImage.height)))
            return X;
    }
}

struct Scene
{
    std::vector<Vec6f> segments3d;
    std::vector<Vec4f> segments2d;
    std::vector<Point3f> points3d;
    std::vector<Point2f> points2d;
};

// Segments and points seen by the camera at `pose`: random 3D segments (not along the viewing rays)
// and points, projected exactly.
Scene sceneFor(const TruePose& pose, int lines, int points, uint64 seed)
{
    RNG rng(seed);
    Scene scene;
    while ((int)scene.segments3d.size() < lines)
    {
        const Vec3d A = pointInView(rng, pose), B = pointInView(rng, pose);
        const Point2d a = project(kK, pose, A), b = project(kK, pose, B);
        if (cv::norm(a - b) < 30)
            continue;
        scene.segments3d.push_back(Vec6f((float)A[0], (float)A[1], (float)A[2], (float)B[0], (float)B[1], (float)B[2]));
        scene.segments2d.push_back(Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y));
    }
    while ((int)scene.points3d.size() < points)
    {
        const Vec3d X = pointInView(rng, pose);
        scene.points3d.push_back(Point3f((float)X[0], (float)X[1], (float)X[2]));
        scene.points2d.push_back(Point2f(project(kK, pose, X)));
    }
    return scene;
}

void expectPose(const PoseEstimate& estimate, const TruePose& truth, double maxRotationDeg, double maxTranslation)
{
    ASSERT_TRUE(estimate.solved);
    double rotationError = 0, translationError = 0;
    poseError(estimate.R, estimate.t, Mat(truth.R), Mat(truth.t), rotationError, translationError);
    EXPECT_LE(rotationError, maxRotationDeg);
    EXPECT_LE(translationError, maxTranslation);
}

// The motions of a stereo odometry step (KITTI: a fraction of a degree, a metre forward), of a
// wide-baseline relocalisation (Strecha: 15 degrees, two metres sideways) and a turn of 35 degrees,
// far from the identity pose the minimal solver's Newton steps start from.
const TruePose kMotions[] = { poseOf(Vec3d(0.3, -0.5, 0.1), Vec3d(0.05, -0.02, -1.2)),
                              poseOf(Vec3d(2, 15, -1), Vec3d(-2.0, 0.1, 0.3)),
                              poseOf(Vec3d(5, 35, 3), Vec3d(-3.0, 0.2, 1.0)) };

TEST(LSDAdvance_PoseEstimation, noise_free_lines_give_the_exact_pose)
{
    for (const TruePose& truth : kMotions)
    {
        const Scene scene = sceneFor(truth, 20, 0, 1);
        const PoseEstimate estimate = estimatePose(kK, scene.segments3d, scene.segments2d);
        // float coordinates: exact to their precision
        expectPose(estimate, truth, 1e-3, 1e-4);
        EXPECT_EQ(20, estimate.lineInliers);
        EXPECT_EQ(0, estimate.pointInliers);
    }
}

TEST(LSDAdvance_PoseEstimation, noise_free_points_and_mixed_correspondences_give_the_exact_pose)
{
    for (const TruePose& truth : kMotions)
    {
        const Scene points = sceneFor(truth, 0, 20, 2);
        expectPose(estimatePose(kK, noArray(), noArray(), points.points3d, points.points2d), truth, 1e-3, 1e-4);
        const Scene mixed = sceneFor(truth, 2, 2, 3);  // four correspondences: no sample is all of one kind
        const PoseEstimate estimate =
            estimatePose(kK, mixed.segments3d, mixed.segments2d, mixed.points3d, mixed.points2d,
                         [] { PoseEstimationParams p; p.minInliers = 4; return p; }());
        expectPose(estimate, truth, 1e-3, 1e-4);
        EXPECT_EQ(2, estimate.lineInliers);
        EXPECT_EQ(2, estimate.pointInliers);
    }
}

// Noise on the 2D endpoints and a share of wrong correspondences (2D lines of other 3D segments).
Scene corrupted(Scene scene, double noisePx, double outlierShare, uint64 seed, std::vector<bool>& outlier)
{
    RNG rng(seed);
    const int n = (int)scene.segments2d.size();
    outlier.assign(n, false);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 4; k++)
            scene.segments2d[i][k] += (float)rng.gaussian(noisePx);
    const int outliers = cvRound(outlierShare * n);
    // The first `outliers` 2D lines, each given to the next one's 3D segment.
    std::vector<Vec4f> first(scene.segments2d.begin(), scene.segments2d.begin() + outliers);
    for (int i = 0; i < outliers; i++)
    {
        scene.segments2d[i] = first[(i + 1) % outliers];
        outlier[i] = true;
    }
    return scene;
}

TEST(LSDAdvance_PoseEstimation, noise_and_outliers_degrade_the_pose_gracefully)
{
    const TruePose& truth = kMotions[0];
    const Scene clean = sceneFor(truth, 60, 0, 4);
    double previousRotation = 0;
    for (double noise : { 0.25, 0.5, 1.0 })
    {
        SCOPED_TRACE(cv::format("noise %.2f px, 30 %% outliers", noise));
        std::vector<bool> outlier;
        const Scene scene = corrupted(clean, noise, 0.3, 5, outlier);
        const PoseEstimate estimate = estimatePose(kK, scene.segments3d, scene.segments2d);
        ASSERT_TRUE(estimate.solved);
        double rotationError = 0, translationError = 0;
        poseError(estimate.R, estimate.t, Mat(truth.R), Mat(truth.t), rotationError, translationError);
        // Bounded by the noise: a fraction of a degree and a few percent of the 1.2 m step at 1 px.
        EXPECT_LE(rotationError, 0.1 * noise);
        EXPECT_LE(translationError, 0.05 * noise);
        // Errors grow with the noise, not with the outliers: every wrong line is rejected, and the
        // right ones kept but for those the noise moves past the 2 px threshold.
        int keptOutliers = 0, keptInliers = 0;
        for (size_t i = 0; i < outlier.size(); i++)
            (outlier[i] ? keptOutliers : keptInliers) += estimate.lineInlierMask[i];
        EXPECT_EQ(0, keptOutliers);
        EXPECT_GE(keptInliers, noise < 1 ? 41 : 34);  // of 42
        EXPECT_GE(rotationError, 0.2 * previousRotation);
        previousRotation = rotationError;
    }
}

TEST(LSDAdvance_PoseEstimation, points_agree_with_solve_pnp_on_noisy_inliers)
{
    const TruePose& truth = kMotions[1];
    Scene scene = sceneFor(truth, 0, 80, 6);
    RNG rng(7);
    for (Point2f& p : scene.points2d)
        p += Point2f((float)rng.gaussian(0.3), (float)rng.gaussian(0.3));
    PoseEstimationParams params;
    params.huberWidth = 100;  // least squares, as solvePnP's
    const PoseEstimate estimate = estimatePose(kK, noArray(), noArray(), scene.points3d, scene.points2d, params);
    ASSERT_TRUE(estimate.solved);
    ASSERT_EQ(80, estimate.pointInliers);
    Mat rvec, tvec, R;
    ASSERT_TRUE(solvePnP(scene.points3d, scene.points2d, Mat(kK), noArray(), rvec, tvec, false, SOLVEPNP_ITERATIVE));
    Rodrigues(rvec, R);
    double rotationError = 0, translationError = 0;
    poseError(estimate.R, estimate.t, R, tvec, rotationError, translationError);
    EXPECT_LE(rotationError, 1e-4);
    EXPECT_LE(translationError, 1e-5);
}

TEST(LSDAdvance_PoseEstimation, too_few_or_degenerate_correspondences_are_not_solved)
{
    const TruePose& truth = kMotions[0];
    const Scene scene = sceneFor(truth, 2, 0, 8);
    EXPECT_FALSE(estimatePose(kK, scene.segments3d, scene.segments2d).solved);
    EXPECT_FALSE(estimatePose(kK, noArray(), noArray()).solved);

    // Parallel 3D lines leave the translation along them free: every pose along it fits them all,
    // and none is the pose.
    Scene parallel;
    RNG rng(9);
    for (int i = 0; i < 12; i++)
    {
        const Vec3d A(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0), rng.uniform(8.0, 20.0));
        const Vec3d B = A + Vec3d(0, 2, 0);
        const Point2d a = project(kK, truth, A), b = project(kK, truth, B);
        parallel.segments3d.push_back(Vec6f((float)A[0], (float)A[1], (float)A[2], (float)B[0], (float)B[1], (float)B[2]));
        parallel.segments2d.push_back(Vec4f((float)a.x, (float)a.y, (float)b.x, (float)b.y));
    }
    const PoseEstimate estimate = estimatePose(kK, parallel.segments3d, parallel.segments2d);
    EXPECT_FALSE(estimate.solved);
}

TEST(LSDAdvance_PoseEstimation, the_same_seed_gives_the_same_pose)
{
    std::vector<bool> outlier;
    const Scene scene = corrupted(sceneFor(kMotions[0], 40, 0, 10), 1.0, 0.4, 11, outlier);
    PoseEstimationParams params;
    params.seed = 3;
    const PoseEstimate a = estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params);
    const PoseEstimate b = estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params);
    ASSERT_TRUE(a.solved);
    EXPECT_EQ(0, cvtest::norm(a.R, b.R, NORM_INF));
    EXPECT_EQ(0, cvtest::norm(a.t, b.t, NORM_INF));
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.lineInlierMask, b.lineInlierMask);
}

TEST(LSDAdvance_PoseEstimation, thresholds_and_minimum_inliers_change_the_outcome)
{
    std::vector<bool> outlier;
    const Scene scene = corrupted(sceneFor(kMotions[0], 30, 0, 12), 1.0, 0.0, 13, outlier);
    PoseEstimationParams params;
    const int loose = estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params).lineInliers;
    params.lineThreshold = 0.5;
    const int tight = estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params).lineInliers;
    EXPECT_LT(tight, loose);
    params = PoseEstimationParams();
    params.minInliers = 31;
    EXPECT_FALSE(estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params).solved);
    params.minInliers = 20;
    params.maxIterations = 1;
    EXPECT_EQ(1, estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), params).iterations);
}

TEST(LSDAdvance_PoseEstimation, bad_input_throws)
{
    const Scene scene = sceneFor(kMotions[0], 5, 5, 14);
    std::vector<Vec4f> fewer(scene.segments2d.begin(), scene.segments2d.end() - 1);
    EXPECT_THROW(estimatePose(kK, scene.segments3d, fewer), cv::Exception);
    std::vector<Point2f> fewerPoints(scene.points2d.begin(), scene.points2d.end() - 1);
    EXPECT_THROW(estimatePose(kK, noArray(), noArray(), scene.points3d, fewerPoints), cv::Exception);
    std::vector<Vec4f> zeroLength = scene.segments2d;
    zeroLength[2] = Vec4f(5, 5, 5, 5);
    EXPECT_THROW(estimatePose(kK, scene.segments3d, zeroLength), cv::Exception);
    std::vector<Vec6f> notFinite = scene.segments3d;
    notFinite[1][4] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(estimatePose(kK, notFinite, scene.segments2d), cv::Exception);
    EXPECT_THROW(estimatePose(Mat::eye(2, 2, CV_64F), scene.segments3d, scene.segments2d), cv::Exception);
    EXPECT_THROW(estimatePose(Matx33d(-1, 0, 0, 0, 1, 0, 0, 0, 1), scene.segments3d, scene.segments2d), cv::Exception);
    EXPECT_THROW(estimatePose(kK, Mat(5, 5, CV_32F, Scalar(1)), scene.segments2d), cv::Exception);
    EXPECT_THROW(estimatePose(kK, Mat(5, 6, CV_8U, Scalar(1)), scene.segments2d), cv::Exception);
    for (int bad = 0; bad < 6; bad++)
    {
        PoseEstimationParams p;
        switch (bad)
        {
        case 0: p.maxIterations = 0; break;
        case 1: p.confidence = 1; break;
        case 2: p.lineThreshold = 0; break;
        case 3: p.pointThreshold = std::numeric_limits<double>::infinity(); break;
        case 4: p.huberWidth = -1; break;
        default: p.minInliers = 2; break;
        }
        SCOPED_TRACE(bad);
        EXPECT_THROW(estimatePose(kK, scene.segments3d, scene.segments2d, noArray(), noArray(), p), cv::Exception);
    }
}

TEST(LSDAdvance_PoseEstimation, segments_as_n_by_6_double_arrays_are_accepted)
{
    const Scene scene = sceneFor(kMotions[0], 10, 0, 15);
    Mat rows;
    Mat(scene.segments3d).reshape(1, 10).convertTo(rows, CV_64F);
    ASSERT_EQ(Size(6, 10), rows.size());
    expectPose(estimatePose(kK, rows, scene.segments2d), kMotions[0], 1e-3, 1e-4);
}

TEST(LSDAdvance_PoseEstimation, pose_error_is_the_angle_and_the_distance)
{
    const TruePose a = poseOf(Vec3d(0, 0, 0), Vec3d(1, 2, 3));
    const TruePose b = poseOf(Vec3d(0, 0.01, 0), Vec3d(1, 2, 3.5));
    double rotationError = 0, translationError = 0;
    poseError(Mat(a.R), Mat(a.t), Mat(b.R), Mat(b.t), rotationError, translationError);
    EXPECT_NEAR(0.01, rotationError, 1e-9);
    EXPECT_NEAR(0.5, translationError, 1e-12);
    EXPECT_THROW(poseError(Mat::eye(2, 2, CV_64F), Mat(a.t), Mat(b.R), Mat(b.t), rotationError, translationError),
                 cv::Exception);
}

// ---------------------------------------------------------------- two-view geometry

// A rectified stereo rig (KITTI's calibration) and a general second view.
Matx34d projectionOf(const Matx33d& K, const TruePose& pose)
{
    Matx34d Rt;
    for (int r = 0; r < 3; r++)
    {
        for (int c = 0; c < 3; c++)
            Rt(r, c) = pose.R(r, c);
        Rt(r, 3) = pose.t[r];
    }
    return K * Rt;
}

const TruePose kLeft = poseOf(Vec3d(0, 0, 0), Vec3d(0, 0, 0));
const TruePose kRight = poseOf(Vec3d(0, 0, 0), Vec3d(-0.54, 0, 0));

Vec4f projected(const Matx34d& P, const Vec3d& A, const Vec3d& B)
{
    const Vec3d a = P * Vec4d(A[0], A[1], A[2], 1), b = P * Vec4d(B[0], B[1], B[2], 1);
    return Vec4f((float)(a[0] / a[2]), (float)(a[1] / a[2]), (float)(b[0] / b[2]), (float)(b[1] / b[2]));
}

TEST(LSDAdvance_PoseEstimation, fundamental_from_projections_holds_for_projected_points)
{
    for (const TruePose& second : { kRight, kMotions[1] })
    {
        const Matx34d P1 = projectionOf(kK, kLeft), P2 = projectionOf(kK, second);
        const Mat F = fundamentalFromProjections(Mat(P1), Mat(P2));
        ASSERT_EQ(CV_64F, F.type());
        RNG rng(16);
        for (int i = 0; i < 10; i++)
        {
            const Vec3d X(rng.uniform(-3.0, 3.0), rng.uniform(-1.0, 1.0), rng.uniform(5.0, 30.0));
            const Vec3d x1 = P1 * Vec4d(X[0], X[1], X[2], 1), x2 = P2 * Vec4d(X[0], X[1], X[2], 1);
            const Mat e = Mat(x2 * (1 / x2[2])).t() * F * Mat(x1 * (1 / x1[2]));
            EXPECT_NEAR(0, e.at<double>(0), 1e-9);
        }
    }
    EXPECT_THROW(fundamentalFromProjections(Mat(projectionOf(kK, kLeft)), Mat(projectionOf(kK * 2, kLeft))),
                 cv::Exception);
    EXPECT_THROW(fundamentalFromProjections(Mat::eye(3, 3, CV_64F), Mat(projectionOf(kK, kLeft))), cv::Exception);
}

TEST(LSDAdvance_PoseEstimation, stereo_segments_are_lifted_to_their_3d_segments)
{
    const Matx34d P1 = projectionOf(kK, kLeft), P2 = projectionOf(kK, kRight);
    // A vertical pole, a slanted edge, a horizontal edge (undefined depth), and one behind the rig.
    const Vec3d A[] = { Vec3d(1, -1, 10), Vec3d(-2, 0.5, 15), Vec3d(-1, 0.2, 8), Vec3d(0, 0, 10) };
    const Vec3d B[] = { Vec3d(1, 1, 10), Vec3d(-1, -0.5, 18), Vec3d(1, 0.2, 8), Vec3d(0, 1, 10) };
    std::vector<Vec4f> left, right;
    for (int i = 0; i < 4; i++)
    {
        left.push_back(projected(P1, A[i], B[i]));
        right.push_back(projected(P2, A[i], B[i]));
    }
    std::swap(right[3][0], right[3][2]);  // a wrong match: the right segment crosses the left one's rows the other way
    right[3] = Vec4f(right[3][0] + 200, right[3][1], right[3][2] + 200, right[3][3]);  // negative disparity
    std::vector<DMatch> matches;
    for (int i = 0; i < 4; i++)
        matches.push_back(DMatch(i, i, 0));
    Mat lifted;
    std::vector<int> kept;
    triangulateSegments(Mat(P1), Mat(P2), left, right, matches, lifted, kept);
    ASSERT_EQ(CV_32FC(6), lifted.type());
    ASSERT_EQ((std::vector<int>{ 0, 1 }), kept);
    for (int k = 0; k < 2; k++)
    {
        const Vec6f s = lifted.at<Vec6f>(k);
        for (int c = 0; c < 3; c++)
        {
            EXPECT_NEAR(A[k][c], s[c], 1e-3) << "segment " << k;
            EXPECT_NEAR(B[k][c], s[3 + c], 1e-3) << "segment " << k;
        }
    }
    // Without the angle limit the horizontal edge is still dropped: its two planes are one.
    triangulateSegments(Mat(P1), Mat(P2), left, right, matches, lifted, kept, 0.0);
    EXPECT_EQ(2u, kept.size());
}

TEST(LSDAdvance_PoseEstimation, lifted_segments_are_clipped_to_what_both_views_observe)
{
    const Matx34d P1 = projectionOf(kK, kLeft), P2 = projectionOf(kK, kMotions[1]);
    const Vec3d A(1, -1, 10), B(1.5, 1, 11);
    const Vec3d M1 = A + (B - A) * 0.3, M2 = A + (B - A) * 0.8;
    // View 1 sees A..M2, view 2 sees M1..B: both see M1..M2, 5/7 of the shorter, view 2's.
    const std::vector<Vec4f> view1 = { projected(P1, A, M2) }, view2 = { projected(P2, M1, B) };
    const std::vector<DMatch> matches = { DMatch(0, 0, 0) };
    Mat lifted;
    std::vector<int> kept;
    triangulateSegments(Mat(P1), Mat(P2), view1, view2, matches, lifted, kept, 1.0, 0.5);
    ASSERT_EQ(1u, kept.size());
    const Vec6f s = lifted.at<Vec6f>(0);
    for (int c = 0; c < 3; c++)
    {
        EXPECT_NEAR(M1[c], s[c], 1e-3);
        EXPECT_NEAR(M2[c], s[3 + c], 1e-3);
    }
    triangulateSegments(Mat(P1), Mat(P2), view1, view2, matches, lifted, kept, 1.0, 0.75);
    EXPECT_TRUE(kept.empty());
    EXPECT_EQ(0, lifted.rows);
}

TEST(LSDAdvance_PoseEstimation, triangulation_rejects_bad_input)
{
    const Matx34d P1 = projectionOf(kK, kLeft), P2 = projectionOf(kK, kRight);
    const std::vector<Vec4f> segments = { Vec4f(10, 10, 20, 40) };
    Mat lifted;
    std::vector<int> kept;
    EXPECT_THROW(triangulateSegments(Mat(P1), Mat(P2), segments, segments, { DMatch(0, 1, 0) }, lifted, kept),
                 cv::Exception);
    EXPECT_THROW(triangulateSegments(Mat(P1), Mat(P1), segments, segments, { DMatch(0, 0, 0) }, lifted, kept),
                 cv::Exception);
    EXPECT_THROW(triangulateSegments(Mat(P1), Mat(P2), segments, segments, { DMatch(0, 0, 0) }, lifted, kept, 90.0),
                 cv::Exception);
    EXPECT_THROW(triangulateSegments(Mat(P1), Mat(P2), segments, segments, { DMatch(0, 0, 0) }, lifted, kept, 10.0,
                                     1.5),
                 cv::Exception);
    EXPECT_THROW(triangulateSegments(Mat::zeros(3, 4, CV_64F), Mat(P2), segments, segments, { DMatch(0, 0, 0) },
                                     lifted, kept),
                 cv::Exception);
    // A zero-length segment is dropped, not an error.
    const std::vector<Vec4f> point = { Vec4f(10, 10, 10, 10) };
    triangulateSegments(Mat(P1), Mat(P2), point, segments, { DMatch(0, 0, 0) }, lifted, kept);
    EXPECT_TRUE(kept.empty());
}

}} // namespace opencv_test::
