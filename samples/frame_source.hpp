// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The samples' input: an image file, the images of a folder in name order, or a video.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_FRAME_SOURCE_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_FRAME_SOURCE_HPP

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

//! Exit status of a run that skipped unreadable files of a folder and did the others.
constexpr int kExitSkipped = 2;

// File name without folder and extension.
inline std::string stemOf(const std::string& path)
{
    const size_t slash = path.find_last_of("/\\");
    const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    return name.substr(0, name.rfind('.'));
}

//! The gray image of a file, empty when OpenCV cannot decode it. The bytes go to imdecode:
//! imread's file reader would also print libjpeg's warnings (a truncated JPEG), the sample
//! reports unreadable files itself.
inline cv::Mat readGrayImage(const std::string& path)
{
    std::vector<uchar> bytes;
    std::ifstream file(path.c_str(), std::ios::binary);
    if (file)
        bytes.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    return bytes.empty() ? cv::Mat() : cv::imdecode(bytes, cv::IMREAD_GRAYSCALE);
}

//! Reports on stderr that a file of a folder was skipped.
inline void reportSkipped(const std::string& path)
{
    std::cerr << "skipped " << path << ": not an image OpenCV can read" << std::endl;
}

// The gray images to detect on, one after the other: an image file, the images of a folder
// in name order, or the frames of a video. A file of a folder that cannot be read as an image
// is reported on stderr and skipped; with a progress label, "[label] k/n" counts the files on
// one stderr line.
class FrameSource
{
public:
    //! Throws std::runtime_error when the input does not exist, cannot be read or holds no image.
    explicit FrameSource(const cv::String& input, const std::string& progressLabel = std::string())
        : progressLabel_(progressLabel)
    {
        // Finds sample names such as building.jpg; keeps what it cannot find (video URLs, patterns).
        const cv::String path = cv::samples::findFileOrKeep(input, true);
        const bool exists = cv::utils::fs::exists(path);
        if (cv::utils::fs::isDirectory(path))
            paths_ = cv::ximgproc::line_evaluation::loadSequence(path).imagePaths;  // name order; throws when there is none
        else if (exists && cv::haveImageReader(path))
        {
            paths_.push_back(path);
            singleImage_ = true;
        }
        // A file named as an image (OpenCV would write one under this name) is not tried as a
        // video: the video backends would only add their own messages to the sample's error.
        else if (exists && cv::haveImageWriter(path))
            throw std::runtime_error("cannot read " + path + " as an image");
        // Streams and image-sequence patterns do not exist as files; anything else missing is
        // reported here rather than by the video backends' warnings.
        else if (!exists && path.find("://") == cv::String::npos && path.find('%') == cv::String::npos)
            throw std::runtime_error("no such image, folder or video: " + path);
        else
        {
            // The backends that cannot open the file log why; the sample's error says it once.
            const cv::utils::logging::LogLevel logLevel =
                cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_FATAL);
            const bool opened = video_.open(path);
            cv::utils::logging::setLogLevel(logLevel);
            if (!opened)
                throw std::runtime_error("cannot read " + path + " as an image or a video");
        }
    }

    //! Number of images, 0 when a video does not tell.
    size_t count() const
    {
        return video_.isOpened() ? (size_t)std::max(0.0, video_.get(cv::CAP_PROP_FRAME_COUNT)) : paths_.size();
    }

    //! An image file, not a folder or a video.
    bool isSingleImage() const { return singleImage_; }

    //! The next image as CV_8UC1 and the stem of its output files; false after the last one.
    //! Throws std::runtime_error when no image at all could be read.
    bool next(cv::Mat& gray, std::string& stem)
    {
        if (video_.isOpened())
        {
            cv::Mat frame;
            if (!video_.read(frame) || frame.empty())
                return finish();
            if (frame.channels() == 1)
                gray = frame;
            else
                cv::cvtColor(frame, gray, frame.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
            stem = cv::format("frame_%06d", frameIndex_++);
            showProgress((size_t)frameIndex_);
            return true;
        }
        while (nextPath_ < paths_.size())
        {
            const cv::String& path = paths_[nextPath_++];
            showProgress(nextPath_);
            gray = readGrayImage(path);
            if (!gray.empty())
            {
                stem = stemOf(path);
                read_++;
                return true;
            }
            if (singleImage_)
                throw std::runtime_error("cannot read " + path + " as an image");
            skipped_.push_back(path);
            if (progressShown_)
                std::cerr << "\n";
            progressShown_ = false;
            reportSkipped(path);
        }
        return finish();
    }

    //! Number of the last image next() returned: its place in the folder (skipped files count)
    //! or in the video, from 0.
    size_t index() const { return video_.isOpened() ? (size_t)frameIndex_ - 1 : nextPath_ - 1; }

    //! The files of a folder skipped so far as unreadable.
    const std::vector<std::string>& skipped() const { return skipped_; }

private:
    void showProgress(size_t done)
    {
        if (progressLabel_.empty() || singleImage_)
            return;
        std::cerr << "\r[" << progressLabel_ << "] " << done;
        if (count() > 0)
            std::cerr << "/" << count();
        std::cerr << std::flush;
        progressShown_ = true;
    }

    // Ends the progress line; false, for next().
    bool finish()
    {
        if (progressShown_)
            std::cerr << "\n";
        progressShown_ = false;
        if (read_ == 0 && frameIndex_ == 0 && !skipped_.empty())
            throw std::runtime_error(cv::format("none of the %zu image files could be read", skipped_.size()));
        return false;
    }

    std::string progressLabel_;
    std::vector<cv::String> paths_;
    bool singleImage_ = false;
    size_t nextPath_ = 0, read_ = 0;
    std::vector<std::string> skipped_;
    bool progressShown_ = false;
    cv::VideoCapture video_;
    int frameIndex_ = 0;
};

#endif
