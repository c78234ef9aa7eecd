// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Correctness of line matches: under a known homography (correspondence, repeatability,
// localisation error) and between frames with known poses (epipolar consistency).
// The criteria are defined in doc/matching.md.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace line_evaluation {

namespace {

Matx33d toMatx33d(InputArray m, const char* what)
{
    const Mat mat = m.getMat();
    if (mat.rows != 3 || mat.cols != 3 || mat.channels() != 1 || (mat.depth() != CV_32F && mat.depth() != CV_64F))
        CV_Error_(Error::StsBadArg, ("%s must be a 3x3 CV_32F or CV_64F matrix, got %s %dx%d", what,
                                     typeToString(mat.type()).c_str(), mat.cols, mat.rows));
    Matx33d out;
    mat.convertTo(Mat(out, false), CV_64F);
    if (!checkRange(Mat(out, false)))
        CV_Error_(Error::StsOutOfRange, ("%s must be finite", what));
    return out;
}

void checkDistance(double value, const char* caller, const char* name)
{
    if (!(value >= 0) || !std::isfinite(value))
        CV_Error_(Error::StsOutOfRange, ("%s: %s must be a finite number >= 0 (pixels), got %g", caller, name, value));
}

// The image of p under H; false when H sends it to (or beyond) infinity.
bool mapPoint(const Matx33d& H, const Point2d& p, Point2d& mapped)
{
    const Vec3d q = H * Vec3d(p.x, p.y, 1.0);
    if (!(q[2] > 1e-12 || q[2] < -1e-12))
        return false;
    mapped = Point2d(q[0] / q[2], q[1] / q[2]);
    return std::isfinite(mapped.x) && std::isfinite(mapped.y);
}

// A segment mapped by a homography; valid is false when an endpoint goes to infinity.
struct MappedSegment
{
    Point2d p1, p2;
    bool valid;
};

MappedSegment mapSegment(const Matx33d& H, const Vec4f& s)
{
    MappedSegment m;
    m.valid = mapPoint(H, Point2d(s[0], s[1]), m.p1) && mapPoint(H, Point2d(s[2], s[3]), m.p2);
    return m;
}

// Mean perpendicular distance of the mapped endpoints to b's line when they correspond (both
// within maxDistance, overlapping extents); negative otherwise.
double correspondenceError(const MappedSegment& a, const Vec4f& b, double maxDistance)
{
    if (!a.valid)
        return -1.0;
    const Point2d b1(b[0], b[1]), b2(b[2], b[3]);
    const double length = norm(b2 - b1);
    if (!(length > 0))
        return -1.0;
    const Point2d dir = (b2 - b1) * (1.0 / length);
    const double d1 = std::abs(dir.cross(a.p1 - b1)), d2 = std::abs(dir.cross(a.p2 - b1));
    if (d1 > maxDistance || d2 > maxDistance)
        return -1.0;
    const double t1 = dir.dot(a.p1 - b1), t2 = dir.dot(a.p2 - b1);
    const double overlap = std::min(std::max(t1, t2), length) - std::max(std::min(t1, t2), 0.0);
    return overlap > 0 ? 0.5 * (d1 + d2) : -1.0;
}

// Pixel-centre convention: the image covers [-0.5, size - 0.5] on each axis.
bool inside(const Point2d& p, Size size)
{
    return p.x >= -0.5 && p.y >= -0.5 && p.x <= size.width - 0.5 && p.y <= size.height - 0.5;
}

// Adds the repeatability counts of `from` mapped by H into an image of size `size` holding `to`.
void countRepeated(const std::vector<Vec4f>& from, const std::vector<Vec4f>& to, const Matx33d& H, Size size,
                   double maxDistance, HomographyMatchScore& score, double& errorSum)
{
    for (const Vec4f& s : from)
    {
        const MappedSegment m = mapSegment(H, s);
        if (!m.valid || !inside(m.p1, size) || !inside(m.p2, size))
            continue;
        score.visible++;
        double best = -1.0;
        for (const Vec4f& t : to)
        {
            const double e = correspondenceError(m, t, maxDistance);
            if (e >= 0 && (best < 0 || e < best))
                best = e;
        }
        if (best >= 0)
        {
            score.repeated++;
            errorSum += best;
        }
    }
}

void checkMatch(const DMatch& m, size_t n1, size_t n2)
{
    if (m.queryIdx < 0 || (size_t)m.queryIdx >= n1 || m.trainIdx < 0 || (size_t)m.trainIdx >= n2)
        CV_Error_(Error::StsOutOfRange, ("match (%d, %d) is out of range: %zu query and %zu train segments",
                                         m.queryIdx, m.trainIdx, n1, n2));
}

// checkEpipolar after validation; minSine is the sine of its minAngle.
int epipolarVerdict(const Vec4f& a, const Vec4f& b, const Matx33d& F, double tolerance, double minSine)
{
    const Point2d b1(b[0], b[1]), b2(b[2], b[3]);
    const double length = norm(b2 - b1);
    if (!(length > 0))
        return EPIPOLAR_UNDECIDABLE;
    const Point2d dir = (b2 - b1) * (1.0 / length);

    // Position along b (0 at b1, pixels) where the epipolar line of each endpoint of a cuts b's line.
    double t[2];
    for (int k = 0; k < 2; k++)
    {
        const Vec3d l = F * Vec3d(a[2 * k], a[2 * k + 1], 1.0);
        const double normalLength = std::hypot(l[0], l[1]);
        if (!(normalLength > 0))
            return EPIPOLAR_UNDECIDABLE;  // the endpoint is the epipole: no epipolar line
        // The sine of the angle between b and the epipolar line.
        const double along = (l[0] * dir.x + l[1] * dir.y) / normalLength;
        if (std::abs(along) <= minSine)
            return EPIPOLAR_UNDECIDABLE;
        t[k] = -(l[0] * b1.x + l[1] * b1.y + l[2]) / (along * normalLength);
    }
    const double lo = std::min(t[0], t[1]), hi = std::max(t[0], t[1]);
    return std::max(lo, -tolerance) <= std::min(hi, length + tolerance) ? EPIPOLAR_CONSISTENT
                                                                          : EPIPOLAR_INCONSISTENT;
}

// Validates checkEpipolar's thresholds; returns the sine of minAngle.
double epipolarMinSine(double tolerance, double minAngle, const char* caller)
{
    checkDistance(tolerance, caller, "tolerance");
    if (!(minAngle >= 0 && minAngle < 90))
        CV_Error_(Error::StsOutOfRange, ("%s: minAngle must be in [0, 90) deg, got %g", caller, minAngle));
    return std::sin(minAngle * CV_PI / 180.0);
}

} // namespace

bool correspondUnderHomography(const Vec4f& a, const Vec4f& b, InputArray H, double maxDistance)
{
    checkDistance(maxDistance, "correspondUnderHomography", "maxDistance");
    return correspondenceError(mapSegment(toMatx33d(H, "correspondUnderHomography: H"), a), b, maxDistance) >= 0;
}

HomographyMatchScore evaluateHomographyMatches(InputArray segments1In, InputArray segments2In,
                                               const std::vector<DMatch>& matches, InputArray HIn,
                                               Size imageSize1, Size imageSize2, double maxDistance)
{
    CV_INSTRUMENT_REGION();
    checkDistance(maxDistance, "evaluateHomographyMatches", "maxDistance");
    CV_CheckGT(imageSize1.area(), 0, "evaluateHomographyMatches: imageSize1 must not be empty");
    CV_CheckGT(imageSize2.area(), 0, "evaluateHomographyMatches: imageSize2 must not be empty");
    const std::vector<Vec4f> segments1 = lsda::toSegments(segments1In, "evaluateHomographyMatches: segments1");
    const std::vector<Vec4f> segments2 = lsda::toSegments(segments2In, "evaluateHomographyMatches: segments2");
    const Matx33d H = toMatx33d(HIn, "evaluateHomographyMatches: H");
    if (!(std::abs(determinant(H)) > 1e-12))
        CV_Error(Error::StsBadArg, "evaluateHomographyMatches: H must be invertible");

    HomographyMatchScore score;
    for (const DMatch& m : matches)
    {
        checkMatch(m, segments1.size(), segments2.size());
        score.matches++;
        score.correct += correspondenceError(mapSegment(H, segments1[m.queryIdx]), segments2[m.trainIdx], maxDistance) >= 0;
    }
    score.precision = score.matches > 0 ? (double)score.correct / score.matches : 0.0;

    double errorSum = 0;
    countRepeated(segments1, segments2, H, imageSize2, maxDistance, score, errorSum);
    countRepeated(segments2, segments1, H.inv(), imageSize1, maxDistance, score, errorSum);
    score.repeatability = score.visible > 0 ? (double)score.repeated / score.visible : 0.0;
    score.localisationError = score.repeated > 0 ? errorSum / score.repeated : 0.0;
    return score;
}

int checkEpipolar(const Vec4f& a, const Vec4f& b, InputArray F, double tolerance, double minAngle)
{
    const double minSine = epipolarMinSine(tolerance, minAngle, "checkEpipolar");
    return epipolarVerdict(a, b, toMatx33d(F, "checkEpipolar: F"), tolerance, minSine);
}

Mat fundamentalFromPoses(InputArray PIn, InputArray pose1In, InputArray pose2In)
{
    Mat P, pose1, pose2;
    const Mat inputs[3] = { PIn.getMat(), pose1In.getMat(), pose2In.getMat() };
    const char* names[3] = { "P", "pose1", "pose2" };
    Mat* outputs[3] = { &P, &pose1, &pose2 };
    for (int i = 0; i < 3; i++)
    {
        if (inputs[i].rows != 3 || inputs[i].cols != 4 || inputs[i].channels() != 1)
            CV_Error_(Error::StsBadArg, ("fundamentalFromPoses: %s must be a 3x4 single-channel matrix, got %s %dx%d",
                                         names[i], typeToString(inputs[i].type()).c_str(), inputs[i].cols, inputs[i].rows));
        inputs[i].convertTo(*outputs[i], CV_64F);
        if (!checkRange(*outputs[i]))
            CV_Error_(Error::StsOutOfRange, ("fundamentalFromPoses: %s must be finite", names[i]));
    }
    const Matx33d K(P(Rect(0, 0, 3, 3)));
    if (norm(P.col(3)) > 1e-9 * norm(K) || !(std::abs(determinant(K)) > 0))
        CV_Error(Error::StsBadArg, "fundamentalFromPoses: P must be K [I | 0] with K invertible");
    const Matx33d R1(pose1(Rect(0, 0, 3, 3))), R2(pose2(Rect(0, 0, 3, 3)));
    const Vec3d t1(pose1(Rect(3, 0, 1, 3))), t2(pose2(Rect(3, 0, 1, 3)));
    // Camera 1 to camera 2: X2 = R2^T (R1 X1 + t1 - t2).
    const Matx33d R = R2.t() * R1;
    const Vec3d t = R2.t() * (t1 - t2);
    if (!(norm(t) > 1e-12))
        CV_Error(Error::StsBadArg, "fundamentalFromPoses: the two poses share their camera centre; F is undefined");
    const Matx33d tx(0, -t[2], t[1], t[2], 0, -t[0], -t[1], t[0], 0);
    const Matx33d Kinv = K.inv();
    Matx33d F = Kinv.t() * tx * R * Kinv;
    F *= 1.0 / norm(F);
    return Mat(F, true);
}

EpipolarMatchScore evaluateEpipolarMatches(InputArray segments1In, InputArray segments2In,
                                           const std::vector<DMatch>& matches, InputArray FIn,
                                           double tolerance, double minAngle)
{
    CV_INSTRUMENT_REGION();
    const std::vector<Vec4f> segments1 = lsda::toSegments(segments1In, "evaluateEpipolarMatches: segments1");
    const std::vector<Vec4f> segments2 = lsda::toSegments(segments2In, "evaluateEpipolarMatches: segments2");
    const double minSine = epipolarMinSine(tolerance, minAngle, "evaluateEpipolarMatches");
    const Matx33d F = toMatx33d(FIn, "evaluateEpipolarMatches: F");
    EpipolarMatchScore score;
    for (const DMatch& m : matches)
    {
        checkMatch(m, segments1.size(), segments2.size());
        score.matches++;
        switch (epipolarVerdict(segments1[m.queryIdx], segments2[m.trainIdx], F, tolerance, minSine))
        {
        case EPIPOLAR_CONSISTENT: score.consistent++; break;
        case EPIPOLAR_INCONSISTENT: score.inconsistent++; break;
        default: score.undecidable++; break;
        }
    }
    const int decided = score.consistent + score.inconsistent;
    score.precision = decided > 0 ? (double)score.consistent / decided : 0.0;
    return score;
}

}}} // namespace cv::ximgproc::line_evaluation
