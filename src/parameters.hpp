// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Every parameter of LSDAdvance is declared once: a row of one of the tables below, with its
// default and its range. From the rows follow the defaults (Params(), LSDParams(), FLDParams()),
// the validation of the setters, of setParams() and of read(), write() and read() themselves, the
// getters and setters of the implementation, and the tests' parameter lists (the fuzzer takes its
// list from write()). The public header declares each row's field and, for LSDAdvance::Params,
// its getter and setter: OpenCV's binding generator and Doxygen read that header as text, so these
// declarations cannot be generated; a test checks the defaults and ranges it documents against
// the rows. Header-only but for the defaults and persistence (parameters.cpp): the tests use the
// same rows without any of it being exported.

#ifndef OPENCV_LSD_ADVANCE_PARAMETERS_HPP
#define OPENCV_LSD_ADVANCE_PARAMETERS_HPP

#include "opencv2/lsd_advance/lsd_advance.hpp"
#include "opencv2/imgproc.hpp"
#include "opencv_lsd.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

// LSDAdvance::Params: X(type, field, Accessor, default, range, key in files of version 4.6.0 or nullptr)
#define LSDA_PARAMS(X)                                                                                             \
    X(int, baseDetector, BaseDetector, LSDAdvance::BASE_FAST_LSD, Range::enumOf(kBaseDetectors), nullptr)               \
    X(int, lengthFilterMode, LengthFilterMode, LSDAdvance::LENGTH_FILTER_ADAPTIVE,                                  \
      Range::enumOf(kLengthFilterModes), nullptr)                                                                    \
    X(int, lengthThresholdRule, LengthThresholdRule, LSDAdvance::LENGTH_THRESHOLD_CAPPED,                           \
      Range::enumOf(kLengthThresholdRules), "lengthThreshold")                                                       \
    X(double, lengthThresholdScale, LengthThresholdScale, 0.95, Range::real(0, OPEN, 10, CLOSED), nullptr)          \
    X(bool, keepStrongSegments, KeepStrongSegments, false, Range::flag(), nullptr)                                  \
    X(int, stageOrder, StageOrder, LSDAdvance::MERGE_THEN_FILTER, Range::enumOf(kStageOrders), nullptr)           \
    X(double, angleBinWidth, AngleBinWidth, 10.0, Range::real(1, CLOSED, 90, CLOSED, " deg"), nullptr)             \
    X(int, angleBinning, AngleBinning, LSDAdvance::ANGLE_BINS_NEIGHBOURS, Range::enumOf(kAngleBinnings), nullptr)  \
    X(double, endpointDistance, EndpointDistance, 15.0, Range::real(0.1, CLOSED, 200, CLOSED, " px"), nullptr)     \
    X(int, mergeStrategy, MergeStrategy, LSDAdvance::MERGE_LONGEST_FIRST, Range::enumOf(kMergeStrategies), nullptr) \
    X(double, baselineRatio, BaselineRatio, 0.8, Range::real(0, OPEN, 1, CLOSED), nullptr)                        \
    X(double, directionWeight, DirectionWeight, 0.4, Range::real(0, CLOSED, 1, CLOSED), nullptr)                  \
    X(double, proximityWeight, ProximityWeight, 0.35, Range::real(0, CLOSED, 1, CLOSED), nullptr)                 \
    X(double, lengthWeight, LengthWeight, 0.2, Range::real(0, CLOSED, 1, CLOSED), nullptr)                        \
    X(double, proximityRatio, ProximityRatio, 1.0, Range::real(0, OPEN, 10, CLOSED), nullptr)                     \
    X(double, mergeThreshold, MergeThreshold, 0.6, Range::real(0, CLOSED, 1, CLOSED), nullptr)                    \
    X(double, maxPerpendicularOffset, MaxPerpendicularOffset, 1.5, Range::real(0, CLOSED, 100, CLOSED, " px"), nullptr) \
    X(double, minLineLength, MinLineLength, 0.0, Range::real(0, CLOSED, 100000, CLOSED, " px"), nullptr)          \
    X(double, minLineLengthRatio, MinLineLengthRatio, 0.0, Range::real(0, CLOSED, 1, CLOSED), nullptr)            \
    X(int, maxLines, MaxLines, 0, Range::real(1, CLOSED, 100000, CLOSED).orValue(0, "all"), nullptr)              \
    X(int, lineOrder, LineOrder, LSDAdvance::LINE_ORDER_STRONGEST, Range::enumOf(kLineOrders), nullptr)           \
    X(int, directionBins, DirectionBins, 4, Range::real(2, CLOSED, 180, CLOSED), nullptr)                        \
    X(int, gridCells, GridCells, 1, Range::real(1, CLOSED, 32, CLOSED), nullptr)

// LSDAdvance::LSDParams: X(type, field, default, range, key in files of version 4.6.0 or nullptr)
#define LSDA_LSD_PARAMS(X)                                                                                         \
    X(int, refine, lsda::kLsdRefineNone, Range::enumOf(kLsdRefinements), "lsdRefine")                              \
    X(double, scale, 1.0, Range::real(0, OPEN, 1, CLOSED), "lsdScale")                                             \
    X(double, sigmaScale, 0.6, Range::real(0, OPEN, 100, CLOSED), "lsdSigmaScale")                                 \
    X(double, fullScaleSigma, 0.5, Range::real(0, CLOSED, 3, CLOSED, " px"), nullptr)                              \
    X(int, fullScaleSmoothing, LSDAdvance::SMOOTH_ALIASED_IMAGES, Range::enumOf(kFullScaleSmoothings), nullptr)     \
    X(double, quant, 2.0, Range::real(0, CLOSED, 255, CLOSED), "lsdQuant")                                         \
    X(double, angleTolerance, 22.5, Range::real(0, OPEN, 180, OPEN, " deg"), "lsdAngleTolerance")                  \
    X(double, logEps, 0.0, Range::real(-1000, CLOSED, 1000, CLOSED), "lsdLogEps")                                  \
    X(double, densityThreshold, 0.7, Range::real(0, CLOSED, 1, OPEN), "lsdDensityThreshold")                       \
    X(int, numBins, 1024, Range::real(1, CLOSED, 65536, CLOSED), "lsdNumBins")                                     \
    X(double, seedGradientRatio, 2.5, Range::real(1, CLOSED, 100, CLOSED), nullptr)                                 \
    X(int, seedAlignedNeighbours, 2, Range::real(0, CLOSED, 2, CLOSED), nullptr)                                   \
    X(int, tileHeight, 64, Range::real(16, CLOSED, 100000, CLOSED, " px").orValue(0, "no tiles"), nullptr)        \
    X(int, regionGrowth, LSDAdvance::GROWTH_PER_NEIGHBOURHOOD, Range::enumOf(kRegionGrowths), nullptr)

// LSDAdvance::FLDParams: X(type, field, default, range, key in files of version 4.6.0)
#define LSDA_FLD_PARAMS(X)                                                                                         \
    X(int, lengthThreshold, 10, Range::real(1, CLOSED, 100000, CLOSED, " px"), "fldLengthThreshold")               \
    X(double, distanceThreshold, 1.414213562, Range::real(0, OPEN, 100, CLOSED, " px"), "fldDistanceThreshold")    \
    X(double, cannyThreshold1, 50.0, Range::real(0, OPEN, 100000, CLOSED), "fldCannyThreshold1")                   \
    X(double, cannyThreshold2, 50.0, Range::real(0, OPEN, 100000, CLOSED), "fldCannyThreshold2")                   \
    X(int, cannyApertureSize, 3, Range::oneOf(kApertureSizes), "fldCannyApertureSize")                            \
    X(bool, doMerge, false, Range::flag(), "fldDoMerge")

// EdgeDrawing::Params, whose defaults are EdgeDrawing's: X(type, field, range, key in files of
// version 4.6.0 or nullptr)
#define LSDA_EDLINES_PARAMS(X)                                                                                     \
    X(bool, PFmode, Range::flag(), nullptr)                                                                        \
    X(int, EdgeDetectionOperator, Range::enumOf(kGradientOperators), "edGradientOperator")                        \
    X(int, GradientThresholdValue, Range::real(1, CLOSED, 10000, CLOSED), "edGradientThreshold")                   \
    X(int, AnchorThresholdValue, Range::real(0, CLOSED, 10000, CLOSED), "edAnchorThreshold")                       \
    X(int, ScanInterval, Range::real(1, CLOSED, 100, CLOSED), "edScanInterval")                                    \
    X(int, MinPathLength, Range::real(2, CLOSED, 100000, CLOSED, " px"), "edMinPathLength")                        \
    X(float, Sigma, Range::real(0, CLOSED, 100, CLOSED, " px"), "edSigma")                                          \
    X(bool, SumFlag, Range::flag(), nullptr)                                                                       \
    X(bool, NFAValidation, Range::flag(), "edNfaValidation")                                                       \
    X(int, MinLineLength, Range::real(9, CLOSED, 100000, CLOSED, " px").orValue(-1, "from the image size"),        \
      "edMinLineLength")                                                                                           \
    X(double, MaxDistanceBetweenTwoLines, Range::real(0, OPEN, 1000, CLOSED, " px"), "edMaxDistanceBetweenTwoLines") \
    X(double, LineFitErrorThreshold, Range::real(0.5, CLOSED, 100, CLOSED, " px"), "edLineFitErrorThreshold")      \
    X(double, MaxErrorThreshold, Range::real(0, OPEN, 100, CLOSED, " px"), "edMaxErrorThreshold")

namespace cv {
namespace ximgproc {
namespace lsda {

// The names files give the values of each enumerated parameter, in value order from 0. Adding
// a value to one of the public enums means adding its name here.
const char* const kBaseDetectors[] = { "BASE_LSD", "BASE_FLD", "BASE_EDLINES", "BASE_FAST_LSD" };
const char* const kLengthFilterModes[] = { "LENGTH_FILTER_NONE", "LENGTH_FILTER_ADAPTIVE", "LENGTH_FILTER_INTERFRAME",
                                           "LENGTH_FILTER_INTERFRAME_CONTINUOUS", "LENGTH_FILTER_COUNT_TRACKING" };
const char* const kLengthThresholdRules[] = { "LENGTH_THRESHOLD_PAPER", "LENGTH_THRESHOLD_CAPPED" };
const char* const kStageOrders[] = { "FILTER_THEN_MERGE", "MERGE_THEN_FILTER" };
const char* const kAngleBinnings[] = { "ANGLE_BINS_STRICT", "ANGLE_BINS_NEIGHBOURS" };
const char* const kMergeStrategies[] = { "MERGE_NONE", "MERGE_BASELINES", "MERGE_LONGEST_FIRST" };
const char* const kLsdRefinements[] = { "LSD_REFINE_NONE", "LSD_REFINE_STD", "LSD_REFINE_ADV" };
const char* const kRegionGrowths[] = { "GROWTH_PER_PIXEL", "GROWTH_PER_NEIGHBOURHOOD" };
const char* const kLineOrders[] = { "LINE_ORDER_STRONGEST", "LINE_ORDER_ACROSS_DIRECTIONS" };
const char* const kFullScaleSmoothings[] = { "SMOOTH_EVERY_IMAGE", "SMOOTH_ALIASED_IMAGES" };
const char* const kGradientOperators[] = { "PREWITT", "SOBEL", "SCHARR", "LSD" };
const int kApertureSizes[] = { 3, 5, 7 };
const char* const kPresets[] = { "PRESET_MOST_ACCURATE", "PRESET_FASTEST", "PRESET_PAPER", "PRESET_SEQUENCE",
                                  "PRESET_FRONT_END" };

#define LSDA_COUNT_OF(names) (int)(sizeof(names) / sizeof(names[0]))
static_assert(LSDA_COUNT_OF(kBaseDetectors) == LSDAdvance::BASE_FAST_LSD + 1, "a name per LSDAdvance::BaseDetector");
static_assert(LSDA_COUNT_OF(kLengthFilterModes) == LSDAdvance::LENGTH_FILTER_COUNT_TRACKING + 1,
              "a name per LSDAdvance::LengthFilterMode");
static_assert(LSDA_COUNT_OF(kLengthThresholdRules) == LSDAdvance::LENGTH_THRESHOLD_CAPPED + 1,
              "a name per LSDAdvance::LengthThresholdRule");
static_assert(LSDA_COUNT_OF(kStageOrders) == LSDAdvance::MERGE_THEN_FILTER + 1, "a name per LSDAdvance::StageOrder");
static_assert(LSDA_COUNT_OF(kAngleBinnings) == LSDAdvance::ANGLE_BINS_NEIGHBOURS + 1, "a name per LSDAdvance::AngleBinning");
static_assert(LSDA_COUNT_OF(kMergeStrategies) == LSDAdvance::MERGE_LONGEST_FIRST + 1, "a name per LSDAdvance::MergeStrategy");
static_assert(LSDA_COUNT_OF(kLsdRefinements) == kLsdRefineAdv + 1, "a name per cv::LineSegmentDetectorModes");
static_assert(LSDA_COUNT_OF(kRegionGrowths) == LSDAdvance::GROWTH_PER_NEIGHBOURHOOD + 1, "a name per LSDAdvance::RegionGrowth");
static_assert(LSDA_COUNT_OF(kLineOrders) == LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS + 1, "a name per LSDAdvance::LineOrder");
static_assert(LSDA_COUNT_OF(kFullScaleSmoothings) == LSDAdvance::SMOOTH_ALIASED_IMAGES + 1,
              "a name per LSDAdvance::FullScaleSmoothing");
static_assert(LSDA_COUNT_OF(kPresets) == LSDAdvance::PRESET_FRONT_END + 1, "a name per LSDAdvance::Preset");
static_assert(LSDA_COUNT_OF(kGradientOperators) == EdgeDrawing::LSD + 1, "a name per EdgeDrawing::GradientOperator");

//! Whether a bound belongs to its range.
enum Bound
{
    CLOSED,
    OPEN
};

//! The values a parameter accepts, and the names files give them.
struct Range
{
    enum Kind
    {
        REAL,  //!< a finite number in [lo, hi] (or open at either end)
        ENUM,  //!< an integer in [0, hi], written by its name
        FLAG,  //!< false or true, written 0 or 1
        LIST   //!< one of values
    };

    static Range real(double lo, Bound loBound, double hi, Bound hiBound, const char* unit = "")
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
    template <size_t N>
    static Range enumOf(const char* const (&names)[N])
    {
        Range r;
        r.kind = ENUM;
        r.hi = (double)N - 1;
        r.names = names;
        r.count = (int)N;
        return r;
    }
    static Range flag()
    {
        Range r;
        r.kind = FLAG;
        r.hi = 1;
        return r;
    }
    template <size_t N>
    static Range oneOf(const int (&values)[N])
    {
        Range r;
        r.kind = LIST;
        r.values = values;
        r.count = (int)N;
        return r;
    }
    //! The same range, which also accepts value (with the meaning given).
    Range orValue(double value, const char* meaning) const
    {
        Range r = *this;
        r.hasExtra = true;
        r.extra = value;
        r.extraMeaning = meaning;
        return r;
    }

    bool accepts(double v) const
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

    //! What accepts() accepts, for messages: "a finite number in (0, 10] px", "one of A (0), B (1)".
    std::string describe() const
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

    Kind kind = REAL;
    double lo = 0, hi = 0;
    Bound loBound = CLOSED, hiBound = CLOSED;
    const char* unit = "";
    const char* const* names = nullptr;  //!< ENUM: the name of each value
    const int* values = nullptr;         //!< LIST
    int count = 0;                       //!< ENUM and LIST: number of values
    bool hasExtra = false;               //!< orValue()
    double extra = 0;
    const char* extraMeaning = "";
};

//! One field of a parameter struct S, read and written as a double.
template <class S>
struct Field
{
    const char* name;
    const char* legacyKey;  //!< key of the flat files of version 4.6.0, or nullptr
    Range range;
    bool integral;          //!< an int or bool field: files hold an integer (or an ENUM's name)
    double (*get)(const S&);
    void (*set)(S&, double);  //!< value already validated
};

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

// The rows of each table as Fields (the persistence and the tests iterate over them).
#define LSDA_FIELD_OF(S, type, field, range, legacyKey)                                                           \
    Field<S>{ #field, legacyKey, range, !std::is_floating_point<type>::value, &getMember<S, type, &S::field>,      \
              &setMember<S, type, &S::field> },
#define LSDA_OWN_FIELD(type, field, Accessor, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::Params, type, field, range, legacyKey)
#define LSDA_LSD_FIELD(type, field, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::LSDParams, type, field, range, legacyKey)
#define LSDA_FLD_FIELD(type, field, value, range, legacyKey) \
    LSDA_FIELD_OF(LSDAdvance::FLDParams, type, field, range, legacyKey)
#define LSDA_EDLINES_FIELD(type, field, range, legacyKey) \
    LSDA_FIELD_OF(EdgeDrawing::Params, type, field, range, legacyKey)

inline const std::vector<Field<LSDAdvance::Params> >& fieldsOf(const LSDAdvance::Params*)
{
    static const std::vector<Field<LSDAdvance::Params> > fields = { LSDA_PARAMS(LSDA_OWN_FIELD) };
    return fields;
}

inline const std::vector<Field<LSDAdvance::LSDParams> >& fieldsOf(const LSDAdvance::LSDParams*)
{
    static const std::vector<Field<LSDAdvance::LSDParams> > fields = { LSDA_LSD_PARAMS(LSDA_LSD_FIELD) };
    return fields;
}

inline const std::vector<Field<LSDAdvance::FLDParams> >& fieldsOf(const LSDAdvance::FLDParams*)
{
    static const std::vector<Field<LSDAdvance::FLDParams> > fields = { LSDA_FLD_PARAMS(LSDA_FLD_FIELD) };
    return fields;
}

inline const std::vector<Field<EdgeDrawing::Params> >& fieldsOf(const EdgeDrawing::Params*)
{
    static const std::vector<Field<EdgeDrawing::Params> > fields = { LSDA_EDLINES_PARAMS(LSDA_EDLINES_FIELD) };
    return fields;
}
#undef LSDA_FIELD_OF
#undef LSDA_OWN_FIELD
#undef LSDA_LSD_FIELD
#undef LSDA_FLD_FIELD
#undef LSDA_EDLINES_FIELD

template <class S>
const std::vector<Field<S> >& fieldsOf()
{
    return fieldsOf((const S*)nullptr);
}

//! Every parameter of a detector, as write() saves them and read() restores them.
struct Parameters
{
    LSDAdvance::Params own;
    LSDAdvance::LSDParams lsd;
    LSDAdvance::FLDParams fld;
    EdgeDrawing::Params edLines;
};

//! The parameters of a preset (LSDAdvance::Preset): the defaults, then what the preset changes.
//! Throws on an unknown preset.
Parameters presetParameters(int preset);

//! Throws cv::Exception naming the first field out of its range, with the range.
void validate(const LSDAdvance::Params& params);
void validate(const LSDAdvance::LSDParams& params);
void validate(const LSDAdvance::FLDParams& params);
void validate(const EdgeDrawing::Params& params);

//! Writes every parameter: LSDAdvance's own at the top, each base's in its own map (lsd, fld,
//! edLines); enumerated values by name.
void writeParameters(FileStorage& fs, const Parameters& parameters);

//! Reads what writeParameters() writes, the flat files of version 4.6.0 (numbers for the
//! enumerated values) and anything between; a missing key keeps the value in parameters, an
//! unknown key is ignored with a warning that names the closest known key. Throws, leaving
//! parameters unchanged, on a value of the wrong type or out of range.
void readParameters(const FileNode& node, Parameters& parameters);

}}} // namespace cv::ximgproc::lsda

#endif
