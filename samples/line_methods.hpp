// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The line detectors the samples compare, behind one small interface. OpenCV's detectors are
// used as they are; only their construction is here.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_LINE_METHODS_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_LINE_METHODS_HPP

#include "command_line.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

#ifdef LSD_ADVANCE_HAVE_ELSED
#include "ELSED.h"   // the optional peer, from its own folder (cmake -DLSD_ADVANCE_ELSED_DIR=<dir>)
#endif

#include <algorithm>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>
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
    return "lsd, fld, fld_merge, edlines, plvins, lsdadvance, lsdadvance_paper, lsdadvance_sequence, lsdadvance_filter, "
           "lsdadvance_base, lsdadvance_merge, lsdadvance_interframe, lsdadvance_continuous, lsdadvance_tracking, "
           "lsdadvance_opencv_full, lsdadvance_opencv_lsd, lsdadvance_fastest, lsdadvance_fld, lsdadvance_edlines, "
           "lsdadvance_edlines_tuned"
#ifdef LSD_ADVANCE_HAVE_ELSED
           ", elsed"
#endif
        ;
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

//! The LSDAdvance parameters file of --params, open for reading; closed for an empty path.
//! Throws std::runtime_error when it is missing, empty or not valid YAML, XML or JSON (with
//! file, line and reason for a syntax error).
inline cv::FileStorage openParamsFile(const std::string& path)
{
    cv::FileStorage file;
    if (path.empty())
        return file;
    const std::string accepted = " (YAML, XML or JSON written by LSDAdvance::save() or write())";
    // Checked here: FileStorage would log an error of its own before returning false.
    if (!cv::utils::fs::exists(path) || cv::utils::fs::isDirectory(path))
        throw std::runtime_error("no such parameters file: " + path + accepted);
    if (std::ifstream(path.c_str()).peek() == std::ifstream::traits_type::eof())
        throw std::runtime_error("the parameters file " + path + " is empty" + accepted);
    try
    {
        if (file.open(path, cv::FileStorage::READ))
            return file;
    }
    catch (const cv::Exception& e)
    {
        std::string message;
        if (parseErrorMessage(e, message))
            throw std::runtime_error(message);
        throw std::runtime_error("cannot read the parameters file " + path + ": " + e.err + accepted);
    }
    throw std::runtime_error("cannot read the parameters file " + path + accepted);
}

//! One of lineMethodNames(); params, when given, configures LSDAdvance. Throws on an unknown name.
inline LineMethod makeLineMethod(const std::string& name, const cv::FileNode& params = cv::FileNode())
{
    using namespace cv;
    if (!params.empty() && name != "lsdadvance")
        CV_Error_(Error::StsBadArg, ("parameters apply to the lsdadvance method only, not to '%s'", name.c_str()));
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
    if (name == "elsed")
    {
#ifdef LSD_ADVANCE_HAVE_ELSED
        // ELSED (Suarez et al., Pattern Recognition 2022) with its defaults.
        std::shared_ptr<upm::ELSED> elsed = std::make_shared<upm::ELSED>();
        return lineMethodOf("ELSED", [elsed](const Mat& g, std::vector<Vec4f>& l) { l = elsed->detect(g); });
#else
        CV_Error(Error::StsBadArg, "method 'elsed' needs the ELSED peer: configure the build with "
                                   "-DLSD_ADVANCE_ELSED_DIR=<ELSED source folder>");
#endif
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
    if (name == "lsdadvance_paper")
        return lineMethodOf("LSDAdvance (paper)", ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_PAPER));
    if (name == "lsdadvance_sequence")
        return lineMethodOf("LSDAdvance (sequence preset)", ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_SEQUENCE));
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
            { "lsdadvance_tracking", ximgproc::LSDAdvance::LENGTH_FILTER_COUNT_TRACKING, "LSDAdvance, count tracking" },
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
    // The default stages on other bases: OpenCV's LSD with the default base's set-up (full
    // resolution, no refinement) and with its own default set-up (refinement, scale 0.8),
    // FastLineDetector and EDLines with their defaults.
    if (name == "lsdadvance_opencv_full")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setBaseDetector(ximgproc::LSDAdvance::BASE_LSD);
        return lineMethodOf("LSDAdvance on OpenCV's LSD (same set-up)", detector);
    }
    if (name == "lsdadvance_opencv_lsd")
    {
        Ptr<ximgproc::LSDAdvance> detector = ximgproc::createLSDAdvance();
        detector->setBaseDetector(ximgproc::LSDAdvance::BASE_LSD);
        detector->setLSDParams(ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_PAPER)->getLSDParams());
        return lineMethodOf("LSDAdvance on OpenCV's default LSD", detector);
    }
    if (name == "lsdadvance_fastest")
        return lineMethodOf("LSDAdvance, fastest preset", ximgproc::createLSDAdvance(ximgproc::LSDAdvance::PRESET_FASTEST));
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
