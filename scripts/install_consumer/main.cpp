// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Detects the line segments of an image with the installed lsd_advance module and prints how
// many it found. Build it with the CMakeLists.txt next to it, or with
//   g++ main.cpp $(pkg-config --cflags --libs opencv_lsd_advance)

#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance.hpp>

#include <fstream>
#include <iostream>
#include <vector>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "Error: give one image, e.g. " << argv[0] << " building.jpg" << std::endl;
        return 1;
    }
    // Checked here: imread would also log a warning of its own about a missing file.
    if (!std::ifstream(argv[1]))
    {
        std::cerr << "Error: cannot open " << argv[1] << std::endl;
        return 1;
    }
    try
    {
        const cv::Mat image = cv::imread(argv[1], cv::IMREAD_GRAYSCALE);
        if (image.empty())
        {
            std::cerr << "Error: cannot read " << argv[1] << " as an image" << std::endl;
            return 1;
        }
        cv::Ptr<cv::ximgproc::LSDAdvance> detector = cv::ximgproc::createLSDAdvance();
        std::vector<cv::Vec4f> lines;
        detector->detect(image, lines);
        std::cout << lines.size() << " line segments in " << argv[1] << std::endl;
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "Error: " << e.err << std::endl;
        return 1;
    }
    return 0;
}
