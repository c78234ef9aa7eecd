// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Structural precision/recall of line segments against ground truth, and data set loaders.

#include "precomp.hpp"
#include "opencv2/core/utils/filesystem.hpp"
#include "opencv2/lsd_advance/pose_evaluation.hpp"

#include <fstream>
#include <sstream>

namespace cv {
namespace ximgproc {
namespace line_evaluation {

namespace {

// Length of the union of [lo, hi] intervals.
double unionLength(std::vector<std::pair<double, double> >& intervals)
{
    std::sort(intervals.begin(), intervals.end());
    double total = 0, end = -DBL_MAX;
    for (const auto& iv : intervals)
    {
        const double lo = std::max(iv.first, end);
        if (iv.second > lo)
            total += iv.second - lo;
        end = std::max(end, iv.second);
    }
    return total;
}

void checkParams(const StructuralMatchParams& p)
{
    const bool ok = std::isfinite(p.maxDistance) && p.maxDistance >= 0 && std::isfinite(p.maxAngle) &&
                    p.maxAngle >= 0 && p.maxAngle <= 90 && p.minCoverage > 0 && p.minCoverage <= 1 &&
                    std::isfinite(p.offset);
    if (!ok)
        CV_Error_(Error::StsOutOfRange,
                  ("StructuralMatchParams: expected maxDistance >= 0, maxAngle in [0, 90] deg, minCoverage in (0, 1] "
                   "and a finite offset; got %g, %g, %g, %g",
                   p.maxDistance, p.maxAngle, p.minCoverage, p.offset));
}

std::vector<String> imagesIn(const String& folder)
{
    std::vector<String> paths;
    for (const char* pattern : { "*.png", "*.jpg", "*.jpeg", "*.ppm", "*.pgm", "*.bmp" })
    {
        std::vector<String> found;
        glob(utils::fs::join(folder, pattern), found, false);
        paths.insert(paths.end(), found.begin(), found.end());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

// Rows of finite numbers of a text file; with labelled, a leading "NAME:" token on a row is skipped.
std::vector<std::vector<double> > readNumberRows(const String& path, bool labelled)
{
    std::ifstream in(path.c_str());
    if (!in)
        CV_Error_(Error::StsError, ("cannot open %s", path.c_str()));
    std::vector<std::vector<double> > rows;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); lineNo++)
    {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
            continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream tokens(line);
        std::vector<double> row;
        std::string token;
        while (tokens >> token)
        {
            if (labelled && row.empty() && token.back() == ':')
                continue;
            char* end = nullptr;
            const double v = std::strtod(token.c_str(), &end);
            if (end == token.c_str() || *end != '\0' || !std::isfinite(v))
                CV_Error_(Error::StsParseError, ("%s:%d: '%s' is not a finite number", path.c_str(), lineNo, token.c_str()));
            row.push_back(v);
        }
        rows.push_back(row);
    }
    return rows;
}

Mat matrix3x4(const std::vector<double>& row, const String& path)
{
    if (row.size() != 12)
        CV_Error_(Error::StsParseError, ("%s: expected 12 numbers per row (a 3x4 matrix), got %zu",
                                         path.c_str(), row.size()));
    return Mat(row, true).reshape(1, 3);
}

// The right camera's frames beside the left ones of `left` (a subfolder of the sequence): the
// same names, each one there; none when the sequence has no right folder.
std::vector<String> rightImagesOf(const String& folder, const char* left, const std::vector<String>& leftPaths)
{
    const std::string leftName = left;
    const std::string rightName = leftName == "image_l" ? "image_r" : leftName == "image_0" ? "image_1" : "cam1/data";
    const String rightDir = utils::fs::join(folder, rightName);
    std::vector<String> paths;
    if (!*left || !utils::fs::isDirectory(rightDir))
        return paths;
    for (const String& leftPath : leftPaths)
    {
        const String path = utils::fs::join(rightDir, leftPath.substr(leftPath.find_last_of("/\\") + 1));
        if (!utils::fs::exists(path))
            CV_Error_(Error::StsError, ("missing right image %s (%s/ must hold a frame of each name in %s/)",
                                        path.c_str(), rightName.c_str(), left));
        paths.push_back(path);
    }
    return paths;
}


// One view of a Strecha-style camera file: K (3 rows), distortion (1 row, zero), R (3 rows, camera
// to world), the centre C (1 row), W H (1 row).
void readCameraFile(const String& path, MultiViewData& data)
{
    const std::vector<std::vector<double> > rows = readNumberRows(path, false);
    const size_t widths[] = { 3, 3, 3, 3, 3, 3, 3, 3, 2 };
    bool ok = rows.size() == 9;
    for (size_t r = 0; ok && r < rows.size(); r++)
        ok = rows[r].size() == widths[r];
    if (!ok)
        CV_Error_(Error::StsParseError, ("%s: expected 9 rows: K (3 rows of 3), the distortion (3), R (3 rows of 3), "
                                         "the centre C (3) and the image size W H", path.c_str()));
    Mat K(3, 3, CV_64F), R(3, 3, CV_64F), C(3, 1, CV_64F);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
        {
            K.at<double>(r, c) = rows[r][c];
            R.at<double>(r, c) = rows[4 + r][c];
            C.at<double>(c) = rows[7][c];
        }
    if (!(K.at<double>(0, 0) > 0 && K.at<double>(1, 1) > 0) || K.at<double>(1, 0) != 0 || K.at<double>(2, 0) != 0 ||
        K.at<double>(2, 1) != 0 || K.at<double>(2, 2) != 1)
        CV_Error_(Error::StsParseError, ("%s: K must be [fx s cx; 0 fy cy; 0 0 1] with fx, fy > 0", path.c_str()));
    if (rows[3][0] != 0 || rows[3][1] != 0 || rows[3][2] != 0)
        CV_Error_(Error::StsParseError, ("%s: the distortion must be 0 0 0 (undistorted images)", path.c_str()));
    // The file's 6 significant digits leave R orthonormal to about 1e-6.
    if (norm(R.t() * R, Mat::eye(3, 3, CV_64F), NORM_INF) > 1e-4 || !(determinant(R) > 0))
        CV_Error_(Error::StsParseError, ("%s: R is not a rotation", path.c_str()));
    if (!(rows[8][0] >= 1 && rows[8][1] >= 1))
        CV_Error_(Error::StsParseError, ("%s: the image size must be positive", path.c_str()));
    Mat pose;
    hconcat(R, C, pose);
    data.cameraMatrices.push_back(K);
    data.poses.push_back(pose);
    data.imageSizes.push_back(Size(cvRound(rows[8][0]), cvRound(rows[8][1])));
}

} // namespace

StructuralScore evaluateStructural(InputArray detectionsIn, InputArray groundTruthIn,
                                   const StructuralMatchParams& params)
{
    CV_INSTRUMENT_REGION();
    checkParams(params);
    std::vector<Vec4f> detections = lsda::toSegments(detectionsIn, "detections");
    const std::vector<Vec4f> groundTruth = lsda::toSegments(groundTruthIn, "groundTruth");
    const float offset = (float)params.offset;
    for (Vec4f& d : detections)
        d += Vec4f(offset, offset, offset, offset);

    StructuralScore score;
    std::vector<double> detectionLength(detections.size()), matched(detections.size(), 0.0);
    for (size_t i = 0; i < detections.size(); i++)
    {
        detectionLength[i] = lsda::segmentLength(detections[i]);
        score.detectedLength += detectionLength[i];
    }

    const double cosMaxAngle = std::cos(params.maxAngle * CV_PI / 180.0);
    std::vector<std::pair<double, double> > intervals;
    std::vector<std::pair<size_t, double> > clipped;  // (detection, clipped length) of one g
    for (const Vec4f& g : groundTruth)
    {
        const double len = lsda::segmentLength(g);
        if (len <= 0)
            continue;
        score.groundTruthCount++;
        score.groundTruthLength += len;
        const Point2d origin(g[0], g[1]), dir = Point2d(g[2] - g[0], g[3] - g[1]) * (1.0 / len);
        intervals.clear();
        clipped.clear();
        for (size_t i = 0; i < detections.size(); i++)
        {
            const Vec4f& d = detections[i];
            if (detectionLength[i] <= 0)
                continue;
            const Point2d a(d[0], d[1]), b(d[2], d[3]);
            const Point2d centre = (a + b) * 0.5;
            if (std::abs(dir.cross(centre - origin)) > params.maxDistance)
                continue;
            if (std::abs(dir.dot(b - a)) < cosMaxAngle * detectionLength[i])
                continue;
            double lo = dir.dot(a - origin), hi = dir.dot(b - origin);
            if (lo > hi)
                std::swap(lo, hi);
            lo = std::max(lo, 0.0);
            hi = std::min(hi, len);
            if (hi <= lo)
                continue;
            intervals.push_back(std::make_pair(lo, hi));
            clipped.push_back(std::make_pair(i, hi - lo));
        }
        const double covered = unionLength(intervals);
        if (covered < params.minCoverage * len)
            continue;
        score.found++;
        score.coveredLength += covered;
        for (const auto& c : clipped)
            matched[c.first] += c.second;
    }
    for (size_t i = 0; i < detections.size(); i++)
        score.matchedLength += std::min(matched[i], detectionLength[i]);
    score.precision = score.detectedLength > 0 ? score.matchedLength / score.detectedLength : 0.0;
    score.recall = score.groundTruthLength > 0 ? score.coveredLength / score.groundTruthLength : 0.0;
    return score;
}

double fScore(double averagePrecision, double averageRecall)
{
    const double sum = averagePrecision + averageRecall;
    return sum > 0 ? 2.0 * averagePrecision * averageRecall / sum : 0.0;
}

double longSegmentShare(InputArray linesIn, double minLength)
{
    const std::vector<Vec4f> lines = lsda::toSegments(linesIn, "lines");
    if (lines.empty())
        return 0.0;
    size_t longOnes = 0;
    for (const Vec4f& l : lines)
        longOnes += lsda::segmentLength(l) >= minLength;
    return (double)longOnes / (double)lines.size();
}

std::vector<Vec4f> readSegments(const String& path)
{
    std::vector<Vec4f> segments;
    for (const std::vector<double>& row : readNumberRows(path, false))
    {
        if (row.size() != 4)
            CV_Error_(Error::StsParseError, ("%s: expected 4 numbers (x1 y1 x2 y2) per row, got %zu",
                                             path.c_str(), row.size()));
        segments.push_back(Vec4f((float)row[0], (float)row[1], (float)row[2], (float)row[3]));
    }
    return segments;
}

void writeSegments(const String& path, InputArray linesIn)
{
    const std::vector<Vec4f> lines = lsda::toSegments(linesIn, "lines");
    std::ofstream out(path.c_str());
    if (!out)
        CV_Error_(Error::StsError, ("cannot write %s", path.c_str()));
    for (const Vec4f& l : lines)
        out << format("%.3f %.3f %.3f %.3f\n", l[0], l[1], l[2], l[3]);
    if (!out)
        CV_Error_(Error::StsError, ("error while writing %s", path.c_str()));
}

std::vector<LabelledImage> loadYorkUrban(const String& folder)
{
    const String imageDir = utils::fs::join(folder, "images"), gtDir = utils::fs::join(folder, "gt");
    if (!utils::fs::isDirectory(imageDir) || !utils::fs::isDirectory(gtDir))
        CV_Error_(Error::StsError, ("%s is not a YorkUrban folder: expected images/ and gt/ in it", folder.c_str()));
    std::vector<String> names;
    const String list = utils::fs::join(folder, "list.txt");
    if (utils::fs::exists(list))
    {
        std::ifstream in(list.c_str());
        std::string name;
        while (in >> name)
            names.push_back(name);
    }
    else
    {
        std::vector<String> jpegs;  // the loader opens NAME.jpg: list only those
        glob(utils::fs::join(imageDir, "*.jpg"), jpegs, false);
        std::sort(jpegs.begin(), jpegs.end());
        for (const String& path : jpegs)
        {
            const size_t slash = path.find_last_of("/\\"), dot = path.find_last_of('.');
            names.push_back(path.substr(slash + 1, dot - slash - 1));
        }
    }
    std::vector<LabelledImage> images;
    for (const String& name : names)
    {
        LabelledImage item;
        item.imagePath = utils::fs::join(imageDir, name + ".jpg");
        if (!utils::fs::exists(item.imagePath))
            CV_Error_(Error::StsError, ("missing image %s", item.imagePath.c_str()));
        item.groundTruth = readSegments(utils::fs::join(gtDir, name + "_gt.txt"));
        images.push_back(item);
    }
    return images;
}

SequenceData loadSequence(const String& folder)
{
    SequenceData data;
    for (const char* sub : { "image_l", "image_0", "cam0/data", "" })
    {
        const String dir = *sub ? utils::fs::join(folder, sub) : folder;
        if (utils::fs::isDirectory(dir))
            data.imagePaths = imagesIn(dir);
        if (!data.imagePaths.empty())
        {
            data.rightImagePaths = rightImagesOf(folder, sub, data.imagePaths);
            break;
        }
    }
    if (data.imagePaths.empty())
        CV_Error_(Error::StsError, ("no image in %s (looked in image_l/, image_0/, cam0/data/ and the folder itself)",
                                    folder.c_str()));
    const String calib = utils::fs::join(folder, "calib.txt");
    if (utils::fs::exists(calib))
    {
        const std::vector<std::vector<double> > rows = readNumberRows(calib, true);
        if (rows.size() >= 1)
            data.P0 = matrix3x4(rows[0], calib);
        if (rows.size() >= 2)
            data.P1 = matrix3x4(rows[1], calib);
    }
    const String poses = utils::fs::join(folder, "poses.txt");
    if (utils::fs::exists(poses))
    {
        for (const std::vector<double>& row : readNumberRows(poses, false))
            data.poses.push_back(matrix3x4(row, poses));
        if (data.poses.size() != data.imagePaths.size())
            CV_Error_(Error::StsError, ("%s has %zu poses for %zu images", poses.c_str(), data.poses.size(),
                                        data.imagePaths.size()));
    }
    return data;
}

MultiViewData loadMultiView(const String& folder)
{
    const String imageDir = utils::fs::join(folder, "images"), cameraDir = utils::fs::join(folder, "gt_dense_cameras");
    if (!utils::fs::isDirectory(imageDir) || !utils::fs::isDirectory(cameraDir))
        CV_Error_(Error::StsError, ("%s is not a multi-view folder: expected images/ and gt_dense_cameras/ in it",
                                    folder.c_str()));
    std::vector<String> cameras;
    glob(utils::fs::join(cameraDir, "*.camera"), cameras, false);
    std::sort(cameras.begin(), cameras.end());
    if (cameras.empty())
        CV_Error_(Error::StsError, ("%s holds no NAME.camera file", cameraDir.c_str()));
    MultiViewData data;
    for (const String& camera : cameras)
    {
        const std::string file = camera.substr(camera.find_last_of("/\\") + 1);
        const String image = utils::fs::join(imageDir, file.substr(0, file.size() - 7));
        if (!utils::fs::exists(image))
            CV_Error_(Error::StsError, ("missing image %s (of the camera file %s)", image.c_str(), camera.c_str()));
        readCameraFile(camera, data);
        data.imagePaths.push_back(image);
    }
    return data;
}

Mat readHomography(const String& path)
{
    if (!utils::fs::exists(path))
        CV_Error_(Error::StsError, ("cannot open %s", path.c_str()));
    Mat H;
    const size_t dot = path.find_last_of('.');
    const std::string ext = dot == std::string::npos ? std::string() : toLowerCase(path.substr(dot + 1));
    if (ext == "xml" || ext == "yml" || ext == "yaml" || ext == "json")
    {
        FileStorage fs(path, FileStorage::READ);
        const FileNode root = fs.root();
        if (root.size() > 0)
            (*root.begin()) >> H;
    }
    else
    {
        std::vector<double> values;
        for (const std::vector<double>& row : readNumberRows(path, false))
            values.insert(values.end(), row.begin(), row.end());
        if (values.size() == 9)
            H = Mat(values, true).reshape(1, 3);
    }
    if (H.rows != 3 || H.cols != 3 || H.channels() != 1)
        CV_Error_(Error::StsParseError, ("%s: expected a 3x3 homography (9 numbers, or a 3x3 matrix as the first "
                                         "node of an OpenCV .xml/.yml/.json file)", path.c_str()));
    H.convertTo(H, CV_64F);
    if (!checkRange(H))
        CV_Error_(Error::StsParseError, ("%s: the homography is not finite", path.c_str()));
    return H;
}

std::vector<HomographyPair> loadHomographyPairs(const String& folder)
{
    const String reference = utils::fs::join(folder, "1.ppm");
    if (!utils::fs::exists(reference))
        CV_Error_(Error::StsError, ("%s is not an HPatches-style folder: 1.ppm is missing", folder.c_str()));
    std::vector<String> homographies;
    glob(utils::fs::join(folder, "H_1_*"), homographies, false);
    std::vector<std::pair<int, String> > indexed;
    for (const String& path : homographies)
    {
        const std::string name = path.substr(path.find_last_of("/\\") + 1);
        char* end = nullptr;
        const long k = std::strtol(name.c_str() + 4, &end, 10);
        if (*end == '\0' && k >= 2 && utils::fs::exists(utils::fs::join(folder, format("%ld.ppm", k))))
            indexed.push_back(std::make_pair((int)k, path));
    }
    std::sort(indexed.begin(), indexed.end());
    if (indexed.empty())
        CV_Error_(Error::StsError, ("%s: no pair k.ppm + H_1_k (k >= 2)", folder.c_str()));
    std::vector<HomographyPair> pairs;
    for (const auto& item : indexed)
    {
        HomographyPair pair;
        pair.image1Path = reference;
        pair.image2Path = utils::fs::join(folder, format("%d.ppm", item.first));
        pair.H = readHomography(item.second);
        pairs.push_back(pair);
    }
    return pairs;
}

}}} // namespace cv::ximgproc::line_evaluation
