// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detects line segments with OpenCV's LSD and with LSDAdvance on one image, prints the count,
// the share of long segments and the median time of each, and writes both results side by side.

#include <opencv2/lsd_advance.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>

using namespace cv;

namespace {

struct Run
{
    std::vector<Vec4f> lines;
    double medianMs;
};

Run timeDetection(const std::function<void(std::vector<Vec4f>&)>& detect, int repeats)
{
    Run run;
    std::vector<double> ms;
    for (int i = 0; i < repeats; i++)
    {
        TickMeter tm;
        tm.start();
        detect(run.lines);
        tm.stop();
        ms.push_back(tm.getTimeMilli());
    }
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    run.medianMs = ms[ms.size() / 2];
    return run;
}

double longShare(const std::vector<Vec4f>& lines, double minLength)
{
    if (lines.empty())
        return 0.0;
    const auto isLong = [&](const Vec4f& l) { return std::hypot(l[2] - l[0], l[3] - l[1]) >= minLength; };
    return (double)std::count_if(lines.begin(), lines.end(), isLong) / (double)lines.size();
}

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

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |                      | print this help }"
        "{image i  | building.jpg         | input image (found with cv::samples::findFile) }"
        "{output o | lsd_advance_demo.png | side-by-side picture: LSD left, LSDAdvance right }"
        "{params p |                      | optional YAML/XML file of LSDAdvance parameters saved with write() }"
        "{repeats  | 11                   | detections per method; the median time is printed }"
        "{long     | 60                   | length in pixels from which a segment counts as long }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("LSDAdvance demo: fewer, longer line segments than LSD, at about LSD's cost.");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    const String imagePath = samples::findFile(parser.get<String>("image"));
    const String outputPath = parser.get<String>("output");
    const String paramsPath = parser.get<String>("params");
    const int repeats = std::max(1, parser.get<int>("repeats"));
    const double longLength = parser.get<double>("long");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }

    const Mat gray = imread(imagePath, IMREAD_GRAYSCALE);
    if (gray.empty())
    {
        std::cerr << "Cannot read " << imagePath << std::endl;
        return 1;
    }

    Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
    Ptr<ximgproc::LSDAdvance> advance = ximgproc::createLSDAdvance();
    if (!paramsPath.empty())
    {
        FileStorage fs(paramsPath, FileStorage::READ);
        if (!fs.isOpened())
        {
            std::cerr << "Cannot open " << paramsPath << std::endl;
            return 1;
        }
        advance->read(fs.root());
    }

    const Run lsdRun = timeDetection([&](std::vector<Vec4f>& lines) { lsd->detect(gray, lines); }, repeats);
    // Each repetition is an independent image, not the next frame of a sequence.
    const Run advanceRun = timeDetection([&](std::vector<Vec4f>& lines) {
        advance->reset();
        advance->detect(gray, lines);
    }, repeats);

    std::cout << "image: " << imagePath << " (" << gray.cols << "x" << gray.rows << ")\n";
    std::printf("%-12s %9s %12s %11s\n", "method", "segments", "long share", "median ms");
    std::printf("%-12s %9zu %12.3f %11.2f\n", "LSD", lsdRun.lines.size(),
                longShare(lsdRun.lines, longLength), lsdRun.medianMs);
    std::printf("%-12s %9zu %12.3f %11.2f\n", "LSDAdvance", advanceRun.lines.size(),
                longShare(advanceRun.lines, longLength), advanceRun.medianMs);
    std::printf("time ratio LSDAdvance / LSD: %.2f (median of %d runs each)\n",
                advanceRun.medianMs / lsdRun.medianMs, repeats);

    Mat sideBySide;
    hconcat(panel(lsd, gray, lsdRun.lines, format("LSD: %zu segments", lsdRun.lines.size())),
            panel(lsd, gray, advanceRun.lines, format("LSDAdvance: %zu segments", advanceRun.lines.size())),
            sideBySide);
    if (!imwrite(outputPath, sideBySide))
    {
        std::cerr << "Cannot write " << outputPath << std::endl;
        return 1;
    }
    std::cout << "wrote " << outputPath << std::endl;
    return 0;
}
