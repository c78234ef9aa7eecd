// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The LBD matching front end of the benchmark (and of the tests that check its tables):
// segments -> KeyLines -> LBD descriptors -> mutual nearest neighbours under a Hamming-distance
// bound; and a point-line SLAM front end's rules (minimum length, line budget, one-way matching
// under Hamming, endpoint-shift and angle gates) for the benchmark's front-end mode.
// The module's computeLBD describes (line_descriptor's descriptors, byte for byte; its
// BinaryDescriptor::compute is timed beside it) and line_descriptor's matcher matches; only the
// filtering of the lines and matches is here.

#ifndef OPENCV_LSD_ADVANCE_APPS_LINE_MATCHING_HPP
#define OPENCV_LSD_ADVANCE_APPS_LINE_MATCHING_HPP

#include <opencv2/core/utility.hpp>
#include <opencv2/line_descriptor.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/lsd_advance/keylines.hpp>

#include <algorithm>
#include <cmath>
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

//! KeyLines (as LSDAdvance::detect(image, keylines) makes them) and their LBD descriptors, by the
//! module's computeLBD: those of line_descriptor's BinaryDescriptor::compute.
inline DescribedLines describeLines(const cv::Mat& gray, const std::vector<cv::Vec4f>& lines)
{
    DescribedLines described;
    described.lines = lines;
    cv::ximgproc::linesToKeyLines(lines, gray.size(), described.keylines);
    cv::ximgproc::computeLBD(gray, described.keylines, described.descriptors);
    return described;
}

//! Milliseconds of each description (KeyLines and descriptors) of the same lines: describeLines()
//! (computeLBD), and the same with line_descriptor's BinaryDescriptor::compute, the LBD of the
//! front ends built on line_descriptor.
struct LbdTimes
{
    std::vector<double> computeLbd, lineDescriptor;
};

//! describeLines(), timed, and line_descriptor's description of the same lines, timed, in
//! alternating order from call to call; throws when the two descriptors differ.
inline DescribedLines describeLinesTimed(const cv::Mat& gray, const std::vector<cv::Vec4f>& lines, LbdTimes& times)
{
    DescribedLines described;
    cv::Mat reference;
    cv::TickMeter ours, theirs;
    const auto describeOurs = [&] {
        ours.start();
        described = describeLines(gray, lines);
        ours.stop();
    };
    const auto describeTheirs = [&] {
        theirs.start();
        std::vector<cv::line_descriptor::KeyLine> keylines;
        cv::ximgproc::linesToKeyLines(lines, gray.size(), keylines);
        if (!keylines.empty())  // it prints an error on none
            cv::line_descriptor::BinaryDescriptor::createBinaryDescriptor()->compute(gray, keylines, reference);
        theirs.stop();
    };
    if (times.computeLbd.size() % 2 == 0)
    {
        describeOurs();
        describeTheirs();
    }
    else
    {
        describeTheirs();
        describeOurs();
    }
    if (!lines.empty() && cv::norm(described.descriptors, reference, cv::NORM_HAMMING) != 0)
        CV_Error(cv::Error::StsInternal, "computeLBD's descriptors differ from line_descriptor's on the same KeyLines");
    times.computeLbd.push_back(ours.getTimeMilli());
    times.lineDescriptor.push_back(theirs.getTimeMilli());
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

//! A point-line SLAM front end's rules for its lines (PL-VINS's set-up by default): which lines
//! of a frame it keeps, and when a line of the frame continues a line of the previous frame.
struct FrontEndParams
{
    double minLength = 0;           //!< px; a line is kept from the larger of this and ...
    double minLengthRatio = 0.125;  //!< ... this times min(W, H)
    int maxLines = 60;              //!< the budget: the lines of highest rank (0: all)
    bool rankByLength = false;      //!< rank by length; else by frontEndResponses()
    int maxHamming = 30;            //!< a match's Hamming distance is below this (of 256 bits)
    double maxShift = 200;          //!< px; both endpoints move less than this
    double maxAngle = 0.1;          //!< rad; the direction turns less than this

    double minLengthIn(cv::Size imageSize) const
    {
        return std::max(minLength, minLengthRatio * std::min(imageSize.width, imageSize.height));
    }
};

inline double segmentLength(const cv::Vec4f& l)
{
    return std::hypot(l[2] - l[0], l[3] - l[1]);
}

//! computeLineResponses of each segment in whichever orientation has its brighter side on the
//! left: the same rank for every detector, whether it orients its lines as LSD does or not.
inline std::vector<float> frontEndResponses(const cv::Mat& gray, const std::vector<cv::Vec4f>& lines)
{
    std::vector<cv::Vec4f> flipped;
    for (const cv::Vec4f& l : lines)
        flipped.push_back(cv::Vec4f(l[2], l[3], l[0], l[1]));
    std::vector<float> responses, flippedResponses;
    cv::ximgproc::computeLineResponses(gray, lines, responses);
    cv::ximgproc::computeLineResponses(gray, flipped, flippedResponses);
    for (size_t i = 0; i < responses.size(); i++)
        responses[i] = std::max(responses[i], flippedResponses[i]);
    return responses;
}

//! The lines of at least the minimum length, as many as the budget, highest rank first.
inline std::vector<cv::Vec4f> frontEndLines(const cv::Mat& gray, const std::vector<cv::Vec4f>& lines,
                                            const FrontEndParams& params)
{
    const double minLength = params.minLengthIn(gray.size());
    std::vector<cv::Vec4f> longEnough;
    for (const cv::Vec4f& l : lines)
        if (segmentLength(l) >= minLength)
            longEnough.push_back(l);
    if (params.maxLines <= 0 || longEnough.empty())
        return longEnough;
    return bestLines(longEnough, params.rankByLength ? lengthResponses(longEnough, gray.size())
                                                     : frontEndResponses(gray, longEnough),
                     params.maxLines);
}

//! Whether segment b of a frame may continue segment a of the previous one: endpoint shifts and
//! the change of direction (directed, as KeyLine::angle) within the front end's gates.
inline bool withinFrontEndGates(const cv::Vec4f& a, const cv::Vec4f& b, const FrontEndParams& params)
{
    const double shift2 = params.maxShift * params.maxShift;
    const double ds = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
    const double de = (b[2] - a[2]) * (b[2] - a[2]) + (b[3] - a[3]) * (b[3] - a[3]);
    const double turn = std::atan2(b[3] - b[1], b[2] - b[0]) - std::atan2(a[3] - a[1], a[2] - a[0]);
    const double angle = std::abs(std::remainder(turn, 2 * CV_PI));
    return ds < shift2 && de < shift2 && angle < params.maxAngle;
}

//! The front end's matches of a frame's lines to the previous frame's (query: previous, train:
//! current, as LineTracks takes them): each current line's nearest previous line by LBD
//! (one way), kept within the gates; a previous line continues into one current line only, the
//! nearest (so that matches chain into tracks).
inline std::vector<cv::DMatch> matchFrontEnd(const DescribedLines& previous, const DescribedLines& current,
                                             const FrontEndParams& params)
{
    std::vector<cv::DMatch> kept;
    if (previous.descriptors.empty() || current.descriptors.empty())
        return kept;
    std::vector<cv::DMatch> nearest;
    cv::line_descriptor::BinaryDescriptorMatcher::createBinaryDescriptorMatcher()->match(current.descriptors,
                                                                                         previous.descriptors, nearest);
    std::vector<int> best(previous.lines.size(), -1);  // per previous line, its match in kept
    for (const cv::DMatch& m : nearest)
    {
        if (m.distance >= params.maxHamming ||
            !withinFrontEndGates(previous.lines[m.trainIdx], current.lines[m.queryIdx], params))
            continue;
        const cv::DMatch link(m.trainIdx, m.queryIdx, m.distance);
        int& slot = best[m.trainIdx];
        if (slot < 0)
        {
            slot = (int)kept.size();
            kept.push_back(link);
        }
        else if (link.distance < kept[slot].distance)
            kept[slot] = link;
    }
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
