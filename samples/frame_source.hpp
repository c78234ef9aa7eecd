// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The samples' input (an image file, the images of a folder in name order, or a video) and
// their error reporting.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_FRAME_SOURCE_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_FRAME_SOURCE_HPP

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

//! Runs a sample's main work; an exception becomes its message on stderr and exit code 1.
inline int runReportingErrors(const std::function<int()>& run)
{
    try
    {
        return run();
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "Error: " << e.err << std::endl;
    }
    catch (const std::exception& e)
    {
        std::cerr << "Error: " << e.what() << std::endl;
    }
    return 1;
}

// File name without folder and extension.
inline std::string stemOf(const std::string& path)
{
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return name.substr(0, name.rfind('.'));
}

// The gray images to detect on, one after the other: an image file, the images of a folder
// in name order, or the frames of a video.
class FrameSource
{
public:
    //! Throws std::runtime_error when the input does not exist, cannot be read or holds no image.
    explicit FrameSource(const cv::String& input)
    {
        // Finds sample names such as building.jpg; keeps what it cannot find (video URLs, patterns).
        const cv::String path = cv::samples::findFileOrKeep(input, true);
        if (cv::utils::fs::isDirectory(path))
            paths_ = cv::ximgproc::line_evaluation::loadSequence(path).imagePaths;  // name order; throws when there is none
        else if (cv::utils::fs::exists(path) && cv::haveImageReader(path))
        {
            paths_.push_back(path);
            singleImage_ = true;
        }
        // Streams and image-sequence patterns do not exist as files; anything else missing is
        // reported here rather than by the video backends' warnings.
        else if (!cv::utils::fs::exists(path) && path.find("://") == cv::String::npos && path.find('%') == cv::String::npos)
            throw std::runtime_error("no such image, folder or video: " + path);
        else if (!video_.open(path))
            throw std::runtime_error("cannot read " + path + " as an image or a video");
    }

    //! Number of images, 0 when a video does not tell.
    size_t count() const
    {
        return video_.isOpened() ? (size_t)std::max(0.0, video_.get(cv::CAP_PROP_FRAME_COUNT)) : paths_.size();
    }

    //! An image file, not a folder or a video.
    bool isSingleImage() const { return singleImage_; }

    //! The next image as CV_8UC1 and the stem of its output files; false after the last one.
    bool next(cv::Mat& gray, std::string& stem)
    {
        if (video_.isOpened())
        {
            cv::Mat frame;
            if (!video_.read(frame) || frame.empty())
                return false;
            if (frame.channels() == 1)
                gray = frame;
            else
                cv::cvtColor(frame, gray, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
            stem = cv::format("frame_%06d", frameIndex_++);
            return true;
        }
        if (nextPath_ == paths_.size())
            return false;
        const cv::String& path = paths_[nextPath_++];
        gray = cv::imread(path, cv::IMREAD_GRAYSCALE);
        if (gray.empty())
            throw std::runtime_error("cannot read " + path);
        stem = stemOf(path);
        return true;
    }

private:
    std::vector<cv::String> paths_;
    bool singleImage_ = false;
    size_t nextPath_ = 0;
    cv::VideoCapture video_;
    int frameIndex_ = 0;
};

#endif
