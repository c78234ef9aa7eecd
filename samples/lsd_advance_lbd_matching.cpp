// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Matches line segments between two images, or between consecutive frames of a folder or a
// video, with OpenCV's LBD descriptor (line_descriptor): detects with a chosen method, converts
// to KeyLines, describes, matches (mutual nearest neighbours under a Hamming bound), prints the
// number of matches and, given ground truth, how many are correct:
//  --homography=<file>: the two images are related by this homography (3x3 text or OpenCV XML);
//  a KITTI-style folder (image_l/ or image_0/, calib.txt, poses.txt): epipolar consistency.
// The criteria are those of doc/matching.md.

#include <opencv2/core.hpp>

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

#include "command_line.hpp"
#include "frame_source.hpp"
#include "line_matching.hpp"
#include "line_methods.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

using namespace cv;

namespace {

// What the ground truth says of a match, which gives its colour in the drawing.
struct MatchClass
{
    std::string name;
    Scalar colour;
    std::vector<char> members;  //!< per match: 1 when the match is of this class
};

// The matches drawn side by side, each class in its colour with its count in the top-left
// corner; without classes, each match in its own random colour (drawLineMatches' choice).
void drawMatches(const Mat& gray1, const DescribedLines& lines1, const Mat& gray2, const DescribedLines& lines2,
                 const std::vector<DMatch>& matches, const std::vector<MatchClass>& classes, const String& path)
{
    Mat colour1, colour2;
    cvtColor(gray1, colour1, COLOR_GRAY2BGR);
    cvtColor(gray2, colour2, COLOR_GRAY2BGR);
    // Matched lines only; with NOT_DRAW_SINGLE_LINES, drawLineMatches draws into a canvas of the
    // right size that the caller allocates, after copying the two images into it: each class
    // is drawn on the halves of the previous drawing.
    Mat canvas(std::max(gray1.rows, gray2.rows), gray1.cols + gray2.cols, CV_8UC3, Scalar::all(0));
    const Rect left(0, 0, gray1.cols, gray1.rows), right(gray1.cols, 0, gray2.cols, gray2.rows);
    std::vector<MatchClass> passes = classes;
    if (passes.empty())
        passes.push_back({ std::string(), Scalar::all(-1), std::vector<char>(matches.size(), 1) });
    for (size_t i = 0; i < passes.size(); i++)
    {
        if (i > 0)
        {
            canvas(left).copyTo(colour1);
            canvas(right).copyTo(colour2);
        }
        // The matched segments in the colour of their match (-1: random, one colour per match).
        line_descriptor::drawLineMatches(colour1, lines1.keylines, colour2, lines2.keylines, matches, canvas,
                                         passes[i].colour, passes[i].colour, passes[i].members,
                                         line_descriptor::DrawLinesMatchesFlags::NOT_DRAW_SINGLE_LINES);
    }
    // The counts, one line per class, on a dark box in the top-left corner.
    const double scale = std::max(0.5, canvas.cols / 1600.0);
    const int weight = scale > 0.8 ? 2 : 1, margin = 8;
    int baseline = 0, width = 0;
    const int rowHeight = getTextSize("Ag", FONT_HERSHEY_SIMPLEX, scale, weight, &baseline).height + baseline + 6;
    std::vector<std::string> rows;
    for (const MatchClass& c : classes)
    {
        rows.push_back(format("%s: %d", c.name.c_str(), (int)std::count(c.members.begin(), c.members.end(), 1)));
        width = std::max(width, getTextSize(rows.back(), FONT_HERSHEY_SIMPLEX, scale, weight, &baseline).width);
    }
    if (!rows.empty())
        rectangle(canvas, Rect(0, 0, width + 2 * margin, (int)rows.size() * rowHeight + margin), Scalar::all(0), FILLED);
    for (size_t i = 0; i < rows.size(); i++)
        putText(canvas, rows[i], Point(margin, (int)(i + 1) * rowHeight), FONT_HERSHEY_SIMPLEX, scale, classes[i].colour,
                weight, LINE_AA);
    if (!imwrite(path, canvas, { IMWRITE_JPEG_QUALITY, 85 }))
        throw std::runtime_error("cannot write " + path);
    std::printf("wrote %s\n", path.c_str());
}

const Scalar kRight(60, 200, 60), kWrong(60, 60, 255), kUndecided(0, 210, 255);

// Correct (green) and wrong (red) matches under the homography H, as evaluateHomographyMatches counts them.
std::vector<MatchClass> classesUnderHomography(const std::vector<Vec4f>& segments1, const std::vector<Vec4f>& segments2,
                                               const std::vector<DMatch>& matches, const Mat& H)
{
    std::vector<MatchClass> classes = { { "correct", kRight, {} }, { "wrong", kWrong, {} } };
    for (const DMatch& m : matches)
    {
        const bool correct = ximgproc::line_evaluation::correspondUnderHomography(segments1[m.queryIdx], segments2[m.trainIdx], H);
        classes[0].members.push_back(correct);
        classes[1].members.push_back(!correct);
    }
    return classes;
}

// Consistent (green), inconsistent (red) and undecidable (yellow) matches under the fundamental
// matrix F, as evaluateEpipolarMatches counts them.
std::vector<MatchClass> classesUnderEpipolar(const std::vector<Vec4f>& segments1, const std::vector<Vec4f>& segments2,
                                             const std::vector<DMatch>& matches, const Mat& F)
{
    std::vector<MatchClass> classes = { { "consistent", kRight, {} }, { "inconsistent", kWrong, {} },
                                        { "undecidable", kUndecided, {} } };
    for (const DMatch& m : matches)
    {
        const int verdict = ximgproc::line_evaluation::checkEpipolar(segments1[m.queryIdx], segments2[m.trainIdx], F);
        classes[0].members.push_back(verdict == ximgproc::line_evaluation::EPIPOLAR_CONSISTENT);
        classes[1].members.push_back(verdict == ximgproc::line_evaluation::EPIPOLAR_INCONSISTENT);
        classes[2].members.push_back(verdict == ximgproc::line_evaluation::EPIPOLAR_UNDECIDABLE);
    }
    return classes;
}

// A drawing can be written to path: its folder exists and OpenCV has an encoder for its extension.
void checkDrawPath(const String& path)
{
    checkOutputFolder("draw", path);
    if (!path.empty() && !haveImageWriter(path))
        throw std::runtime_error("--draw=" + path + ": no image format for this file name (use .jpg or .png)");
}

int matchPair(const LineMethod& method, const String& path1, const String& path2, const String& homographyPath,
              const LineMatchParams& params, const String& drawPath)
{
    const Mat H = homographyPath.empty() ? Mat() : ximgproc::line_evaluation::readHomography(samples::findFile(homographyPath, true, true));
    const Mat gray1 = imread(samples::findFile(path1, true, true), IMREAD_GRAYSCALE);
    const Mat gray2 = imread(samples::findFile(path2, true, true), IMREAD_GRAYSCALE);
    if (gray1.empty() || gray2.empty())
        throw std::runtime_error("cannot read " + (gray1.empty() ? path1 : path2) + " as an image");
    std::vector<Vec4f> segments1, segments2;
    // Two unrelated detections: neither may steer the other's inter-frame factor.
    method.reset();
    method.detect(gray1, segments1);
    method.reset();
    method.detect(gray2, segments2);
    const DescribedLines lines1 = describeLines(gray1, segments1), lines2 = describeLines(gray2, segments2);
    const std::vector<DMatch> matches = matchLines(lines1, lines2, params);

    std::printf("method:          %s\n", method.name.c_str());
    std::printf("segments:        %zu / %zu\n", segments1.size(), segments2.size());
    std::printf("matches:         %zu\n", matches.size());
    if (!H.empty())
    {
        const ximgproc::line_evaluation::HomographyMatchScore s =
            ximgproc::line_evaluation::evaluateHomographyMatches(segments1, segments2, matches, H, gray1.size(), gray2.size());
        std::printf("correct:         %d (precision %.3f; mapped within 3 px, overlapping)\n", s.correct, s.precision);
        std::printf("repeatability:   %.3f (%d of %d visible segments)\n", s.repeatability, s.repeated, s.visible);
        std::printf("localisation:    %.2f px (mean, repeated segments)\n", s.localisationError);
    }
    if (!drawPath.empty())
        drawMatches(gray1, lines1, gray2, lines2, matches,
                    H.empty() ? std::vector<MatchClass>() : classesUnderHomography(segments1, segments2, matches, H),
                    drawPath);
    return 0;
}

int matchSequence(const LineMethod& method, const String& input, const LineMatchParams& params,
                  const String& drawPath)
{
    const String path = samples::findFileOrKeep(input, true);
    ximgproc::line_evaluation::SequenceData calibration;
    if (utils::fs::isDirectory(path))
        calibration = ximgproc::line_evaluation::loadSequence(path);
    const bool withPoses = !calibration.P0.empty() && !calibration.poses.empty();

    FrameSource source(input);
    Mat previousGray, gray;
    DescribedLines previous;
    std::string stem;
    int pairs = 0;
    ximgproc::line_evaluation::EpipolarMatchScore total;
    size_t totalMatches = 0;
    method.reset();
    // frame: the number of the image in the folder or video (skipped files count), for its pose.
    for (int previousFrame = -1, frame = 0; source.next(gray, stem); previousFrame = frame)
    {
        frame = (int)source.index();
        std::vector<Vec4f> segments;
        method.detect(gray, segments);
        DescribedLines current = describeLines(gray, segments);
        if (previousFrame >= 0)
        {
            const std::vector<DMatch> matches = matchLines(previous, current, params);
            totalMatches += matches.size();
            std::printf("frames %d-%d: segments %zu / %zu, matches %zu", previousFrame, frame, previous.lines.size(),
                        current.lines.size(), matches.size());
            Mat F;
            if (withPoses)
            {
                F = ximgproc::line_evaluation::fundamentalFromPoses(calibration.P0, calibration.poses[previousFrame],
                                                   calibration.poses[frame]);
                const ximgproc::line_evaluation::EpipolarMatchScore s =
                    ximgproc::line_evaluation::evaluateEpipolarMatches(previous.lines, current.lines, matches, F);
                std::printf(", consistent %d, inconsistent %d, undecidable %d", s.consistent, s.inconsistent,
                            s.undecidable);
                total.consistent += s.consistent;
                total.inconsistent += s.inconsistent;
                total.undecidable += s.undecidable;
            }
            std::printf("\n");
            if (pairs == 0 && !drawPath.empty())
                drawMatches(previousGray, previous, gray, current, matches,
                            F.empty() ? std::vector<MatchClass>()
                                      : classesUnderEpipolar(previous.lines, current.lines, matches, F),
                            drawPath);
            pairs++;
        }
        previous = current;
        gray.copyTo(previousGray);
    }
    if (pairs == 0)
        throw std::runtime_error("a sequence needs at least two frames: " + input);
    std::printf("method:            %s\n", method.name.c_str());
    std::printf("frame pairs:       %d\n", pairs);
    std::printf("matches / pair:    %.1f\n", (double)totalMatches / pairs);
    if (withPoses)
    {
        const int decided = total.consistent + total.inconsistent;
        std::printf("consistent / pair: %.1f (share of decidable matches %.3f; %.1f undecidable / pair)\n",
                    (double)total.consistent / pairs, decided > 0 ? (double)total.consistent / decided : 0.0,
                    (double)total.undecidable / pairs);
    }
    if (!source.skipped().empty())
    {
        std::printf("skipped:           %zu unreadable file(s)\n", source.skipped().size());
        return kExitSkipped;
    }
    return 0;
}

int run(const CommandLine& args)
{
    const String image1 = args.text("@image1"), image2 = args.text("@image2");
    const String sequence = args.text("sequence");
    const String homography = args.text("homography"), drawPath = args.text("draw");
    LineMatchParams params;
    params.maxHamming = args.integer("max-hamming", 0, 256);
    params.crossCheck = !args.has("no-cross-check");
    checkDrawPath(drawPath);
    const FileStorage paramsFile = openParamsFile(args.text("params"));
    const LineMethod method = makeLineMethod(args.text("method"), paramsFile.isOpened() ? paramsFile.root() : FileNode());
    if (!sequence.empty())
    {
        if (!homography.empty())
            throw std::runtime_error("--homography applies to two images, not to --sequence");
        return matchSequence(method, sequence, params, drawPath);
    }
    return matchPair(method, image1, image2, homography, params, drawPath);
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h         |            | print this help }"
        "{@image1        | graf1.png  | first image (OpenCV sample names are found in OPENCV_SAMPLES_DATA_PATH) }"
        "{@image2        | graf3.png  | second image }"
        "{sequence s     |            | instead of two images: a folder of frames (KITTI-style with calib.txt and "
                                        "poses.txt for the epipolar check) or a video; consecutive frames are matched }"
        "{method m       | lsdadvance | one of: " + std::string(lineMethodNames()) + " }"
        "{params p       |            | YAML/XML of LSDAdvance parameters saved with write(), for the lsdadvance method }"
        "{homography H   |            | 3x3 homography from image 1 to image 2 (text, or OpenCV XML such as H1to3p.xml) }"
        "{max-hamming    | 30         | largest Hamming distance of a kept match, 0 to 256 (LBD: 256 bits) }"
        "{no-cross-check |            | keep every nearest neighbour, not only mutual ones }"
        "{draw d         |            | write the matches drawn side by side to this image (.jpg or .png; first pair "
                                        "of a sequence); with --homography or poses, correct matches in green and "
                                        "wrong ones in red, with their counts }";
    const String about = "Matches line segments with LBD, e.g. lsd_advance_lbd_matching graf1.png graf3.png "
                         "-H=H1to3p.xml --draw=matches.jpg, or lsd_advance_lbd_matching --sequence=<kitti folder>. "
                         "Exit status: 0, 1 on an error, 2 when unreadable files of a sequence folder were skipped.";
    return runSample(argc, argv, keys, about, { "no-cross-check" }, {}, run);
}

#else

#include <cstdio>

int main()
{
    std::fprintf(stderr, "lsd_advance_lbd_matching needs OpenCV's line_descriptor module, absent from this build\n");
    return 1;
}

#endif
