// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// 3D segments from segments matched between two views of known cameras (doc/pose.md): the 3D line
// is where the two back-projected planes meet, its extent what both segments observe of it.

#include "precomp.hpp"
#include "opencv2/lsd_advance/pose_evaluation.hpp"

namespace cv {
namespace ximgproc {
namespace line_evaluation {

namespace {

// A camera of a 3x4 projection matrix P = [M | p]: its centre, and the rays through its pixels.
struct Camera
{
    Matx34d P;
    Matx33d Minv;
    Vec3d centre;
    double depthSign = 1;  //!< sign(det M): the third coordinate of P X times it is positive in front

    explicit Camera(InputArray projection, const char* what)
    {
        Mat P64;
        if (!projection.empty())
            projection.getMat().convertTo(P64, CV_64F);
        if (P64.rows != 3 || P64.cols != 4 || !checkRange(P64))
            CV_Error_(Error::StsBadArg, ("%s must be a finite 3x4 projection matrix", what));
        P = Matx34d(P64);
        const Matx33d M = P.get_minor<3, 3>(0, 0);
        const double det = determinant(M);
        if (!(std::abs(det) > 0))
            CV_Error_(Error::StsBadArg, ("%s is singular: its left 3x3 block must be invertible (a finite camera)", what));
        Minv = M.inv();
        centre = -(Minv * Vec3d(P(0, 3), P(1, 3), P(2, 3)));
        depthSign = det > 0 ? 1 : -1;
    }

    Vec3d rayThrough(const Point2d& pixel) const { return Minv * Vec3d(pixel.x, pixel.y, 1); }
    Vec3d project(const Vec3d& X) const { return P * Vec4d(X[0], X[1], X[2], 1); }
    bool inFront(const Vec3d& X) const { return depthSign * project(X)[2] > 0; }
    //! The plane (n, d) of the points X with n . X + d = 0 that project onto the image line l.
    Vec4d planeOf(const Vec3d& l) const { return P.t() * l; }
};

// The homogeneous line through a segment, scaled so that its normal (l0, l1) is a unit vector.
Vec3d lineThrough(const Vec4f& s)
{
    const Vec3d l = Vec3d(s[0], s[1], 1).cross(Vec3d(s[2], s[3], 1));
    return l * (1.0 / std::hypot(l[0], l[1]));
}

// Whether segment s runs at least minAngle (radians) away from the epipolar line through its
// midpoint, for the epipole e (homogeneous, possibly at infinity).
bool awayFromEpipolarLine(const Vec4f& s, const Vec3d& e, double minAngle)
{
    const Vec3d mid(0.5 * (s[0] + s[2]), 0.5 * (s[1] + s[3]), 1);
    const Vec3d epipolar = e.cross(mid);
    const double epipolarNorm = std::hypot(epipolar[0], epipolar[1]);
    if (!(epipolarNorm > 0))
        return false;  // the midpoint is the epipole
    // The sine of the angle between the segment and the epipolar line: the segment's direction dotted
    // with the line's unit normal.
    const double dx = s[2] - s[0], dy = s[3] - s[1];
    const double sine = std::abs(dx * epipolar[0] + dy * epipolar[1]) / (std::hypot(dx, dy) * epipolarNorm);
    return sine >= std::sin(minAngle);
}

// Where the ray of a pixel of camera `from` meets the plane; false when it runs parallel to it.
bool rayMeetsPlane(const Camera& from, const Point2d& pixel, const Vec4d& plane, Vec3d& X)
{
    const Vec3d n(plane[0], plane[1], plane[2]), ray = from.rayThrough(pixel);
    const double along = n.dot(ray);
    if (!(std::abs(along) > 1e-12 * norm(n) * norm(ray)))
        return false;
    X = from.centre + ray * (-(n.dot(from.centre) + plane[3]) / along);
    return true;
}

} // namespace

Mat fundamentalFromProjections(InputArray P1, InputArray P2)
{
    CV_INSTRUMENT_REGION();
    const Camera camera1(P1, "P1"), camera2(P2, "P2");
    const Vec3d e2 = camera2.project(camera1.centre);
    if (!(norm(camera1.centre - camera2.centre) > 0))
        CV_Error(Error::StsBadArg, "fundamentalFromProjections: the two cameras share their centre");
    // F = [e2]x P2 P1^+, with P1^+ = [M1^-1; 0] completed by the centre: P2 P1^+ = M2 M1^-1.
    const Matx33d M2 = camera2.P.get_minor<3, 3>(0, 0);
    const Matx33d e2x(0, -e2[2], e2[1], e2[2], 0, -e2[0], -e2[1], e2[0], 0);
    const Matx33d F = e2x * M2 * camera1.Minv;
    return Mat(F * (1.0 / norm(F)));
}

void triangulateSegments(InputArray P1, InputArray P2, InputArray segments1In, InputArray segments2In,
                         const std::vector<DMatch>& matches, OutputArray segments3d, std::vector<int>& kept,
                         double minEpipolarAngle, double minOverlap)
{
    CV_INSTRUMENT_REGION();
    if (!(minEpipolarAngle >= 0 && minEpipolarAngle < 90) || !(minOverlap >= 0 && minOverlap <= 1))
        CV_Error_(Error::StsOutOfRange, ("triangulateSegments: expected minEpipolarAngle in [0, 90) degrees and "
                                         "minOverlap in [0, 1], got %g and %g", minEpipolarAngle, minOverlap));
    const Camera camera1(P1, "P1"), camera2(P2, "P2");
    if (!(norm(camera1.centre - camera2.centre) > 0))
        CV_Error(Error::StsBadArg, "triangulateSegments: the two cameras share their centre");
    const std::vector<Vec4f> segments1 = lsda::toSegments(segments1In, "segments1");
    const std::vector<Vec4f> segments2 = lsda::toSegments(segments2In, "segments2");
    const Vec3d epipole1 = camera1.project(camera2.centre), epipole2 = camera2.project(camera1.centre);
    const double minAngle = minEpipolarAngle * CV_PI / 180.0;

    std::vector<Vec6f> lifted;
    kept.clear();
    for (size_t m = 0; m < matches.size(); m++)
    {
        const int i = matches[m].queryIdx, j = matches[m].trainIdx;
        if (i < 0 || i >= (int)segments1.size() || j < 0 || j >= (int)segments2.size())
            CV_Error_(Error::StsOutOfRange, ("triangulateSegments: match %zu (%d -> %d) is out of range (%zu and %zu "
                                             "segments)", m, i, j, segments1.size(), segments2.size()));
        const Vec4f& s1 = segments1[i];
        const Vec4f& s2 = segments2[j];
        if (!(lsda::segmentLength(s1) > 0) || !(lsda::segmentLength(s2) > 0) ||
            !awayFromEpipolarLine(s1, epipole1, minAngle) || !awayFromEpipolarLine(s2, epipole2, minAngle))
            continue;
        const Vec4d plane1 = camera1.planeOf(lineThrough(s1)), plane2 = camera2.planeOf(lineThrough(s2));
        // Each segment's endpoints on the 3D line: their rays meet the other view's plane, in front of
        // their camera (behind it, the segment would be the 3D line's part through infinity).
        Vec3d A1, B1, A2, B2;
        if (!rayMeetsPlane(camera1, Point2d(s1[0], s1[1]), plane2, A1) ||
            !rayMeetsPlane(camera1, Point2d(s1[2], s1[3]), plane2, B1) ||
            !rayMeetsPlane(camera2, Point2d(s2[0], s2[1]), plane1, A2) ||
            !rayMeetsPlane(camera2, Point2d(s2[2], s2[3]), plane1, B2) || !camera1.inFront(A1) ||
            !camera1.inFront(B1) || !camera2.inFront(A2) || !camera2.inFront(B2))
            continue;
        const double length1 = norm(B1 - A1);
        if (!(length1 > 0))
            continue;
        // Positions along the line from A1 towards B1: segment 1 spans [0, length1].
        const Vec3d u = (B1 - A1) * (1.0 / length1);
        const double a2 = (A2 - A1).dot(u), b2 = (B2 - A1).dot(u);
        const double lo = std::max(0.0, std::min(a2, b2)), hi = std::min(length1, std::max(a2, b2));
        const double shorter = std::min(length1, std::abs(b2 - a2));
        if (!(hi > lo) || hi - lo < minOverlap * shorter)
            continue;
        const Vec3d start = A1 + u * lo, end = A1 + u * hi;
        if (!camera1.inFront(start) || !camera1.inFront(end) || !camera2.inFront(start) || !camera2.inFront(end))
            continue;
        lifted.push_back(Vec6f((float)start[0], (float)start[1], (float)start[2], (float)end[0], (float)end[1],
                               (float)end[2]));
        kept.push_back((int)m);
    }
    segments3d.create((int)lifted.size(), 1, CV_32FC(6));
    if (!lifted.empty())
        Mat(lifted).copyTo(segments3d.getMat());
}

}}} // namespace cv::ximgproc::line_evaluation
