// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What follows from the parameter tables of parameters.hpp: the defaults, the validation, and
// the persistence (write/read, with names for enumerated values and warnings on unknown keys).

#include "precomp.hpp"
#include "parameters.hpp"
#include "opencv2/core/utils/logger.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <type_traits>

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

Range Range::real(double lo, Bound loBound, double hi, Bound hiBound, const char* unit)
{
    Range r;
    r.kind = REAL;
    r.lo = lo;
    r.hi = hi;
    r.loBound = loBound;
    r.hiBound = hiBound;
    r.unit = unit;
    return r;
}

Range Range::enumOf(const char* const* names, int count)
{
    Range r;
    r.kind = ENUM;
    r.hi = count - 1;
    r.names = names;
    r.count = count;
    return r;
}

Range Range::flag()
{
    Range r;
    r.kind = FLAG;
    r.hi = 1;
    return r;
}

Range Range::oneOf(const int* values, int count)
{
    Range r;
    r.kind = LIST;
    r.values = values;
    r.count = count;
    return r;
}

Range Range::orValue(double value, const char* meaning) const
{
    Range r = *this;
    r.hasExtra = true;
    r.extra = value;
    r.extraMeaning = meaning;
    return r;
}

bool Range::accepts(double v) const
{
    if (hasExtra && v == extra)
        return true;
    switch (kind)
    {
    case ENUM:
    case FLAG:
        return v >= lo && v <= hi && v == std::floor(v);
    case LIST:
        return std::find(values, values + count, v) != values + count;
    default:
        return std::isfinite(v) && (loBound == OPEN ? v > lo : v >= lo) && (hiBound == OPEN ? v < hi : v <= hi);
    }
}

std::string Range::describe() const
{
    std::string text;
    switch (kind)
    {
    case ENUM:
        text = "one of ";
        for (int k = 0; k < count; k++)
            text += format("%s%s (%d)", k == 0 ? "" : ", ", names[k], k);
        break;
    case FLAG:
        text = "0 (false) or 1 (true)";
        break;
    case LIST:
        for (int k = 0; k < count; k++)
            text += format("%s%d", k == 0 ? "" : (k + 1 == count ? " or " : ", "), values[k]);
        break;
    default:
        text = format("a finite number in %c%g, %g%c%s", loBound == OPEN ? '(' : '[', lo, hi,
                      hiBound == OPEN ? ')' : ']', unit);
    }
    if (hasExtra)
        text += format(", or %g (%s)", extra, extraMeaning);
    return text;
}

namespace {

template <class S, class T, T S::*member>
double getMember(const S& s)
{
    return (double)(s.*member);
}

template <class S, class T, T S::*member>
void setMember(S& s, double value)
{
    s.*member = (T)value;
}

// A row of a table as a Field of struct S.
#define LSDA_FIELD_OF(S, type, field, range, legacyKey)                                                           \
    Field<S>{ #field, legacyKey, range, !std::is_floating_point<type>::value, &getMember<S, type, &S::field>,      \
              &setMember<S, type, &S::field> },

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

#define LSDA_OWN_FIELD(type, field, Accessor, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::Params, type, field, range, legacyKey)

const std::vector<Field<LSDAdvance::Params> >& fieldsOf(const LSDAdvance::Params*)
{
    static const std::vector<Field<LSDAdvance::Params> > fields = { LSDA_PARAMS(LSDA_OWN_FIELD) };
    return fields;
}

#define LSDA_LSD_FIELD(type, field, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::LSDParams, type, field, range, legacyKey)
const std::vector<Field<LSDAdvance::LSDParams> >& fieldsOf(const LSDAdvance::LSDParams*)
{
    static const std::vector<Field<LSDAdvance::LSDParams> > fields = { LSDA_LSD_PARAMS(LSDA_LSD_FIELD) };
    return fields;
}

#define LSDA_FLD_FIELD(type, field, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::FLDParams, type, field, range, legacyKey)
const std::vector<Field<LSDAdvance::FLDParams> >& fieldsOf(const LSDAdvance::FLDParams*)
{
    static const std::vector<Field<LSDAdvance::FLDParams> > fields = { LSDA_FLD_PARAMS(LSDA_FLD_FIELD) };
    return fields;
}

#define LSDA_EDLINES_FIELD(type, field, range, legacyKey) \
    LSDA_FIELD_OF(EdgeDrawing::Params, type, field, range, legacyKey)
const std::vector<Field<EdgeDrawing::Params> >& fieldsOf(const EdgeDrawing::Params*)
{
    static const std::vector<Field<EdgeDrawing::Params> > fields = { LSDA_EDLINES_PARAMS(LSDA_EDLINES_FIELD) };
    return fields;
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
