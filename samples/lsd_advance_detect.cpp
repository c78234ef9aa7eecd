// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detects line segments in an image, each image of a folder or each frame of a video with one
// of the methods of line_methods.hpp, optionally writes them (<stem>.txt, x1 y1 x2 y2 per row)
// and drawn on the image (<stem>.png), and prints segments per image, the share of long
// segments and the time of the detection.

#include "frame_source.hpp"
#include "line_methods.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <stdexcept>

using namespace cv;

namespace {

struct Summary
{
    size_t images = 0;
    double segments = 0, longSegments = 0;
    std::vector<double> ms;

    void add(const std::vector<Vec4f>& lines, double detectMs, double longLength)
    {
        images++;
        segments += (double)lines.size();
        longSegments += ximgproc::longSegmentShare(lines, longLength) * (double)lines.size();
        ms.push_back(detectMs);
    }

    void print(const std::string& method, double longLength) const
    {
        std::printf("method:            %s\n", method.c_str());
        std::printf("images:            %zu\n", images);
        std::printf("segments / image:  %.1f\n", segments / (double)images);
        std::printf("long share:        %.3f (>= %g px, over all segments)\n",
                    segments > 0 ? longSegments / segments : 0.0, longLength);
        std::printf("ms / image:        %.2f mean, %.2f median (detection only)\n", mean(ms)[0], median(ms));
    }
};

int run(const CommandLineParser& parser)
{
    const String input = parser.get<String>("input");
    const String output = parser.get<String>("output");
    const String paramsPath = parser.get<String>("params");
    const bool sequence = parser.has("sequence"), draw = parser.has("draw");
    const double longLength = parser.get<double>("long");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }
    if (draw && output.empty())
        throw std::runtime_error("--draw needs --output");

    FileStorage params;
    if (!paramsPath.empty() && !params.open(paramsPath, FileStorage::READ))
        throw std::runtime_error("cannot open " + paramsPath);
    const LineMethod method = makeLineMethod(parser.get<std::string>("method"),
                                             params.isOpened() ? params.root() : FileNode());
    FrameSource source(input);
    if (!output.empty() && !utils::fs::createDirectories(output))
        throw std::runtime_error("cannot create the output folder " + output);

    const Ptr<LineSegmentDetector> drawer = createLineSegmentDetector();
    const size_t total = source.count();
    Summary summary;
    Mat gray;
    std::string stem;
    method.reset();
    while (source.next(gray, stem))
    {
        // Unrelated images must not steer the inter-frame factor of the next one.
        if (!sequence)
            method.reset();
        std::vector<Vec4f> lines;
        TickMeter tm;
        tm.start();
        method.detect(gray, lines);
        tm.stop();
        summary.add(lines, tm.getTimeMilli(), longLength);

        if (!output.empty())
            ximgproc::writeSegments(utils::fs::join(output, stem + ".txt"), lines);
        if (draw)
        {
            Mat canvas;
            cvtColor(gray, canvas, COLOR_GRAY2BGR);
            drawer->drawSegments(canvas, lines);
            const String png = utils::fs::join(output, stem + ".png");
            if (!imwrite(png, canvas))
                throw std::runtime_error("cannot write " + png);
        }
        if (!source.isSingleImage())
        {
            std::cerr << "\r[detect] " << summary.images;
            if (total > 0)
                std::cerr << "/" << total;
            std::cerr << std::flush;
        }
    }
    if (!source.isSingleImage())
        std::cerr << "\n";
    if (summary.images == 0)
        throw std::runtime_error("no frame in " + input);

    summary.print(method.name, longLength);
    if (!output.empty())
        std::printf("wrote %zu segment file(s)%s to %s\n", summary.images, draw ? " and drawings" : "",
                    output.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |            | print this help }"
        "{input i  | <none>     | an image, a folder of images (png, jpg, jpeg, ppm, pgm, bmp) or a video }"
        "{output o |            | folder for <stem>.txt (x1 y1 x2 y2 per segment, pixel centres); created if missing }"
        "{method m | lsdadvance | one of: " + std::string(lineMethodNames()) + " }"
        "{sequence |            | the images of a folder (in name order) or a video are consecutive frames: "
                                 "LSDAdvance's inter-frame factor is on; otherwise every image is independent }"
        "{draw     |            | also write <stem>.png, the segments drawn on the image (needs --output) }"
        "{params p |            | YAML/XML of LSDAdvance parameters saved with write(), for the lsdadvance method }"
        "{long     | 60         | length in pixels from which a segment counts as long }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("Detects line segments with LSDAdvance (or another method) and writes them to text files.");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    return runReportingErrors([&parser] { return run(parser); });
}
