// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The line detectors the samples compare, behind one small interface. OpenCV's detectors are
// used as they are; only their construction is here.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_LINE_METHODS_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_LINE_METHODS_HPP

#include <opencv2/core/utility.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

struct LineMethod
{
    std::string name;
    //! Detects on a gray image; consecutive calls may form a sequence.
    std::function<void(const cv::Mat&, std::vector<cv::Vec4f>&)> detect;
    //! Starts a new sequence (no-op for detectors without sequence state).
    std::function<void()> reset;
    //! The LSDAdvance detector behind the method, for its stage outputs; empty for other detectors.
    cv::Ptr<cv::ximgproc::LSDAdvance> lsdAdvance;
};

//! Median of the values (the upper one of the two middle values for an even count); 0 for none.
inline double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

//! Median time in ms of `repeats` detections on one image; lines of the last one. With
//! independent, the sequence is reset before each detection (outside the timed call).
inline double timedDetect(const LineMethod& method, const cv::Mat& gray, int repeats,
                          std::vector<cv::Vec4f>& lines, bool independent)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; r++)
    {
        if (independent)
            method.reset();
        cv::TickMeter tm;
        tm.start();
        method.detect(gray, lines);
        tm.stop();
        ms.push_back(tm.getTimeMilli());
    }
    return median(ms);
}

//! Names accepted by makeLineMethod, for help texts.
inline const char* lineMethodNames()
{
    return "lsd, fld, fld_merge, edlines, plvins, lsdadvance, lsdadvance_paper, lsdadvance_filter, lsdadvance_base, lsdadvance_merge, "
           "lsdadvance_interframe, lsdadvance_continuous, lsdadvance_tracking, lsdadvance_opencv_lsd, lsdadvance_fld, "
           "lsdadvance_edlines, lsdadvance_edlines_tuned";
}

inline LineMethod lineMethodOf(const std::string& name,
                               const std::function<void(const cv::Mat&, std::vector<cv::Vec4f>&)>& detect)
{
    return LineMethod{ name, detect, [] {}, cv::Ptr<cv::ximgproc::LSDAdvance>() };
}

//! An LSDAdvance detector as a method; its sequence state is reset by reset().
inline LineMethod lineMethodOf(const std::string& name, const cv::Ptr<cv::ximgproc::LSDAdvance>& detector)
{
    return LineMethod{ name,
                       [detector](const cv::Mat& gray, std::vector<cv::Vec4f>& lines) { detector->detect(gray, lines); },
                       [detector] { detector->reset(); }, detector };
}

//! PL-VINS's LSD set-up: half scale, looser density, lines >= 1/8 of the smaller image side.
inline void detectPlVins(const cv::Ptr<cv::LineSegmentDetector>& lsd, const cv::Mat& gray,
                         std::vector<cv::Vec4f>& lines)
{
    std::vector<cv::Vec4f> all;
    lsd->detect(gray, all);
    const double minLength = 0.125 * std::min(gray.cols, gray.rows);
    lines.clear();
    for (const cv::Vec4f& l : all)
        if (std::hypot(l[2] - l[0], l[3] - l[1]) >= minLength)
            lines.push_back(l);
}

//! One of lineMethodNames(); params, when given, configures LSDAdvance. Throws on an unknown name.
inline LineMethod makeLineMethod(const std::string& name, const cv::FileNode& params = cv::FileNode())
{
    using namespace cv;
    if (name == "lsd")
    {
        Ptr<LineSegmentDetector> lsd = createLineSegmentDetector();
        return lineMethodOf("LSD", [lsd](const Mat& g, std::vector<Vec4f>& l) { lsd->detect(g, l); });
    }
    if (name == "fld" || name == "fld_merge")
    {
        const bool merge = name == "fld_merge";
        Ptr<ximgproc::FastLineDetector> fld = ximgproc::createFastLineDetector(10, 1.414213562f, 50, 50, 3, merge);
        return lineMethodOf(merge ? "FLD+merge" : "FLD", [fld](const Mat& g, std::vector<Vec4f>& l) { fld->detect(g, l); });
    }
    if (name == "edlines")
    {
        Ptr<ximgproc::EdgeDrawing> ed = ximgproc::createEdgeDrawing();
        return lineMethodOf("EDLines", [ed](const Mat& g, std::vector<Vec4f>& l) {
            ed->detectEdges(g);
            ed->detectLines(l);
        });
    }
    if (name == "plvins")
    {
        Ptr<LineSegmentDetector> lsd = createLineSegmentDetector(LSD_REFINE_STD, 0.5, 0.6, 2.0, 22.5, 0, 0.6, 1024);
        return lineMethodOf("PL-VINS LSD", [lsd](const Mat& g, std::vector<Vec4f>& l) { detectPlVins(lsd, g, l); });
    }
    if (name == "lsdadvance")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        // Algorithm::save() nests the parameters under the algorithm's name; write() does not.
        const FileNode named = params.empty() ? FileNode() : params[detector->getDefaultName()];
        if (!params.empty())
            detector->read(named.empty() ? params : named);
        return lineMethodOf("LSDAdvance", detector);
    }
    if (!params.empty())
        CV_Error_(Error::StsBadArg, ("parameters apply to the lsdadvance method only, not to '%s'", name.c_str()));
    if (name == "lsdadvance_paper")
        return lineMethodOf("LSDAdvance (paper)", ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_PAPER));
    if (name == "lsdadvance_filter")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_PAPER);
        detector->setMergeStrategy(ximgproc::LSDAdvance::MERGE_NONE);
        return lineMethodOf("LSDAdvance (paper, length filter only)", detector);
    }
    // The length filter's modes, everything else at the defaults (stateless, alpha = 1).
    if (name == "lsdadvance_interframe" || name == "lsdadvance_continuous" || name == "lsdadvance_tracking" ||
        name == "lsdadvance_merge")
    {
        struct Mode { const char* method; int mode; const char* title; };
        static const Mode modes[] = {
            { "lsdadvance_interframe", ximgproc::LSDAdvance::LENGTH_FILTER_INTERFRAME, "LSDAdvance, paper's inter-frame rule" },
            { "lsdadvance_continuous", ximgproc::LSDAdvance::LENGTH_FILTER_INTERFRAME_CONTINUOUS,
              "LSDAdvance, continuous inter-frame rule" },
            { "lsdadvance_tracking", ximgproc::LSDAdvance::LENGTH_FILTER_COUNT_TRACKING, "LSDAdvance, count tracking (sequence preset)" },
            { "lsdadvance_merge", ximgproc::LSDAdvance::LENGTH_FILTER_NONE, "LSDAdvance, merging only (no length filter)" },
        };
        for (const Mode& m : modes)
            if (name == m.method)
            {
                Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
                detector->setLengthFilterMode(m.mode);
                return lineMethodOf(m.title, detector);
            }
    }
    // The default stages on other bases: OpenCV's default LSD set-up (refinement, scale 0.8),
    // FastLineDetector and EDLines with their defaults.
    if (name == "lsdadvance_opencv_lsd")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setLSDParams(ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_PAPER)->getLSDParams());
        return lineMethodOf("LSDAdvance on OpenCV's default LSD", detector);
    }
    if (name == "lsdadvance_fld" || name == "lsdadvance_edlines")
    {
        const bool fld = name == "lsdadvance_fld";
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setBaseDetector(fld ? ximgproc::LSDAdvance::BASE_FLD : ximgproc::LSDAdvance::BASE_EDLINES);
        return lineMethodOf(fld ? "LSDAdvance on FLD" : "LSDAdvance on EDLines", detector);
    }
    // EDLines without smoothing and a higher gradient threshold, the paper's length threshold and
    // a 2 px gate: the best of the sweep on the even YorkUrban images (doc/performance.md).
    if (name == "lsdadvance_edlines_tuned")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setBaseDetector(ximgproc::LSDAdvance::BASE_EDLINES);
        ximgproc::EdgeDrawing::Params ed = detector->getEDLinesParams();
        ed.Sigma = 0.5f;
        ed.GradientThresholdValue = 30;
        detector->setEDLinesParams(ed);
        detector->setLengthThresholdRule(ximgproc::LSDAdvance::LENGTH_THRESHOLD_PAPER);
        detector->setMaxPerpendicularOffset(2.0);
        return lineMethodOf("LSDAdvance on EDLines, tuned", detector);
    }
    if (name == "lsdadvance_base")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setLengthFilterMode(ximgproc::LSDAdvance::LENGTH_FILTER_NONE);
        detector->setMergeStrategy(ximgproc::LSDAdvance::MERGE_NONE);
        return lineMethodOf("LSDAdvance's base LSD alone", detector);
    }
    CV_Error_(Error::StsBadArg, ("unknown method '%s'; known: %s", name.c_str(), lineMethodNames()));
}

#endif
