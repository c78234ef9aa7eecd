// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The LBD matching front end the samples share: segments -> KeyLines -> LBD descriptors ->
// mutual nearest neighbours under a Hamming-distance bound. OpenCV's line_descriptor does the
// describing and matching; only the filtering of its matches is here.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_LINE_MATCHING_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_LINE_MATCHING_HPP

#include <opencv2/line_descriptor.hpp>
#include <opencv2/lsd_advance.hpp>

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

#endif
