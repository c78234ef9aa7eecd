// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance on a video as a SLAM front end runs it: one detector for the whole sequence,
// PRESET_SEQUENCE, whose length threshold follows the segment counts of the frames before
// (the inter-frame factor alpha of getLastStats()). Prints the count and threshold now and
// then, their spread over the video, and writes the last frame with its segments.

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

using namespace cv;

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |                       | print this help }"
        "{@video   | vtest.avi             | a video, or an image sequence such as frame_%04d.png (OpenCV's samples are found by name) }"
        "{frames   | 0                     | frames to process, 0 for all }"
        "{output o | lsd_advance_video.png | the last frame with its segments }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("LSDAdvance on a video with PRESET_SEQUENCE (the count-tracking inter-frame rule).");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    const String videoName = parser.get<String>("@video"), outputPath = parser.get<String>("output");
    const int maxFrames = parser.get<int>("frames");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }
    try
    {
        VideoCapture video(samples::findFileOrKeep(videoName, true));
        if (!video.isOpened())
            CV_Error(Error::StsBadArg, "cannot read " + videoName + " as a video");
        // One detector per sequence; call reset() where the next frame does not follow (a cut).
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_SEQUENCE);
        Mat frame, last;
        std::vector<Vec4f> lines;
        double sum = 0, sumOfSquares = 0;
        int frames = 0;
        for (; (maxFrames <= 0 || frames < maxFrames) && video.read(frame); frames++)
        {
            detector->detect(frame, lines);  // BGR frames are converted to gray inside
            sum += (double)lines.size();
            sumOfSquares += (double)lines.size() * lines.size();
            const ximgproc::LSDAdvanceStats stats = detector->getLastStats();
            if (frames % 100 == 0)
                std::printf("frame %d: %zu segments, length threshold %.1f px (alpha %.2f)\n", frames, lines.size(),
                            stats.minLength, stats.alpha);
            frame.copyTo(last);
        }
        if (frames == 0)
            CV_Error(Error::StsBadArg, "no frame in " + videoName);
        const double mean = sum / frames;
        std::printf("frames: %d, segments per frame: %.1f mean, %.1f standard deviation\n", frames, mean,
                    std::sqrt(std::max(0.0, sumOfSquares / frames - mean * mean)));
        detector->drawSegments(last, lines);
        if (!imwrite(outputPath, last))
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
