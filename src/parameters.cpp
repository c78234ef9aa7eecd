// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What follows from the parameter tables of parameters.hpp: the defaults, the presets, the
// validation, and the persistence (write/read, with names for enumerated values and warnings on
// unknown keys).

#include "precomp.hpp"
#include "parameters.hpp"
#include "opencv2/core/utils/logger.hpp"

#include <cctype>

namespace cv {
namespace ximgproc {

#define LSDA_DEFAULT(type, field, Accessor, value, range, legacyKey) field = value;
LSDAdvance::Params::Params()
{
    LSDA_PARAMS(LSDA_DEFAULT)
}
#undef LSDA_DEFAULT

#define LSDA_DEFAULT(type, field, value, range, legacyKey) field = value;
LSDAdvance::LSDParams::LSDParams()
{
    LSDA_LSD_PARAMS(LSDA_DEFAULT)
}

LSDAdvance::FLDParams::FLDParams()
{
    LSDA_FLD_PARAMS(LSDA_DEFAULT)
}
#undef LSDA_DEFAULT

namespace lsda {

namespace {

// Enumerated values are written by name.
template <class S>
void writeFields(FileStorage& fs, const S& s)
{
    for (const Field<S>& f : fieldsOf<S>())
    {
        const double v = f.get(s);
        if (f.range.kind == Range::ENUM && f.range.accepts(v))
            fs << f.name << f.range.names[(int)v];
        else if (f.integral)
            fs << f.name << (int)v;
        else
            fs << f.name << v;
    }
}

// The value of a field's node: a number, or for an enumerated field one of its names. Throws on
// anything else, naming the field (prefix: where it is) and what it accepts.
template <class S>
double valueOf(const FileNode& node, const Field<S>& f, const std::string& prefix)
{
    if (node.isString() && f.range.kind == Range::ENUM)
    {
        const std::string name = (std::string)node;
        for (int k = 0; k < f.range.count; k++)
            if (name == f.range.names[k])
                return k;
        CV_Error_(Error::StsOutOfRange, ("LSDAdvance::read: %s%s must be %s, got '%s'", prefix.c_str(), f.name,
                                         f.range.describe().c_str(), name.c_str()));
    }
    const bool number = node.isInt() || (!f.integral && node.isReal());
    if (!number)
        CV_Error_(Error::StsParseError, ("LSDAdvance::read: %s%s must be %s", prefix.c_str(), f.name,
                                         f.integral && f.range.kind != Range::ENUM
                                             ? "an integer"
                                             : (f.integral ? "one of the names or numbers below" : "a number")));
    return node.isInt() ? (double)(int)node : (double)node;
}

// Levenshtein distance, case-insensitive.
size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); j++)
        row[j] = j;
    for (size_t i = 1; i <= a.size(); i++)
    {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); j++)
        {
            const size_t up = row[j];
            const bool same = std::tolower((unsigned char)a[i - 1]) == std::tolower((unsigned char)b[j - 1]);
            row[j] = std::min(std::min(row[j] + 1, row[j - 1] + 1), diagonal + (same ? 0 : 1));
            diagonal = up;
        }
    }
    return row[b.size()];
}

// Warns about each key of node that is not one of known (and, at the top, not an older key).
void warnAboutUnknownKeys(const FileNode& node, const std::vector<std::string>& known,
                          const std::vector<std::string>& alsoAccepted, const std::string& prefix)
{
    for (const FileNode& child : node)
    {
        const std::string key = child.name();
        if (std::find(known.begin(), known.end(), key) != known.end() ||
            std::find(alsoAccepted.begin(), alsoAccepted.end(), key) != alsoAccepted.end())
            continue;
        const std::string* closest = &known.front();
        for (const std::string& k : known)
            if (editDistance(key, k) < editDistance(key, *closest))
                closest = &k;
        CV_LOG_WARNING(NULL, "LSDAdvance::read: unknown key '" << prefix << key << "' ignored; the closest known key is '"
                                                              << prefix << *closest << "'");
    }
}

template <class S>
std::vector<std::string> namesOf()
{
    std::vector<std::string> names;
    for (const Field<S>& f : fieldsOf<S>())
        names.push_back(f.name);
    return names;
}

// Reads the fields of S from map (its keys are the field names) and, for files of version 4.6.0,
// from flat (keys legacyKey); a key of map wins over the same parameter's legacyKey.
template <class S>
void readFields(const FileNode& map, const FileNode& flat, const std::string& prefix, S& s)
{
    for (const Field<S>& f : fieldsOf<S>())
    {
        FileNode node = map.isMap() ? map[f.name] : FileNode();
        if (node.empty() && f.legacyKey && flat.isMap())
            node = flat[f.legacyKey];
        if (node.empty())
            continue;
        const double v = valueOf(node, f, prefix);
        if (!f.range.accepts(v))
            CV_Error_(Error::StsOutOfRange, ("LSDAdvance::read: %s%s must be %s, got %.10g", prefix.c_str(), f.name,
                                             f.range.describe().c_str(), v));
        f.set(s, v);
    }
    if (map.isMap() && !prefix.empty())
        warnAboutUnknownKeys(map, namesOf<S>(), {}, prefix);
}

template <class S>
void validateFields(const S& s, const char* prefix)
{
    for (const Field<S>& f : fieldsOf<S>())
    {
        const double v = f.get(s);
        if (!f.range.accepts(v))
            CV_Error_(Error::StsOutOfRange, ("LSDAdvance: %s%s must be %s, got %.10g", prefix, f.name,
                                             f.range.describe().c_str(), v));
    }
}

template <class S>
void addLegacyKeys(std::vector<std::string>& keys)
{
    for (const Field<S>& f : fieldsOf<S>())
        if (f.legacyKey)
            keys.push_back(f.legacyKey);
}

const char* const kLsdKey = "lsd";
const char* const kFldKey = "fld";
const char* const kEdLinesKey = "edLines";

} // namespace

// The most accurate configuration is the defaults; the fastest is the default base at OpenCV LSD's
// scale 0.8 (the fastest measured set-up whose F stays above LSD's, doc/performance.md).
Parameters presetParameters(int preset)
{
    Parameters p;
    switch (preset)
    {
    case LSDAdvance::PRESET_MOST_ACCURATE:
        break;
    case LSDAdvance::PRESET_FASTEST:
        p.lsd.scale = 0.8;
        break;
    case LSDAdvance::PRESET_PAPER:
        // OpenCV's LSD with its own set-up (createLineSegmentDetector's defaults), the paper's base.
        p.own.baseDetector = LSDAdvance::BASE_LSD;
        p.lsd.refine = lsda::kLsdRefineStd;
        p.lsd.scale = 0.8;
        p.own.lengthFilterMode = LSDAdvance::LENGTH_FILTER_INTERFRAME;
        p.own.lengthThresholdRule = LSDAdvance::LENGTH_THRESHOLD_PAPER;
        p.own.stageOrder = LSDAdvance::FILTER_THEN_MERGE;
        p.own.mergeStrategy = LSDAdvance::MERGE_BASELINES;
        p.own.proximityRatio = 0.1;
        break;
    case LSDAdvance::PRESET_SEQUENCE:
        p.own.lengthFilterMode = LSDAdvance::LENGTH_FILTER_COUNT_TRACKING;
        // A front end keeps its N best lines: short strong ones give it more correct LBD matches
        // at an equal line budget (doc/matching.md).
        p.own.keepStrongSegments = true;
        break;
    case LSDAdvance::PRESET_FRONT_END:
        // A point-line front end's budget (PL-VINS keeps about 60 lines), spread over the directions
        // in each quarter of the image: of the budget policies measured by the poses they give, the
        // one that did best on the even pairs of the stereo and multi-view sets (doc/pose.md). The
        // full-scale smoothing of every image too: without it, the 60 lines of the half-size
        // multi-view images lost most poses.
        p.own.maxLines = 60;
        p.own.lineOrder = LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS;
        p.own.gridCells = 2;
        p.lsd.fullScaleSmoothing = LSDAdvance::SMOOTH_EVERY_IMAGE;
        break;
    default:
        CV_Error_(Error::StsOutOfRange, ("createLSDAdvance: preset must be %s, got %d",
                                         Range::enumOf(kPresets).describe().c_str(), preset));
    }
    return p;
}

void validate(const LSDAdvance::Params& params) { validateFields(params, ""); }
void validate(const LSDAdvance::LSDParams& params) { validateFields(params, "LSDParams::"); }
void validate(const LSDAdvance::FLDParams& params) { validateFields(params, "FLDParams::"); }
void validate(const EdgeDrawing::Params& params) { validateFields(params, "EdgeDrawing::Params::"); }

void writeParameters(FileStorage& fs, const Parameters& p)
{
    writeFields(fs, p.own);
    fs << kLsdKey << "{";
    writeFields(fs, p.lsd);
    fs << "}" << kFldKey << "{";
    writeFields(fs, p.fld);
    fs << "}" << kEdLinesKey << "{";
    writeFields(fs, p.edLines);
    fs << "}";
}

void readParameters(const FileNode& node, Parameters& parameters)
{
    Parameters read = parameters;
    readFields(node, node, "", read.own);
    readFields(node[kLsdKey], node, std::string(kLsdKey) + ".", read.lsd);
    readFields(node[kFldKey], node, std::string(kFldKey) + ".", read.fld);
    readFields(node[kEdLinesKey], node, std::string(kEdLinesKey) + ".", read.edLines);
    if (node.isMap())
    {
        std::vector<std::string> known = namesOf<LSDAdvance::Params>(), older;
        known.insert(known.end(), { kLsdKey, kFldKey, kEdLinesKey, "format" });
        addLegacyKeys<LSDAdvance::Params>(older);
        addLegacyKeys<LSDAdvance::LSDParams>(older);
        addLegacyKeys<LSDAdvance::FLDParams>(older);
        addLegacyKeys<EdgeDrawing::Params>(older);
        warnAboutUnknownKeys(node, known, older, "");
    }
    parameters = read;
}

}}} // namespace cv::ximgproc::lsda
