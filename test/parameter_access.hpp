// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Every parameter of LSDAdvance as the tests reach it, from the tables of src/parameters.hpp:
// LSDAdvance's own through their getters and setters, the base detectors' through their structs.

#ifndef OPENCV_LSD_ADVANCE_TEST_PARAMETER_ACCESS_HPP
#define OPENCV_LSD_ADVANCE_TEST_PARAMETER_ACCESS_HPP

#include "test_precomp.hpp"
#include "../src/parameters.hpp"

namespace opencv_test {

struct ParameterAccess
{
    std::string name;  //!< as setters' messages name it: "mergeThreshold", "LSDParams::scale", ...
    std::string key;   //!< its key in files: "mergeThreshold", "scale", ...
    std::string map;   //!< the map of files that holds key: "" (the top), "lsd", "fld" or "edLines"
    lsda::Range range;
    bool integral;
    int base;          //!< the BaseDetector whose parameter it is; -1 for LSDAdvance's own
    std::function<void(LSDAdvance&, double)> set;
    std::function<double(const LSDAdvance&)> get;
};

template <class S>
void addStructFields(std::vector<ParameterAccess>& out, const std::string& prefix, const std::string& map, int base,
                     S (LSDAdvance::*getStruct)() const, void (LSDAdvance::*setStruct)(const S&))
{
    for (const lsda::Field<S>& f : lsda::fieldsOf<S>())
        out.push_back({ prefix + f.name, f.name, map, f.range, f.integral, base,
                        [=](LSDAdvance& d, double v) {
                            S s = (d.*getStruct)();
                            f.set(s, v);
                            (d.*setStruct)(s);
                        },
                        [=](const LSDAdvance& d) { return f.get((d.*getStruct)()); } });
}

//! Every parameter: the rows of the four tables.
inline std::vector<ParameterAccess> everyParameter()
{
    std::vector<ParameterAccess> out;
    const std::vector<lsda::Field<LSDAdvance::Params> >& own = lsda::fieldsOf<LSDAdvance::Params>();
    size_t row = 0;
#define LSDA_ACCESS(type, field, Accessor, value, valid, legacyKey)                                              \
    out.push_back({ #field, #field, "", own[row].range, own[row].integral, -1,                                              \
                    [](LSDAdvance& d, double v) { d.set##Accessor((type)v); },                                   \
                    [](const LSDAdvance& d) { return (double)d.get##Accessor(); } });                           \
    row++;
    LSDA_PARAMS(LSDA_ACCESS)
#undef LSDA_ACCESS
    CV_Assert(row == own.size());
    addStructFields(out, "LSDParams::", "lsd", LSDAdvance::BASE_LSD, &LSDAdvance::getLSDParams, &LSDAdvance::setLSDParams);
    addStructFields(out, "FLDParams::", "fld", LSDAdvance::BASE_FLD, &LSDAdvance::getFLDParams, &LSDAdvance::setFLDParams);
    addStructFields(out, "EdgeDrawing::Params::", "edLines", LSDAdvance::BASE_EDLINES, &LSDAdvance::getEDLinesParams,
                    &LSDAdvance::setEDLinesParams);
    return out;
}

//! A value of a parameter that changes what detect() returns, and what to set before on both
//! detectors for the parameter to act (setUpName nullptr: nothing).
struct EffectOf
{
    const char* name;
    double value;
    const char* setUpName;
    double setUpValue;
};

//! Every parameter that `which` selects must have an entry in `effects` and change the lines of
//! img on detectors made by detectorFor(parameter).
inline void expectEveryParameterChangesTheLines(const std::vector<EffectOf>& effects, const Mat& img,
                                                const std::function<bool(const ParameterAccess&)>& which,
                                                const std::function<Ptr<LSDAdvance>(const ParameterAccess&)>& detectorFor)
{
    const std::vector<ParameterAccess> parameters = everyParameter();
    const auto named = [&](const std::string& name) {
        for (const ParameterAccess& p : parameters)
            if (p.name == name)
                return p;
        CV_Error(Error::StsError, "no parameter " + name);
    };
    for (const ParameterAccess& p : parameters)
    {
        if (!which(p))
            continue;
        SCOPED_TRACE(p.name);
        const auto effect = std::find_if(effects.begin(), effects.end(), [&](const EffectOf& e) { return p.name == e.name; });
        ASSERT_TRUE(effect != effects.end()) << "no test of the effect of " << p.name;
        Ptr<LSDAdvance> reference = detectorFor(p), changed = detectorFor(p);
        if (effect->setUpName)
            for (const Ptr<LSDAdvance>& d : { reference, changed })
                named(effect->setUpName).set(*d, effect->setUpValue);
        p.set(*changed, effect->value);
        std::vector<Vec4f> expected, lines;
        reference->detect(img, expected);
        changed->detect(img, lines);
        EXPECT_NE(expected, lines);
    }
}

//! The YAML that sets parameter p to value (a YAML scalar).
inline std::string yamlOf(const ParameterAccess& p, const std::string& value)
{
    const std::string entry = p.key + ": " + value;
    return "%YAML:1.0\n---\n" + (p.map.empty() ? entry : p.map + ": { " + entry + " }") + "\n";
}

//! Values the range accepts: its ends (or points just inside open ones), a middle value, the
//! extra value.
inline std::vector<double> insideValues(const lsda::Range& r)
{
    std::vector<double> v;
    if (r.kind == lsda::Range::LIST)
        v.assign(r.values, r.values + r.count);
    else if (r.kind != lsda::Range::REAL)
        for (double k = r.lo; k <= r.hi; k++)
            v.push_back(k);
    else
    {
        const double step = std::min(1e-3, (r.hi - r.lo) / 4);
        v.push_back(r.loBound == lsda::OPEN ? r.lo + step : r.lo);
        v.push_back(r.hiBound == lsda::OPEN ? r.hi - step : r.hi);
        const double middle = std::floor(0.5 * (r.lo + r.hi));  // an integer where the range has one
        v.push_back(r.accepts(middle) ? middle : 0.5 * (r.lo + r.hi));
    }
    if (r.hasExtra)
        v.push_back(r.extra);
    return v;
}

//! Values the range rejects: just outside each end (the end itself when open), and for integral
//! ranges the integers next to them; flags have none (a bool cannot be out of range).
inline std::vector<double> outsideValues(const lsda::Range& r)
{
    std::vector<double> v;
    switch (r.kind)
    {
    case lsda::Range::FLAG:
        break;
    case lsda::Range::LIST:
        for (int k = 0; k + 1 < r.count; k++)
            if (r.values[k + 1] - r.values[k] > 1)
                v.push_back(r.values[k] + 1);
        v.push_back(r.values[0] - 1);
        v.push_back(r.values[r.count - 1] + 1);
        break;
    case lsda::Range::ENUM:
        v.push_back(r.lo - 1);
        v.push_back(r.hi + 1);
        break;
    default:
        v.push_back(r.loBound == lsda::OPEN ? r.lo : r.lo - std::max(1.0, std::abs(r.lo) * 1e-3));
        v.push_back(r.hiBound == lsda::OPEN ? r.hi : r.hi + std::max(1.0, std::abs(r.hi) * 1e-3));
    }
    if (r.hasExtra)
    {
        v.push_back(r.extra - 1);
        v.push_back(r.extra + 1);
        v.erase(std::remove_if(v.begin(), v.end(), [&](double x) { return r.accepts(x); }), v.end());
    }
    return v;
}

} // namespace opencv_test

#endif
