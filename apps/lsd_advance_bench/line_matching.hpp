// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The LBD matching front end of the benchmark (and of the tests that check its tables):
// segments -> KeyLines -> LBD descriptors -> mutual nearest neighbours under a Hamming-distance
// bound. OpenCV's line_descriptor does the describing and matching; only the filtering of its
// matches is here.

#ifndef OPENCV_LSD_ADVANCE_APPS_LINE_MATCHING_HPP
#define OPENCV_LSD_ADVANCE_APPS_LINE_MATCHING_HPP

#include <opencv2/line_descriptor.hpp>
#include <opencv2/lsd_advance.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

//! How matches are kept: the usual set-up of line-based SLAM front ends.
struct LineMatchParams
{
    int maxHamming = 30;     //!< largest Hamming distance of a kept match (of 256 bits)
    bool crossCheck = true;  //!< keep a match only when each line is the other's nearest neighbour
};

//! Segments of one image with their KeyLines and LBD descriptors (one row per KeyLine).
struct DescribedLines
{
    std::vector<cv::Vec4f> lines;
    std::vector<cv::line_descriptor::KeyLine> keylines;
    cv::Mat descriptors;
};

//! KeyLines (as LSDAdvance::detect(image, keylines) makes them) and LBD descriptors of segments.
inline DescribedLines describeLines(const cv::Mat& gray, const std::vector<cv::Vec4f>& lines)
{
    DescribedLines described;
    described.lines = lines;
    cv::ximgproc::linesToKeyLines(lines, gray.size(), described.keylines);
    if (!described.keylines.empty())
        cv::line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, described.keylines,
                                                                               described.descriptors);
    return described;
}

//! KeyLine responses as linesToKeyLines sets them, like LSDDetector: length / longer image side.
inline std::vector<float> lengthResponses(const std::vector<cv::Vec4f>& lines, cv::Size imageSize)
{
    std::vector<cv::line_descriptor::KeyLine> keylines;
    cv::ximgproc::linesToKeyLines(lines, imageSize, keylines);
    std::vector<float> responses;
    for (const cv::line_descriptor::KeyLine& kl : keylines)
        responses.push_back(kl.response);
    return responses;
}

//! A front end's line budget: the `budget` lines of highest response, highest first (ties in
//! their order); all of them, in their order, when budget <= 0.
inline std::vector<cv::Vec4f> bestLines(const std::vector<cv::Vec4f>& lines, const std::vector<float>& responses,
                                        int budget)
{
    CV_Assert(responses.size() == lines.size());
    if (budget <= 0)
        return lines;
    std::vector<int> order(lines.size());
    for (size_t i = 0; i < order.size(); i++)
        order[i] = (int)i;
    std::stable_sort(order.begin(), order.end(), [&responses](int a, int b) { return responses[a] > responses[b]; });
    order.resize(std::min(order.size(), (size_t)budget));
    std::vector<cv::Vec4f> kept;
    for (int i : order)
        kept.push_back(lines[i]);
    return kept;
}

//! Matches of lines 1 (query) to lines 2 (train) kept by params.
inline std::vector<cv::DMatch> matchLines(const DescribedLines& lines1, const DescribedLines& lines2,
                                          const LineMatchParams& params)
{
    std::vector<cv::DMatch> kept;
    if (lines1.descriptors.empty() || lines2.descriptors.empty())
        return kept;
    cv::Ptr<cv::line_descriptor::BinaryDescriptorMatcher> matcher =
        cv::line_descriptor::BinaryDescriptorMatcher::createBinaryDescriptorMatcher();
    std::vector<cv::DMatch> forward, backward;
    matcher->match(lines1.descriptors, lines2.descriptors, forward);
    if (params.crossCheck)
        matcher->match(lines2.descriptors, lines1.descriptors, backward);
    std::vector<int> nearestOf2(lines2.descriptors.rows, -1);
    for (const cv::DMatch& m : backward)
        nearestOf2[m.queryIdx] = m.trainIdx;
    for (const cv::DMatch& m : forward)
        if (m.distance <= params.maxHamming && (!params.crossCheck || nearestOf2[m.trainIdx] == m.queryIdx))
            kept.push_back(m);
    return kept;
}

//! Chains the matches of consecutive frames into tracks: a line matched to a line of the
//! previous frame continues that line's track, or starts one with it.
struct LineTracks
{
    std::vector<int> previous;  //!< track of each line of the previous frame, -1 for none
    std::vector<int> lengths;   //!< frames of each track (at least 2)
    int frames = 0;

    //! Adds a frame of `lines` lines; matchesFromPrevious match the previous frame's lines (query)
    //! to this frame's (train).
    void addFrame(size_t lines, const std::vector<cv::DMatch>& matchesFromPrevious)
    {
        std::vector<int> current(lines, -1);
        for (const cv::DMatch& m : matchesFromPrevious)
        {
            int& track = previous[m.queryIdx];
            if (track < 0)
            {
                track = (int)lengths.size();
                lengths.push_back(1);
            }
            current[m.trainIdx] = track;
            lengths[track]++;
        }
        previous.swap(current);
        frames++;
    }
    //! Tracks a frame's lines belong to, on average over the frames.
    double perFrame() const
    {
        return frames > 0 ? std::accumulate(lengths.begin(), lengths.end(), 0.0) / frames : 0.0;
    }
    //! Mean frames per track.
    double meanLength() const
    {
        return lengths.empty() ? 0.0 : std::accumulate(lengths.begin(), lengths.end(), 0.0) / lengths.size();
    }
    //! Tracks of at least frameCount frames.
    int atLeast(int frameCount) const
    {
        return (int)std::count_if(lengths.begin(), lengths.end(), [frameCount](int l) { return l >= frameCount; });
    }
};

#endif
