// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The pose evaluation of the benchmark (doc/pose.md): what a SLAM system gets from a line
// detector's lines. Each method's lines (under a budget, ranked by its own response or by length)
// are described by LBD, matched between two views of known cameras and lifted to 3D, matched by
// LBD alone into another view, whose pose line_evaluation::estimatePose() then estimates; the
// error against the ground truth is scored per pair and over several RANSAC seeds.
//  - stereo (a KITTI-style sequence with image_r/): the map from the stereo pair of frame t, the
//    pose of frame t+1;
//  - multiview (a Strecha-style scene): the map from views i and i+1, the pose of view i+2.
// ORB points (features2d) give the references: points alone, and points with each method's lines.
// The estimated view's ground truth never enters the matching nor the estimation; it only scores.

#ifndef OPENCV_LSD_ADVANCE_APPS_POSE_BENCHMARK_HPP
#define OPENCV_LSD_ADVANCE_APPS_POSE_BENCHMARK_HPP

#include "line_matching.hpp"
#include "line_methods.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>
#include <opencv2/lsd_advance/pose_evaluation.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

//! How the pose evaluation runs.
struct PoseBenchmarkParams
{
    std::vector<int> budgets = { 60, 100, 150, 0 };  //!< lines per image (0: all of them)
    bool lengthControl = true;   //!< also rank LSDAdvance's lines by length (the others' own rank is length)
    int seeds = 3;               //!< RANSAC seeds per pair
    int orbFeatures = 500;       //!< ORB points per image of the point rows
    int pointLineBudget = 60;    //!< the line budget of the points + lines rows
    int maxHamming = 60;         //!< LBD matches: mutual nearest neighbours at most this far (of 256 bits)
    int orbMaxHamming = 50;      //!< ORB matches: the same, of 256 bits
    double epipolarTolerance = 2; //!< two-view matches of known cameras: px from the epipolar band (lines) or line (points)
    double minEpipolarAngle = 10; //!< degrees; lines closer to the epipolar direction are not lifted
    int pairs = 0;               //!< the first N pairs or triplets (0: all)
    int subset = -1;             //!< of those, only the pairs (triplets) of even (0) or odd (1) index; -1: all
    double rotationLimit = 0.5;  //!< degrees: the pose AUC's rotation error at which a pair scores 0
    double translationLimit = 0.1;  //!< the same for the translation error, as a share of the true step
    double successRotation = 0.25;  //!< degrees: a pair is a success below this rotation error ...
    double successTranslation = 0.05;  //!< ... and below this share of the step
    cv::ximgproc::line_evaluation::PoseEstimationParams estimation;

    bool takes(size_t pair) const { return subset < 0 || (int)(pair % 2) == subset; }
};

//! A budget as the tables print it.
inline std::string budgetName(int budget)
{
    return budget > 0 ? std::to_string(budget) : std::string("all");
}

// ------------------------------------------------------------------------------------------------
// Features of one image

//! One selection of a method's lines in an image: the rank and budget of a table row.
struct LineSelection
{
    bool byLength;
    int budget;
};

//! The lines of a method in an image for each selection, with their LBD descriptors, and the time of
//! the detection that gave them (ms).
struct SelectedLines
{
    std::vector<DescribedLines> lines;  //!< one per selection, in the order asked
    std::vector<double> detectMs;
};

//! A method's lines under each selection. LSDAdvance ranks its own (its response, by its budget,
//! Params::maxLines: what detect() returns); every other selection is the longest `budget` lines of
//! one detection of all of them, so that a budget is the prefix of a larger one. Each detection
//! starts a new sequence: a detector with a sequence state (PRESET_SEQUENCE) would otherwise see
//! each image once per selection, and the two cameras' images in turn.
inline SelectedLines selectLines(const LineMethod& method, const cv::Mat& gray, const std::vector<LineSelection>& selections)
{
    SelectedLines out;
    std::vector<cv::Vec4f> all;
    double allMs = -1;
    const int ownBudget = method.lsdAdvance ? method.lsdAdvance->getMaxLines() : 0;
    for (const LineSelection& s : selections)
    {
        std::vector<cv::Vec4f> lines;
        cv::TickMeter tm;
        if (method.lsdAdvance && !s.byLength)
        {
            method.lsdAdvance->setMaxLines(s.budget);
            method.reset();
            tm.start();
            method.detect(gray, lines);
            tm.stop();
            method.lsdAdvance->setMaxLines(ownBudget);
            out.detectMs.push_back(tm.getTimeMilli());
        }
        else
        {
            if (allMs < 0)
            {
                if (method.lsdAdvance)
                    method.lsdAdvance->setMaxLines(0);
                method.reset();
                tm.start();
                method.detect(gray, all);
                tm.stop();
                allMs = tm.getTimeMilli();
                if (method.lsdAdvance)
                    method.lsdAdvance->setMaxLines(ownBudget);
            }
            lines = bestLines(all, lengthResponses(all, gray.size()), s.budget);
            out.detectMs.push_back(allMs);
        }
        out.lines.push_back(describeLines(gray, lines));
    }
    return out;
}

//! ORB keypoints of an image and their descriptors.
struct DescribedPoints
{
    std::vector<cv::KeyPoint> keypoints;
    cv::Mat descriptors;
};

inline DescribedPoints describePoints(const cv::Mat& gray, int features)
{
    DescribedPoints out;
    cv::ORB::create(features)->detectAndCompute(gray, cv::noArray(), out.keypoints, out.descriptors);
    return out;
}

// ------------------------------------------------------------------------------------------------
// Matching

//! Mutual nearest neighbours of two sets of binary descriptors under the Hamming distance, at most
//! maxHamming apart, among the pairs (i, j) the gate accepts (all when it is empty): each row i of
//! descriptors1 with the row j of descriptors2 nearest to it, when i is also the nearest to j (ties:
//! the lower index). queryIdx into 1, trainIdx into 2.
inline std::vector<cv::DMatch> mutualMatches(const cv::Mat& descriptors1, const cv::Mat& descriptors2, int maxHamming,
                                             const std::function<bool(int, int)>& gate = std::function<bool(int, int)>())
{
    std::vector<cv::DMatch> matches;
    if (descriptors1.empty() || descriptors2.empty())
        return matches;
    const int n1 = descriptors1.rows, n2 = descriptors2.rows;
    std::vector<int> best1(n1, -1), best2(n2, -1), distance1(n1, INT_MAX), distance2(n2, INT_MAX);
    const int block = 256;  // rows of distances at once: memory bounded for thousands of lines
    for (int start = 0; start < n1; start += block)
    {
        const int end = std::min(n1, start + block);
        cv::Mat distances;
        cv::batchDistance(descriptors1.rowRange(start, end), descriptors2, distances, CV_32S, cv::noArray(),
                          cv::NORM_HAMMING);
        for (int i = start; i < end; i++)
        {
            const int* d = distances.ptr<int>(i - start);
            for (int j = 0; j < n2; j++)
            {
                if (d[j] > maxHamming || (d[j] >= distance1[i] && d[j] >= distance2[j]) || (gate && !gate(i, j)))
                    continue;
                if (d[j] < distance1[i])
                    distance1[i] = d[j], best1[i] = j;
                if (d[j] < distance2[j])
                    distance2[j] = d[j], best2[j] = i;
            }
        }
    }
    for (int i = 0; i < n1; i++)
        if (best1[i] >= 0 && best2[best1[i]] == i)
            matches.push_back(cv::DMatch(i, best1[i], (float)distance1[i]));
    return matches;
}

//! The gate of two views of known cameras for lines: the epipolar band of a overlaps b
//! (line_evaluation::checkEpipolar; undecidable pairs are refused).
inline std::function<bool(int, int)> epipolarLineGate(const std::vector<cv::Vec4f>& lines1,
                                                      const std::vector<cv::Vec4f>& lines2, const cv::Mat& F,
                                                      double tolerance)
{
    return [&lines1, &lines2, F, tolerance](int i, int j) {
        return cv::ximgproc::line_evaluation::checkEpipolar(lines1[i], lines2[j], F, tolerance) ==
               cv::ximgproc::line_evaluation::EPIPOLAR_CONSISTENT;
    };
}

//! The gate for points: the point of view 2 lies within tolerance px of the epipolar line of view 1's.
inline std::function<bool(int, int)> epipolarPointGate(const std::vector<cv::KeyPoint>& points1,
                                                       const std::vector<cv::KeyPoint>& points2, const cv::Mat& F,
                                                       double tolerance)
{
    const cv::Matx33d F33(F);
    return [&points1, &points2, F33, tolerance](int i, int j) {
        const cv::Vec3d l = F33 * cv::Vec3d(points1[i].pt.x, points1[i].pt.y, 1);
        const double distance = std::abs(l[0] * points2[j].pt.x + l[1] * points2[j].pt.y + l[2]);
        return distance <= tolerance * std::hypot(l[0], l[1]);
    };
}

// ------------------------------------------------------------------------------------------------
// Geometry

//! A relative pose: X_b = R X_a + t.
struct RelativePose
{
    cv::Matx33d R;
    cv::Vec3d t;
};

//! The pose of camera b relative to camera a, from their camera-to-world poses [R | C]
//! (line_evaluation::SequenceData::poses, MultiViewData::poses).
inline RelativePose relativePose(const cv::Mat& poseA, const cv::Mat& poseB)
{
    const cv::Matx34d a(poseA), b(poseB);
    const cv::Matx33d Ra = a.get_minor<3, 3>(0, 0), Rb = b.get_minor<3, 3>(0, 0);
    const cv::Vec3d Ca(a(0, 3), a(1, 3), a(2, 3)), Cb(b(0, 3), b(1, 3), b(2, 3));
    return RelativePose{ Rb.t() * Ra, Rb.t() * (Ca - Cb) };
}

//! Throws when the true pose of an estimated view has no translation: its translation error, as a
//! share of the step, would be undefined.
inline void requireStep(const RelativePose& truth, const std::string& views)
{
    if (!(cv::norm(truth.t) > 0))
        throw std::runtime_error(views + ": no translation between them, so the translation error, a share of the "
                                 "step, is undefined");
}

//! K [R | t].
inline cv::Mat projectionOf(const cv::Matx33d& K, const RelativePose& pose)
{
    cv::Matx34d Rt;
    for (int r = 0; r < 3; r++)
    {
        for (int c = 0; c < 3; c++)
            Rt(r, c) = pose.R(r, c);
        Rt(r, 3) = pose.t[r];
    }
    return cv::Mat(K * Rt);
}

//! The 3D segments of matched lines of two views (line_evaluation::triangulateSegments), and for
//! each the index of its line in view 1.
struct LineMap
{
    cv::Mat segments3d;
    std::vector<int> lineOf;
};

inline LineMap liftLines(const cv::Mat& P1, const cv::Mat& P2, const DescribedLines& view1, const DescribedLines& view2,
                         const PoseBenchmarkParams& params)
{
    using namespace cv::ximgproc::line_evaluation;
    const cv::Mat F = fundamentalFromProjections(P1, P2);
    const std::vector<cv::DMatch> matches =
        mutualMatches(view1.descriptors, view2.descriptors, params.maxHamming,
                      epipolarLineGate(view1.lines, view2.lines, F, params.epipolarTolerance));
    LineMap map;
    std::vector<int> kept;
    triangulateSegments(P1, P2, view1.lines, view2.lines, matches, map.segments3d, kept, params.minEpipolarAngle);
    for (int k : kept)
        map.lineOf.push_back(matches[k].queryIdx);
    return map;
}

//! The 3D points of matched ORB points of two views, in front of both cameras, and for each the
//! index of its keypoint in view 1.
struct PointMap
{
    std::vector<cv::Point3f> points3d;
    std::vector<int> pointOf;
};

inline PointMap liftPoints(const cv::Mat& P1, const cv::Mat& P2, const DescribedPoints& view1,
                           const DescribedPoints& view2, const PoseBenchmarkParams& params)
{
    const cv::Mat F = cv::ximgproc::line_evaluation::fundamentalFromProjections(P1, P2);
    const std::vector<cv::DMatch> matches =
        mutualMatches(view1.descriptors, view2.descriptors, params.orbMaxHamming,
                      epipolarPointGate(view1.keypoints, view2.keypoints, F, params.epipolarTolerance));
    PointMap map;
    if (matches.empty())
        return map;
    std::vector<cv::Point2f> x1, x2;
    for (const cv::DMatch& m : matches)
    {
        x1.push_back(view1.keypoints[m.queryIdx].pt);
        x2.push_back(view2.keypoints[m.trainIdx].pt);
    }
    cv::Mat X;
    cv::triangulatePoints(P1, P2, x1, x2, X);
    X.convertTo(X, CV_64F);
    for (size_t k = 0; k < matches.size(); k++)
    {
        const cv::Vec4d h(X.at<double>(0, (int)k), X.at<double>(1, (int)k), X.at<double>(2, (int)k), X.at<double>(3, (int)k));
        if (!(std::abs(h[3]) > 0))
            continue;
        const cv::Vec4d p = h * (1.0 / h[3]);
        const cv::Vec3d d1 = cv::Matx34d(P1) * p, d2 = cv::Matx34d(P2) * p;
        if (d1[2] > 0 && d2[2] > 0)
        {
            map.points3d.push_back(cv::Point3f((float)p[0], (float)p[1], (float)p[2]));
            map.pointOf.push_back(matches[k].queryIdx);
        }
    }
    return map;
}

// ------------------------------------------------------------------------------------------------
// One estimation and the scores of many

//! The outcome of one pose estimation: its errors (infinite when not solved) and what it used.
struct PoseTrial
{
    bool solved = false;
    double rotationError = std::numeric_limits<double>::infinity();     //!< degrees
    double translationError = std::numeric_limits<double>::infinity();  //!< share of the true step
    int lineCorrespondences = 0, pointCorrespondences = 0, inliers = 0;
};

//! The 2D-3D correspondences of a map with a view: the map's lines (or points) matched by their
//! descriptors in the map's view 1 to the view's.
struct Correspondences
{
    cv::Mat segments3d;
    std::vector<cv::Vec4f> segments2d;
    std::vector<cv::Point3f> points3d;
    std::vector<cv::Point2f> points2d;
};

//! The matches of the map's features (their descriptors: the rows `features` of mapDescriptors) to
//! a view's: query the index into `features`, train the view's feature.
inline std::vector<cv::DMatch> mapMatches(const cv::Mat& mapDescriptors, const std::vector<int>& features,
                                          const cv::Mat& viewDescriptors, int maxHamming)
{
    cv::Mat descriptors;
    for (int i : features)
        descriptors.push_back(mapDescriptors.row(i));
    return mutualMatches(descriptors, viewDescriptors, maxHamming);
}

inline void addLineCorrespondences(const LineMap& map, const DescribedLines& mapView, const DescribedLines& view,
                                   int maxHamming, Correspondences& out)
{
    for (const cv::DMatch& m : mapMatches(mapView.descriptors, map.lineOf, view.descriptors, maxHamming))
    {
        out.segments3d.push_back(map.segments3d.row(m.queryIdx));
        out.segments2d.push_back(view.lines[m.trainIdx]);
    }
}

inline void addPointCorrespondences(const PointMap& map, const DescribedPoints& mapView, const DescribedPoints& view,
                                    int maxHamming, Correspondences& out)
{
    for (const cv::DMatch& m : mapMatches(mapView.descriptors, map.pointOf, view.descriptors, maxHamming))
    {
        out.points3d.push_back(map.points3d[m.queryIdx]);
        out.points2d.push_back(view.keypoints[m.trainIdx].pt);
    }
}

//! How many line correspondences the true pose makes inliers: both projected 3D endpoints within
//! `threshold` px of the 2D line (the estimator's test), scoring only, never estimating.
inline int trueLineInliers(const cv::Matx33d& K, const Correspondences& c, const RelativePose& truth, double threshold)
{
    if (c.segments2d.empty())
        return 0;
    cv::Mat endpoints;
    c.segments3d.reshape(1, c.segments3d.rows).convertTo(endpoints, CV_64F);
    cv::Vec3d rotation;
    cv::Rodrigues(truth.R, rotation);
    std::vector<cv::Point2d> projected;
    cv::projectPoints(endpoints.reshape(3, 2 * endpoints.rows), rotation, truth.t, K, cv::noArray(), projected);
    int inliers = 0;
    for (size_t i = 0; i < c.segments2d.size(); i++)
    {
        const cv::Vec4f& s = c.segments2d[i];
        const cv::Vec3d line = cv::Vec3d(s[0], s[1], 1).cross(cv::Vec3d(s[2], s[3], 1));
        const double norm = std::hypot(line[0], line[1]);
        bool inlier = true;
        for (const cv::Point2d& x : { projected[2 * i], projected[2 * i + 1] })
            inlier = inlier && std::abs(line[0] * x.x + line[1] * x.y + line[2]) <= threshold * norm;
        inliers += inlier;
    }
    return inliers;
}

//! The pose of the view from the correspondences, for each seed, against the true relative pose.
inline std::vector<PoseTrial> estimateTrials(const cv::Matx33d& K, const Correspondences& c, const RelativePose& truth,
                                             const PoseBenchmarkParams& params)
{
    using namespace cv::ximgproc::line_evaluation;
    std::vector<PoseTrial> trials;
    const double step = cv::norm(truth.t);
    CV_Assert(step > 0);  // requireStep
    for (int seed = 0; seed < params.seeds; seed++)
    {
        PoseEstimationParams estimation = params.estimation;
        estimation.seed = seed;
        const PoseEstimate e = estimatePose(K, c.segments3d, c.segments2d, c.points3d, c.points2d, estimation);
        PoseTrial trial;
        trial.lineCorrespondences = (int)c.segments2d.size();
        trial.pointCorrespondences = (int)c.points2d.size();
        trial.solved = e.solved;
        trial.inliers = e.lineInliers + e.pointInliers;
        if (e.solved)
        {
            double translation = 0;
            poseError(e.R, e.t, cv::Mat(truth.R), cv::Mat(truth.t), trial.rotationError, translation);
            trial.translationError = translation / step;
        }
        trials.push_back(trial);
    }
    return trials;
}

//! A pair's score in the pose AUC: 1 for an exact pose, falling linearly to 0 at either limit; 0
//! when not solved.
inline double poseScore(const PoseTrial& t, const PoseBenchmarkParams& params)
{
    if (!t.solved)
        return 0.0;
    return 1.0 - std::min(1.0, std::max(t.rotationError / params.rotationLimit, t.translationError / params.translationLimit));
}

//! The median of the values of the resampled pairs, the 2.5 % and 97.5 % quantiles of 1000 bootstrap
//! resamples of the pairs (each pair with all its seeds), fixed seed.
inline cv::Vec3d medianWithInterval(const std::vector<std::vector<double> >& perPair)
{
    const auto medianOf = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                         : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
    };
    std::vector<double> all;
    for (const auto& p : perPair)
        all.insert(all.end(), p.begin(), p.end());
    cv::RNG rng(12345);
    std::vector<double> medians;
    for (int b = 0; b < 1000 && !perPair.empty(); b++)
    {
        std::vector<double> resample;
        for (size_t k = 0; k < perPair.size(); k++)
        {
            const std::vector<double>& p = perPair[rng.uniform(0, (int)perPair.size())];
            resample.insert(resample.end(), p.begin(), p.end());
        }
        medians.push_back(medianOf(resample));
    }
    std::sort(medians.begin(), medians.end());
    if (medians.empty())
        return cv::Vec3d::all(std::numeric_limits<double>::quiet_NaN());
    return cv::Vec3d(medianOf(all), medians[medians.size() * 25 / 1000], medians[medians.size() * 975 / 1000]);
}

//! Two-sided sign test: the probability of a split at least as uneven as wins : losses under a fair coin.
inline double signTestP(int wins, int losses)
{
    const int n = wins + losses, k = std::min(wins, losses);
    if (n == 0)
        return 1.0;
    double tail = 0;
    for (int i = 0; i <= k; i++)
        tail += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) - n * std::log(2.0));
    return std::min(1.0, 2 * tail);
}

// ------------------------------------------------------------------------------------------------
// The runs

//! What a table row estimated with: lines only, ORB points only, or both.
enum class PoseFeatures
{
    Lines,
    Points,
    PointsAndLines
};

//! The trials of one table row, per pair and seed, and what its lines were.
struct PoseRow
{
    PoseRow(const std::string& title, PoseFeatures used, LineSelection lines)
        : method(title), features(used), selection(lines)
    {}
    std::string method;         //!< the method's title ("ORB" for the points alone)
    PoseFeatures features;
    LineSelection selection;
    std::vector<std::vector<PoseTrial> > pairs;
    std::vector<double> linesPerImage, liftedPerPair, detectMs;
    //! over the pairs: the line correspondences, those the true pose makes inliers, and the
    //! lengths of their 2D lines in pixels
    int lineMatches = 0, trueLineInliers = 0;
    std::vector<double> matchedLineLengths;
};

//! One image of a pose run: its gray pixels and its camera matrix (scaled with the image).
struct PoseView
{
    cv::Mat gray;
    cv::Matx33d K;
};

//! Reads an image as gray, resized by scale (cv::INTER_AREA) with its camera matrix (pixel centres
//! at integers: x' = scale (x + 0.5) - 0.5); an error when it is not the size its camera was calibrated
//! for (when given).
inline PoseView readPoseView(const std::string& path, const cv::Matx33d& K, double scale,
                             const cv::Size& calibrated = cv::Size())
{
    PoseView view;
    const cv::Mat gray = cv::imread(path, cv::IMREAD_GRAYSCALE);
    if (gray.empty())
        throw std::runtime_error("cannot read " + path + " as an image");
    if (!calibrated.empty() && gray.size() != calibrated)
        throw std::runtime_error(cv::format("%s is %dx%d, its camera was calibrated for %dx%d", path.c_str(), gray.cols,
                                            gray.rows, calibrated.width, calibrated.height));
    view.K = K;
    if (scale == 1)
        view.gray = gray;
    else
    {
        cv::resize(gray, view.gray, cv::Size(), scale, scale, cv::INTER_AREA);
        view.K(0, 0) *= scale;
        view.K(1, 1) *= scale;
        view.K(0, 1) *= scale;
        view.K(0, 2) = scale * (K(0, 2) + 0.5) - 0.5;
        view.K(1, 2) = scale * (K(1, 2) + 0.5) - 0.5;
    }
    return view;
}

//! The features of every method in one image, and the ORB points.
struct ViewFeatures
{
    std::vector<SelectedLines> methods;
    DescribedPoints points;
};

//! Builds the pose rows and runs the estimations of one map-and-query step at a time.
class PoseRun
{
public:
    PoseRun(const std::vector<LineMethod>& methods, const PoseBenchmarkParams& params)
        : methods_(methods), params_(params)
    {
        for (size_t m = 0; m < methods.size(); m++)
        {
            std::vector<LineSelection> selections;
            for (bool byLength : { false, true })
                for (int budget : params.budgets)
                    if (!byLength || (params.lengthControl && methods[m].lsdAdvance))
                        selections.push_back(LineSelection{ byLength, budget });
            if (std::find(params.budgets.begin(), params.budgets.end(), params.pointLineBudget) == params.budgets.end())
                selections.push_back(LineSelection{ false, params.pointLineBudget });
            selections_.push_back(selections);
        }
        rows_.push_back(PoseRow("ORB", PoseFeatures::Points, LineSelection{ false, 0 }));
        for (size_t m = 0; m < methods.size(); m++)
            for (size_t s = 0; s < selections_[m].size(); s++)
            {
                const LineSelection& sel = selections_[m][s];
                if (std::find(params.budgets.begin(), params.budgets.end(), sel.budget) != params.budgets.end())
                    rows_.push_back(PoseRow(methods[m].name, PoseFeatures::Lines, sel));
                if (!sel.byLength && sel.budget == params.pointLineBudget)
                    rows_.push_back(PoseRow(methods[m].name, PoseFeatures::PointsAndLines, sel));
            }
    }

    //! Every method's lines and the ORB points of an image; with timed, the detection times count.
    ViewFeatures describe(const cv::Mat& gray, bool timed)
    {
        ViewFeatures f;
        for (size_t m = 0; m < methods_.size(); m++)
            f.methods.push_back(selectLines(methods_[m], gray, selections_[m]));
        f.points = describePoints(gray, params_.orbFeatures);
        for (PoseRow& row : rows_)
        {
            const int m = methodIndex(row), s = selectionIndex(row);
            if (m < 0)
                continue;
            row.linesPerImage.push_back((double)f.methods[m].lines[s].lines.size());
            if (timed && row.features == PoseFeatures::Lines)
                row.detectMs.push_back(f.methods[m].detectMs[s]);
        }
        return f;
    }

    //! One pair: the map from views 1 and 2 of known projections (in the reference's coordinates,
    //! that of view 1), the pose of the query view against the truth (reference to query).
    void estimate(const cv::Mat& P1, const ViewFeatures& view1, const cv::Mat& P2, const ViewFeatures& view2,
                  const cv::Matx33d& queryK, const ViewFeatures& query, const RelativePose& truth)
    {
        Correspondences points;
        addPointCorrespondences(liftPoints(P1, P2, view1.points, view2.points, params_), view1.points, query.points,
                                params_.orbMaxHamming, points);
        std::vector<std::vector<Correspondences> > lines(methods_.size());
        std::vector<std::vector<double> > lifted(methods_.size());
        for (size_t m = 0; m < methods_.size(); m++)
            for (size_t s = 0; s < selections_[m].size(); s++)
            {
                const LineMap map = liftLines(P1, P2, view1.methods[m].lines[s], view2.methods[m].lines[s], params_);
                Correspondences c;
                addLineCorrespondences(map, view1.methods[m].lines[s], query.methods[m].lines[s], params_.maxHamming, c);
                lines[m].push_back(c);
                lifted[m].push_back((double)map.lineOf.size());
            }
        for (PoseRow& row : rows_)
        {
            const int m = methodIndex(row), s = selectionIndex(row);
            Correspondences c = m < 0 ? points : lines[m][s];
            if (row.features == PoseFeatures::PointsAndLines)
            {
                c.points3d = points.points3d;
                c.points2d = points.points2d;
            }
            if (m >= 0)
            {
                row.liftedPerPair.push_back(lifted[m][s]);
                row.lineMatches += (int)c.segments2d.size();
                row.trueLineInliers += trueLineInliers(queryK, c, truth, params_.estimation.lineThreshold);
                for (const cv::Vec4f& line : c.segments2d)
                    row.matchedLineLengths.push_back(std::hypot(line[2] - line[0], line[3] - line[1]));
            }
            row.pairs.push_back(estimateTrials(queryK, c, truth, params_));
        }
    }

    const std::vector<PoseRow>& rows() const { return rows_; }

private:
    int methodIndex(const PoseRow& row) const
    {
        if (row.features == PoseFeatures::Points)
            return -1;
        for (size_t m = 0; m < methods_.size(); m++)
            if (methods_[m].name == row.method)
                return (int)m;
        CV_Error(cv::Error::StsInternal, "a pose row of an unknown method");
    }
    int selectionIndex(const PoseRow& row) const
    {
        const int m = methodIndex(row);
        if (m < 0)
            return -1;
        for (size_t s = 0; s < selections_[m].size(); s++)
            if (selections_[m][s].byLength == row.selection.byLength && selections_[m][s].budget == row.selection.budget)
                return (int)s;
        CV_Error(cv::Error::StsInternal, "a pose row of an unknown selection");
    }

    const std::vector<LineMethod>& methods_;
    const PoseBenchmarkParams params_;
    std::vector<std::vector<LineSelection> > selections_;
    std::vector<PoseRow> rows_;
};

//! Stereo: for each pair of consecutive frames t, t+1 of a rectified stereo sequence (P0 the left
//! camera K [I | 0], P1 the right one), the map from the stereo pair of frame t, the pose of the left
//! camera of t+1. Every method's lines and the points are described once per image.
inline std::vector<PoseRow> runStereoPose(const std::vector<LineMethod>& methods,
                                          const cv::ximgproc::line_evaluation::SequenceData& sequence,
                                          const PoseBenchmarkParams& params)
{
    if (sequence.rightImagePaths.empty() || sequence.P0.empty() || sequence.P1.empty() || sequence.poses.empty())
        throw std::runtime_error("--dataset=stereo needs image_l/ with image_r/, calib.txt (P0 and P1) and poses.txt");
    const cv::Matx34d P0(sequence.P0);
    if (P0(0, 3) != 0 || P0(1, 3) != 0 || P0(2, 3) != 0)
        throw std::runtime_error("--dataset=stereo: calib.txt's P0 must be K [I | 0] (the left camera at the origin)");
    const cv::Matx33d K = P0.get_minor<3, 3>(0, 0);
    PoseRun run(methods, params);
    const size_t frames = params.pairs > 0 ? std::min(sequence.imagePaths.size(), (size_t)params.pairs + 1)
                                           : sequence.imagePaths.size();
    for (size_t t = 1; t < frames; t++)
        requireStep(relativePose(sequence.poses[t - 1], sequence.poses[t]), cv::format("frames %zu and %zu", t - 1, t));
    ViewFeatures previousLeft, previousRight;
    for (size_t t = 0; t < frames; t++)
    {
        std::cerr << "\r[stereo] frame " << t + 1 << "/" << frames << std::flush;
        const ViewFeatures left = run.describe(readPoseView(sequence.imagePaths[t], K, 1).gray, true);
        const ViewFeatures right = run.describe(readPoseView(sequence.rightImagePaths[t], K, 1).gray, false);
        if (t > 0 && params.takes(t - 1))
            run.estimate(sequence.P0, previousLeft, sequence.P1, previousRight, K, left,
                         relativePose(sequence.poses[t - 1], sequence.poses[t]));
        previousLeft = left;
        previousRight = right;
    }
    std::cerr << "\n";
    return run.rows();
}

//! Multi-view: for each triplet of consecutive views in either order, a, m, q = i, i+1, i+2 and
//! i+2, i+1, i, the map from views m and a (in the coordinates of view m), the pose of view q
//! relative to view m. Images and cameras at `scale`.
inline std::vector<PoseRow> runMultiViewPose(const std::vector<LineMethod>& methods,
                                             const cv::ximgproc::line_evaluation::MultiViewData& scene, double scale,
                                             const PoseBenchmarkParams& params)
{
    if (scene.imagePaths.size() < 3)
        throw std::runtime_error("--dataset=multiview needs at least 3 views");
    PoseRun run(methods, params);
    const size_t views = params.pairs > 0 ? std::min(scene.imagePaths.size(), ((size_t)params.pairs + 1) / 2 + 2)
                                          : scene.imagePaths.size();
    std::vector<ViewFeatures> features;
    std::vector<cv::Matx33d> K;
    for (size_t v = 0; v < views; v++)
    {
        std::cerr << "\r[multiview] view " << v + 1 << "/" << views << std::flush;
        const PoseView view =
            readPoseView(scene.imagePaths[v], cv::Matx33d(scene.cameraMatrices[v]), scale, scene.imageSizes[v]);
        features.push_back(run.describe(view.gray, true));
        K.push_back(view.K);
    }
    std::cerr << "\n";
    const RelativePose identity{ cv::Matx33d::eye(), cv::Vec3d() };
    for (size_t i = 0; i + 2 < views; i++)
        for (bool reversed : { false, true })
        {
            const size_t a = reversed ? i + 2 : i, m = i + 1, q = reversed ? i : i + 2;
            if (params.pairs > 0 && 2 * i + reversed >= (size_t)params.pairs)
                break;
            if (!params.takes(i))
                continue;
            const RelativePose truth = relativePose(scene.poses[m], scene.poses[q]);
            requireStep(truth, cv::format("views %zu and %zu", m, q));
            run.estimate(projectionOf(K[m], identity), features[m],
                         projectionOf(K[a], relativePose(scene.poses[m], scene.poses[a])), features[a], K[q],
                         features[q], truth);
        }
    return run.rows();
}

#endif
