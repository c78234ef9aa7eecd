// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The line detectors that the benchmark apps and the perf suite compare, by name. Every
// LSDAdvance variant is a parameters file of the methods folder, methods/<name>.yml: a preset, the
// parameters that differ from it (keys of LSDAdvance::write()), and the title the tables print. The other detectors, OpenCV's as
// they are and the optional peer ELSED, are constructed here.

#ifndef OPENCV_LSD_ADVANCE_APPS_LINE_METHODS_HPP
#define OPENCV_LSD_ADVANCE_APPS_LINE_METHODS_HPP

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/lsd_advance.hpp>
#include <opencv2/ximgproc.hpp>
#include "../../src/opencv_lsd.hpp"  // OpenCV's LSD, in imgproc or in ximgproc

#ifdef LSD_ADVANCE_HAVE_ELSED
#include "ELSED.h"   // the optional peer, from its own folder (cmake -DLSD_ADVANCE_ELSED_DIR=<dir>)
#endif

#include <algorithm>
#include <climits>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#ifndef LSD_ADVANCE_METHODS_DIR
#error "LSD_ADVANCE_METHODS_DIR must name the folder of the LSDAdvance method files (set by the build)"
#endif

struct LineMethod
{
    std::string name;  //!< the title of the tables
    //! Detects on a gray image; consecutive calls may form a sequence.
    std::function<void(const cv::Mat&, std::vector<cv::Vec4f>&)> detect;
    //! Starts a new sequence (no-op for detectors without sequence state).
    std::function<void()> reset;
    //! The LSDAdvance detector behind the method, for its stage outputs; empty for other detectors.
    cv::Ptr<cv::ximgproc::LSDAdvance> lsdAdvance;
};

//! The folder of the LSDAdvance method files.
inline std::string lineMethodsFolder()
{
    return LSD_ADVANCE_METHODS_DIR;
}

//! The methods that are not LSDAdvance variants.
inline std::vector<std::string> otherLineMethodNames()
{
    return { "lsd", "fld", "fld_merge", "fld_half", "edlines", "plvins"
#ifdef LSD_ADVANCE_HAVE_ELSED
             , "elsed"
#endif
    };
}

//! Every method: the others, then the method files in name order.
inline std::vector<std::string> lineMethodNames()
{
    std::vector<std::string> names = otherLineMethodNames();
    std::vector<cv::String> files;
    cv::glob(cv::utils::fs::join(lineMethodsFolder(), "*.yml"), files);
    CV_Assert(!files.empty());
    for (const cv::String& file : files)
    {
        const size_t slash = file.find_last_of("/\\") + 1;
        names.push_back(file.substr(slash, file.size() - slash - 4));
    }
    return names;
}

//! lineMethodNames() as one line, for messages and help texts.
inline std::string lineMethodList()
{
    std::string list;
    for (const std::string& name : lineMethodNames())
        list += (list.empty() ? "" : ", ") + name;
    return list;
}

inline LineMethod lineMethodOf(const std::string& name,
                               const std::function<void(const cv::Mat&, std::vector<cv::Vec4f>&)>& detect)
{
    return LineMethod{ name, detect, [] {}, cv::Ptr<cv::ximgproc::LSDAdvance>() };
}

//! PL-VINS's LSD set-up: half scale, looser density, lines >= 1/8 of the smaller image side.
//! (PL-VINS also sets log_eps 1: OpenCV's LSD reads it with LSD_REFINE_ADV only.)
inline LineMethod plVinsMethod()
{
    using namespace cv::ximgproc::lsda;
    const cv::Ptr<OpenCVLineSegmentDetector> lsd =
        createOpenCVLineSegmentDetector(kLsdRefineStd, 0.5, 0.6, 2.0, 22.5, 0, 0.6, 1024);
    return lineMethodOf("PL-VINS LSD", [lsd](const cv::Mat& gray, std::vector<cv::Vec4f>& lines) {
        std::vector<cv::Vec4f> all;
        lsd->detect(gray, all);
        const double minLength = 0.125 * std::min(gray.cols, gray.rows);
        lines.clear();
        for (const cv::Vec4f& l : all)
            if (std::hypot(l[2] - l[0], l[3] - l[1]) >= minLength)
                lines.push_back(l);
    });
}

//! FLD with its defaults on the image resized to half its size (cv::INTER_AREA), as front ends
//! run it; the segments in the coordinates of the full image (pixel centres: x = 2 x' + 0.5).
inline LineMethod fldHalfMethod()
{
    const cv::Ptr<cv::ximgproc::FastLineDetector> fld = cv::ximgproc::createFastLineDetector();
    return lineMethodOf("FLD, half size", [fld](const cv::Mat& gray, std::vector<cv::Vec4f>& lines) {
        cv::Mat half;
        cv::resize(gray, half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
        fld->detect(half, lines);
        for (cv::Vec4f& l : lines)
            for (int i = 0; i < 4; i++)
                l[i] = 2 * l[i] + 0.5f;
    });
}

//! The presets a method file starts from, by the names of LSDAdvance::Preset.
inline std::vector<std::pair<std::string, cv::ximgproc::LSDAdvance::Preset> > lsdAdvancePresets()
{
    using cv::ximgproc::LSDAdvance;
    return { { "PRESET_MOST_ACCURATE", LSDAdvance::PRESET_MOST_ACCURATE }, { "PRESET_FASTEST", LSDAdvance::PRESET_FASTEST },
             { "PRESET_PAPER", LSDAdvance::PRESET_PAPER }, { "PRESET_SEQUENCE", LSDAdvance::PRESET_SEQUENCE },
             { "PRESET_FRONT_END", LSDAdvance::PRESET_FRONT_END } };
}

//! What LSDAdvance::write() writes of a detector (the full set of its parameters), to be read back.
inline cv::FileStorage writtenParameters(const cv::ximgproc::LSDAdvance& detector)
{
    cv::FileStorage out(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    detector.write(out);
    return cv::FileStorage(out.releaseAndGetString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
}

//! The keys of `full` whose values differ from those of `base`, each with its value, written to
//! `out` when it is open (the maps of the base detectors' parameters only with a key that differs);
//! returns how many differ.
inline int writeDifferences(const cv::FileNode& full, const cv::FileNode& base, cv::FileStorage* out)
{
    int count = 0;
    for (cv::FileNodeIterator it = full.begin(); it != full.end(); ++it)
    {
        const cv::FileNode value = *it, other = base[value.name()];
        if (value.isMap())
        {
            const int inside = writeDifferences(value, other, nullptr);
            if (inside > 0 && out)
            {
                *out << value.name() << "{";
                writeDifferences(value, other, out);
                *out << "}";
            }
            count += inside;
            continue;
        }
        const bool same = value.isString() ? other.isString() && (std::string)value == (std::string)other
                          : value.isInt()  ? other.isInt() && (int)value == (int)other
                                           : other.isReal() && (double)value == (double)other;
        if (same)
            continue;
        count++;
        if (!out)
            continue;
        if (value.isString())
            *out << value.name() << (std::string)value;
        else if (value.isInt())
            *out << value.name() << (int)value;
        else
            *out << value.name() << (double)value;
    }
    return count;
}

//! The detector of a preset, by its name in a file (`preset:`); empty for an unknown name.
inline cv::Ptr<cv::ximgproc::LSDAdvance> lsdAdvanceOfPreset(const cv::FileNode& name)
{
    for (const auto& preset : lsdAdvancePresets())
        if (name.isString() && preset.first == (std::string)name)
            return cv::ximgproc::createLSDAdvance(preset.second);
    return cv::Ptr<cv::ximgproc::LSDAdvance>();
}

//! The LSDAdvance variant of methods/<name>.yml: the file's preset, then the parameters it sets
//! (those that differ from the preset's). params, when given, are read on top of it: a method file
//! (its preset, then its parameters), what Algorithm::save() writes, or what write() writes.
inline LineMethod lsdAdvanceMethod(const std::string& name, const cv::FileNode& params)
{
    const std::vector<std::string> known = lineMethodNames();
    if (std::find(known.begin(), known.end(), name) == known.end())
        CV_Error_(cv::Error::StsBadArg, ("unknown method '%s'; known: %s", name.c_str(), lineMethodList().c_str()));
    const std::string path = cv::utils::fs::join(lineMethodsFolder(), name + ".yml");
    const cv::FileStorage file(path, cv::FileStorage::READ);
    const std::string title = file["title"].isString() ? (std::string)file["title"] : std::string();
    cv::Ptr<cv::ximgproc::LSDAdvance> detector = lsdAdvanceOfPreset(file["preset"]);
    if (!detector || title.empty())
        CV_Error_(cv::Error::StsParseError, ("the method file %s needs a 'preset' (a name of LSDAdvance::Preset) and a "
                                             "'title'", path.c_str()));
    const cv::FileNode variant = file[detector->getDefaultName()];
    if (!variant.empty())
        detector->read(variant);
    if (!params.empty())
    {
        if (!params["preset"].empty() && !(detector = lsdAdvanceOfPreset(params["preset"])))
            CV_Error(cv::Error::StsParseError, "the parameters' 'preset' is not a name of LSDAdvance::Preset");
        // Algorithm::save() and a method file nest the parameters under the algorithm's name; write() does not.
        const cv::FileNode named = params[detector->getDefaultName()];
        if (!named.empty() || params["preset"].empty())
            detector->read(named.empty() ? params : named);
    }
    return LineMethod{ title,
                       [detector](const cv::Mat& gray, std::vector<cv::Vec4f>& lines) { detector->detect(gray, lines); },
                       [detector] { detector->reset(); }, detector };
}

//! Writes an LSDAdvance method as a method file: the preset it differs least from, the parameters
//! that differ from it (LSDAdvance::write()'s keys), then the title. A method file is canonical
//! when this writes it again unchanged; adding a parameter changes none (its value is the presets').
inline void writeLineMethod(const std::string& path, const LineMethod& method)
{
    CV_Assert(method.lsdAdvance);
    const cv::FileStorage full = writtenParameters(*method.lsdAdvance);
    std::string nearest;
    cv::FileStorage nearestParameters;
    int fewest = INT_MAX;
    for (const auto& preset : lsdAdvancePresets())
    {
        cv::FileStorage presetParameters = writtenParameters(*cv::ximgproc::createLSDAdvance(preset.second));
        const int count = writeDifferences(full.root(), presetParameters.root(), nullptr);
        if (count < fewest)
        {
            fewest = count;
            nearest = preset.first;
            nearestParameters = presetParameters;
        }
    }
    cv::FileStorage file(path, cv::FileStorage::WRITE);
    if (!file.isOpened())
        CV_Error_(cv::Error::StsError, ("cannot write %s", path.c_str()));
    file << "preset" << nearest;
    if (fewest > 0)
    {
        file << method.lsdAdvance->getDefaultName() << "{";
        writeDifferences(full.root(), nearestParameters.root(), &file);
        file << "}";
    }
    file << "title" << method.name;
}

//! One of lineMethodNames(); params, when given, configure the method "lsdadvance" (and only it).
//! Throws a cv::Exception that lists the known names for an unknown one.
inline LineMethod makeLineMethod(const std::string& name, const cv::FileNode& params = cv::FileNode())
{
    using namespace cv;
    if (!params.empty() && name != "lsdadvance")
        CV_Error_(Error::StsBadArg, ("parameters apply to the lsdadvance method only, not to '%s'", name.c_str()));
    if (name == "lsd")
    {
        const Ptr<ximgproc::lsda::OpenCVLineSegmentDetector> lsd = ximgproc::lsda::createOpenCVLineSegmentDetector();
        return lineMethodOf("LSD", [lsd](const Mat& g, std::vector<Vec4f>& l) { lsd->detect(g, l); });
    }
    if (name == "fld" || name == "fld_merge")
    {
        const bool merge = name == "fld_merge";
        const Ptr<ximgproc::FastLineDetector> fld = ximgproc::createFastLineDetector(10, 1.414213562f, 50, 50, 3, merge);
        return lineMethodOf(merge ? "FLD+merge" : "FLD", [fld](const Mat& g, std::vector<Vec4f>& l) { fld->detect(g, l); });
    }
    if (name == "edlines")
    {
        const Ptr<ximgproc::EdgeDrawing> ed = ximgproc::createEdgeDrawing();
        return lineMethodOf("EDLines", [ed](const Mat& g, std::vector<Vec4f>& l) {
            ed->detectEdges(g);
            ed->detectLines(l);
        });
    }
    if (name == "plvins")
        return plVinsMethod();
    if (name == "fld_half")
        return fldHalfMethod();
#ifdef LSD_ADVANCE_HAVE_ELSED
    if (name == "elsed")
    {
        // ELSED (Suarez et al., Pattern Recognition 2022) with its defaults.
        const std::shared_ptr<upm::ELSED> elsed = std::make_shared<upm::ELSED>();
        return lineMethodOf("ELSED", [elsed](const Mat& g, std::vector<Vec4f>& l) { l = elsed->detect(g); });
    }
#else
    if (name == "elsed")
        CV_Error(Error::StsBadArg, "method 'elsed' needs the ELSED peer: configure the build with "
                                   "-DLSD_ADVANCE_ELSED_DIR=<ELSED source folder>");
#endif
    return lsdAdvanceMethod(name, params);
}

//! Median of the values (the upper one of the two middle values for an even count); 0 for none.
inline double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

#endif
