// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// LSDAdvance's lines matched between two views with the LBD descriptor: detect, convert to
// KeyLines, describe (computeLBD: line_descriptor's LBD descriptors, byte for byte, in a fraction
// of BinaryDescriptor::compute's time), keep mutual nearest neighbours within a Hamming distance
// (the usual set-up of line-based SLAM front ends). Given the homography between the views, the correct matches
// are counted (doc/matching.md) and drawn in green, the wrong ones in red.

#include <opencv2/core.hpp>

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/line_descriptor.hpp>
#include <opencv2/lsd_advance.hpp>

#include <cstdio>
#include <iostream>

using namespace cv;
using namespace cv::line_descriptor;

// Matches of descriptors1 (query) to descriptors2 (train) that are each other's nearest
// neighbour within maxHamming bits.
static std::vector<DMatch> mutualMatches(const Mat& descriptors1, const Mat& descriptors2, int maxHamming)
{
    std::vector<DMatch> forward, backward, kept;
    if (descriptors1.empty() || descriptors2.empty())
        return kept;
    Ptr<BinaryDescriptorMatcher> matcher = BinaryDescriptorMatcher::createBinaryDescriptorMatcher();
    matcher->match(descriptors1, descriptors2, forward);
    matcher->match(descriptors2, descriptors1, backward);
    std::vector<int> nearestOf2(descriptors2.rows, -1);
    for (const DMatch& m : backward)
        nearestOf2[m.queryIdx] = m.trainIdx;
    for (const DMatch& m : forward)
        if (m.distance <= maxHamming && nearestOf2[m.trainIdx] == m.queryIdx)
            kept.push_back(m);
    return kept;
}

int main(int argc, char** argv)
{
    const String keys =
        "{help h        |           | print this help }"
        "{@image1       | graf1.png | first image (OpenCV's sample images are found by name) }"
        "{@image2       | graf3.png | second image }"
        "{homography H  |           | 3x3 homography from image 1 to image 2 (text, or OpenCV XML such as H1to3p.xml) }"
        "{max-hamming   | 30        | largest Hamming distance of a kept match (LBD: 256 bits) }"
        "{draw d        |           | write the matches drawn side by side to this image }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("Matches LSDAdvance's lines with LBD, e.g. lsd_advance_lbd_matching graf1.png graf3.png "
                 "-H=H1to3p.xml -d=matches.jpg");
    if (parser.has("help"))
    {
        parser.printMessage();
        return 0;
    }
    const String names[2] = { parser.get<String>("@image1"), parser.get<String>("@image2") };
    const String homographyName = parser.get<String>("homography"), drawPath = parser.get<String>("draw");
    const int maxHamming = parser.get<int>("max-hamming");
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }
    try
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        Mat gray[2], descriptors[2];
        std::vector<Vec4f> lines[2];
        std::vector<KeyLine> keylines[2];
        for (int i = 0; i < 2; i++)
        {
            gray[i] = imread(samples::findFile(names[i], true, true), IMREAD_GRAYSCALE);
            if (gray[i].empty())
                CV_Error(Error::StsBadArg, "cannot read " + names[i] + " as an image");
            detector->reset();  // two views, not consecutive frames of a sequence
            detector->detect(gray[i], lines[i]);
            ximgproc::linesToKeyLines(lines[i], gray[i].size(), keylines[i]);
            ximgproc::computeLBD(gray[i], keylines[i], descriptors[i]);
        }
        const std::vector<DMatch> matches = mutualMatches(descriptors[0], descriptors[1], maxHamming);
        std::printf("segments:        %zu / %zu\n", lines[0].size(), lines[1].size());
        std::printf("matches:         %zu\n", matches.size());

        Mat H;
        if (!homographyName.empty())
        {
            H = ximgproc::line_evaluation::readHomography(samples::findFile(homographyName, true, true));
            const ximgproc::line_evaluation::HomographyMatchScore score = ximgproc::line_evaluation::evaluateHomographyMatches(
                lines[0], lines[1], matches, H, gray[0].size(), gray[1].size());
            std::printf("correct:         %d (precision %.3f; mapped within 3 px, overlapping)\n", score.correct,
                        score.precision);
        }
        if (!drawPath.empty())
        {
            // Image 1 on the left, image 2 on the right; without H every match is yellow.
            Mat canvas, left, right;
            cvtColor(gray[0], left, COLOR_GRAY2BGR);
            cvtColor(gray[1], right, COLOR_GRAY2BGR);
            copyMakeBorder(left, left, 0, std::max(0, right.rows - left.rows), 0, 0, BORDER_CONSTANT);
            copyMakeBorder(right, right, 0, std::max(0, left.rows - right.rows), 0, 0, BORDER_CONSTANT);
            hconcat(left, right, canvas);
            const Point2f shift((float)gray[0].cols, 0.f);
            for (const DMatch& m : matches)
            {
                const Vec4f& a = lines[0][m.queryIdx];
                const Vec4f& b = lines[1][m.trainIdx];
                const Scalar colour = H.empty() ? Scalar(0, 210, 255)
                                      : ximgproc::line_evaluation::correspondUnderHomography(a, b, H) ? Scalar(60, 200, 60)
                                                                                                     : Scalar(60, 60, 255);
                line(canvas, Point2f(a[0], a[1]), Point2f(a[2], a[3]), colour, 2);
                line(canvas, Point2f(b[0], b[1]) + shift, Point2f(b[2], b[3]) + shift, colour, 2);
            }
            if (!imwrite(drawPath, canvas))
                CV_Error(Error::StsError, "cannot write " + drawPath);
            std::printf("wrote %s\n", drawPath.c_str());
        }
    }
    catch (const Exception& e)
    {
        std::cerr << "Error: " << e.err << std::endl;
        return 1;
    }
    return 0;
}

#else

#include <cstdio>

int main()
{
    std::fprintf(stderr, "lsd_advance_lbd_matching needs OpenCV's line_descriptor module, absent from this build\n");
    return 1;
}

#endif
