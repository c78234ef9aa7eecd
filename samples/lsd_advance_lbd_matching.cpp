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

void drawMatches(const Mat& gray1, const DescribedLines& lines1, const Mat& gray2, const DescribedLines& lines2,
                 const std::vector<DMatch>& matches, const String& path)
{
    Mat colour1, colour2;
    cvtColor(gray1, colour1, COLOR_GRAY2BGR);
    cvtColor(gray2, colour2, COLOR_GRAY2BGR);
    // Matched lines only, each match in its own colour; with NOT_DRAW_SINGLE_LINES,
    // drawLineMatches draws into a canvas of the right size that the caller allocates.
    Mat canvas(std::max(gray1.rows, gray2.rows), gray1.cols + gray2.cols, CV_8UC3, Scalar::all(0));
    const std::vector<char> everyMatch(matches.size(), 1);
    line_descriptor::drawLineMatches(colour1, lines1.keylines, colour2, lines2.keylines, matches, canvas,
                                     Scalar::all(-1), Scalar::all(-1), everyMatch,
                                     line_descriptor::DrawLinesMatchesFlags::NOT_DRAW_SINGLE_LINES);
    if (!imwrite(path, canvas, { IMWRITE_JPEG_QUALITY, 85 }))
        throw std::runtime_error("cannot write " + path);
    std::printf("wrote %s\n", path.c_str());
}

int matchPair(const LineMethod& method, const String& path1, const String& path2, const String& homographyPath,
              const LineMatchParams& params, const String& drawPath)
{
    const Mat gray1 = imread(samples::findFile(path1, true, true), IMREAD_GRAYSCALE);
    const Mat gray2 = imread(samples::findFile(path2, true, true), IMREAD_GRAYSCALE);
    if (gray1.empty() || gray2.empty())
        throw std::runtime_error("cannot read " + (gray1.empty() ? path1 : path2));
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
    if (!homographyPath.empty())
    {
        const Mat H = ximgproc::line_evaluation::readHomography(samples::findFile(homographyPath, true, true));
        const ximgproc::line_evaluation::HomographyMatchScore s =
            ximgproc::line_evaluation::evaluateHomographyMatches(segments1, segments2, matches, H, gray1.size(), gray2.size());
        std::printf("correct:         %d (precision %.3f; mapped within 3 px, overlapping)\n", s.correct, s.precision);
        std::printf("repeatability:   %.3f (%d of %d visible segments)\n", s.repeatability, s.repeated, s.visible);
        std::printf("localisation:    %.2f px (mean, repeated segments)\n", s.localisationError);
    }
    if (!drawPath.empty())
        drawMatches(gray1, lines1, gray2, lines2, matches, drawPath);
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
    for (int frame = 0; source.next(gray, stem); frame++)
    {
        std::vector<Vec4f> segments;
        method.detect(gray, segments);
        DescribedLines current = describeLines(gray, segments);
        if (frame > 0)
        {
            const std::vector<DMatch> matches = matchLines(previous, current, params);
            totalMatches += matches.size();
            std::printf("frames %d-%d: segments %zu / %zu, matches %zu", frame - 1, frame, previous.lines.size(),
                        current.lines.size(), matches.size());
            if (withPoses)
            {
                const Mat F = ximgproc::line_evaluation::fundamentalFromPoses(calibration.P0, calibration.poses[frame - 1],
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
                drawMatches(previousGray, previous, gray, current, matches, drawPath);
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
    return 0;
}

int run(const CommandLineParser& parser)
{
    const String image1 = parser.get<String>("@image1"), image2 = parser.get<String>("@image2");
    const String sequence = parser.get<String>("sequence");
    const String homography = parser.get<String>("homography"), drawPath = parser.get<String>("draw");
    LineMatchParams params;
    params.maxHamming = parser.get<int>("max-hamming");
    params.crossCheck = !parser.has("no-cross-check");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }
    const String paramsPath = parser.get<String>("params");
    FileStorage paramsFile;
    if (!paramsPath.empty() && !paramsFile.open(paramsPath, FileStorage::READ))
        throw std::runtime_error("cannot open " + paramsPath);
    const LineMethod method = makeLineMethod(parser.get<std::string>("method"),
                                             paramsFile.isOpened() ? paramsFile.root() : FileNode());
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
        "{max-hamming    | 30         | largest Hamming distance of a kept match (LBD: 256 bits) }"
        "{no-cross-check |            | keep every nearest neighbour, not only mutual ones }"
        "{draw d         |            | write the matches drawn side by side to this image (first pair of a sequence) }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("Matches line segments with LBD, e.g. lsd_advance_lbd_matching graf1.png graf3.png -H=H1to3p.xml "
                 "--draw=matches.png, or lsd_advance_lbd_matching --sequence=<kitti folder>");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    return runReportingErrors([&parser] { return run(parser); });
}

#else

#include <cstdio>

int main()
{
    std::fprintf(stderr, "lsd_advance_lbd_matching needs OpenCV's line_descriptor module, absent from this build\n");
    return 1;
}

#endif
