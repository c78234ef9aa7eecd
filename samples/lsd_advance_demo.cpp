// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detects line segments with OpenCV's LSD and with LSDAdvance on one image (or each image of a
// folder), prints segments per image, the share of long segments and the median time of each,
// and writes both results for the (first) image side by side.

#include "command_line.hpp"
#include "frame_source.hpp"
#include "line_methods.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>

using namespace cv;

namespace {

// Segment counts, long segments and per-image median times of one method over all images.
struct Totals
{
    size_t segments = 0, longSegments = 0;
    std::vector<double> ms;

    void add(const std::vector<Vec4f>& lines, double medianMs, double longLength)
    {
        segments += lines.size();
        longSegments += (size_t)cvRound(ximgproc::line_evaluation::longSegmentShare(lines, longLength) * (double)lines.size());
        ms.push_back(medianMs);
    }
    void print(const char* name, size_t images) const
    {
        std::printf("%-12s %17.1f %12.3f %18.2f\n", name, (double)segments / images,
                    segments ? (double)longSegments / segments : 0.0, median(ms));
    }
};

Mat panel(const Ptr<LineSegmentDetector>& drawer, const Mat& gray, const std::vector<Vec4f>& lines,
          const std::string& title)
{
    Mat canvas;
    cvtColor(gray / 2 + 64, canvas, COLOR_GRAY2BGR);
    drawer->drawSegments(canvas, lines);
    putText(canvas, title, Point(10, 28), FONT_HERSHEY_SIMPLEX, 0.8, Scalar(0, 0, 0), 4, LINE_AA);
    putText(canvas, title, Point(10, 28), FONT_HERSHEY_SIMPLEX, 0.8, Scalar(255, 255, 255), 2, LINE_AA);
    return canvas;
}

int run(const CommandLine& args)
{
    const String input = args.text("image");
    const String outputPath = args.text("output");
    const int repeats = args.integer("repeats", 1);
    const double longLength = args.number("long", 0, kUnbounded, true);
    checkOutputFolder("output", outputPath);
    if (!haveImageWriter(outputPath))
        throw std::runtime_error("--output=" + outputPath + ": no image format for this file name (use .png or .jpg)");
    const FileStorage params = openParamsFile(args.text("params"));
    const LineMethod lsd = makeLineMethod("lsd");
    const LineMethod advance = makeLineMethod("lsdadvance", params.isOpened() ? params.root() : FileNode());
    Ptr<LineSegmentDetector> drawer = createLineSegmentDetector();

    // An image, the images of a folder (in name order) or the frames of a video, each on its own.
    FrameSource source(input, "demo");
    Totals lsdTotals, advanceTotals;
    std::vector<double> ratios;
    Mat gray;
    std::string stem;
    for (size_t k = 0; source.next(gray, stem); k++)
    {
        // Every image is independent, not the next frame of a sequence.
        std::vector<Vec4f> lsdLines, advanceLines;
        const double lsdMs = timedDetect(lsd, gray, repeats, lsdLines, true);
        const double advanceMs = timedDetect(advance, gray, repeats, advanceLines, true);
        lsdTotals.add(lsdLines, lsdMs, longLength);
        advanceTotals.add(advanceLines, advanceMs, longLength);
        ratios.push_back(advanceMs / lsdMs);

        if (k == 0)
        {
            Mat sideBySide;
            hconcat(panel(drawer, gray, lsdLines, format("LSD: %zu segments", lsdLines.size())),
                    panel(drawer, gray, advanceLines, format("LSDAdvance: %zu segments", advanceLines.size())),
                    sideBySide);
            if (!imwrite(outputPath, sideBySide))
                throw std::runtime_error("cannot write " + outputPath);
        }
    }
    if (ratios.empty())
        throw std::runtime_error("no frame in " + input);

    const std::string skipped =
        source.skipped().empty() ? std::string() : format(" (%zu unreadable skipped)", source.skipped().size());
    std::cout << (source.isSingleImage() ? "image: " + input : format("images: %zu in %s", ratios.size(), input.c_str()))
              << skipped << "\n";
    std::printf("%-12s %17s %12s %18s\n", "method", "segments / image", "long share", "median ms / image");
    lsdTotals.print("LSD", ratios.size());
    advanceTotals.print("LSDAdvance", ratios.size());
    std::printf("time ratio LSDAdvance / LSD: %.2f (median over images of per-image medians of %d runs)\n",
                median(ratios), repeats);
    std::cout << "wrote " << outputPath << std::endl;
    return source.skipped().empty() ? 0 : kExitSkipped;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |                      | print this help }"
        "{image i  | building.jpg         | input image (found with cv::samples::findFile), a folder of images or a video }"
        "{output o | lsd_advance_demo.png | side-by-side picture of the (first) image: LSD left, LSDAdvance right }"
        "{params p |                      | optional YAML/XML file of LSDAdvance parameters saved with write() or save() }"
        "{repeats  | 11                   | detections per method and image, >= 1; the median time is used }"
        "{long     | 60                   | length in pixels from which a segment counts as long, > 0 }";
    const String about = "LSDAdvance demo: fewer, longer line segments than LSD, side by side, with the time of each. "
                         "Exit status: 0, 1 on an error, 2 when unreadable files of a folder were skipped.";
    return runSample(argc, argv, keys, about, {}, {}, run);
}
