// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance where LSD was: both detect on one image, the counts and times are printed, and
// the two results are drawn side by side into one picture.

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/ximgproc.hpp>

#include <cstdio>
#include <iostream>

using namespace cv;
// LineSegmentDetector is cv::'s up to OpenCV 4.x and cv::ximgproc::'s once it moves (opencv#29349):
// with both namespaces in use, the names below find either.
using namespace cv::ximgproc;

// The segments drawn on the darkened image, with a title.
static Mat panel(const Mat& gray, const std::vector<Vec4f>& lines, const String& title)
{
    Mat canvas;
    cvtColor(gray / 2 + 64, canvas, COLOR_GRAY2BGR);
    ximgproc::createLSDAdvance()->drawSegments(canvas, lines);
    putText(canvas, title, Point(10, 28), FONT_HERSHEY_SIMPLEX, 0.8, Scalar(0, 0, 0), 4, LINE_AA);
    putText(canvas, title, Point(10, 28), FONT_HERSHEY_SIMPLEX, 0.8, Scalar(255, 255, 255), 2, LINE_AA);
    return canvas;
}

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |                      | print this help }"
        "{@image   | building.jpg         | input image (OpenCV's sample images are found by name) }"
        "{output o | lsd_advance_demo.png | the picture: LSD on the left, LSDAdvance on the right }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("LSDAdvance demo: fewer, longer line segments than OpenCV's LSD, side by side.");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    const String imageName = parser.get<String>("@image"), outputPath = parser.get<String>("output");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }
    try
    {
        const Mat gray = imread(samples::findFile(imageName, true, true), IMREAD_GRAYSCALE);
        if (gray.empty())
            CV_Error(Error::StsBadArg, "cannot read " + imageName + " as an image");

        // Where LSD was created, LSDAdvance is: same input, same output format and orientation.
        Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
        Ptr<ximgproc::LSDAdvance> lsdAdvance = ximgproc::createLSDAdvance();
        std::vector<Vec4f> lsdLines, advanceLines;
        TickMeter lsdTime, advanceTime;
        lsdTime.start();
        lsd->detect(gray, lsdLines);
        lsdTime.stop();
        advanceTime.start();
        lsdAdvance->detect(gray, advanceLines);
        advanceTime.stop();

        const ximgproc::LSDAdvanceStats stats = lsdAdvance->getLastStats();
        std::printf("LSD:        %zu segments, %.1f ms\n", lsdLines.size(), lsdTime.getTimeMilli());
        std::printf("LSDAdvance: %zu segments, %.1f ms (its base found %d; merging left %d, of which the "
                    "length filter kept those of %.1f px or more)\n",
                    advanceLines.size(), advanceTime.getTimeMilli(), stats.baseSegments, stats.mergedSegments,
                    stats.minLength);

        Mat sideBySide;
        hconcat(panel(gray, lsdLines, format("LSD: %zu segments", lsdLines.size())),
                panel(gray, advanceLines, format("LSDAdvance: %zu segments", advanceLines.size())), sideBySide);
        if (!imwrite(outputPath, sideBySide))
            CV_Error(Error::StsError, "cannot write " + outputPath);
        std::cout << "wrote " << outputPath << std::endl;
    }
    catch (const Exception& e)
    {
        std::cerr << "Error: " << e.err << std::endl;
        return 1;
    }
    return 0;
}
