// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Parameters: getters and setters, Params and the base structs as a whole, presets, write() and
// read(). The parameter lists come from the tables of src/parameters.hpp (parameter_access.hpp);
// the effects of each parameter are tested here (LSDAdvance's own) and in
// test_base_detectors.cpp (the bases').

#include "test_precomp.hpp"
#include "parameter_access.hpp"

#include <fstream>
#include <regex>

namespace opencv_test { namespace {

// A value of the range other than current.
double otherValue(const lsda::Range& range, double current)
{
    for (double v : insideValues(range))
        if (v != current)
            return v;
    CV_Error(Error::StsError, "no other value");
}

double otherValue(const ParameterAccess& p, const LSDAdvance& d)
{
    return otherValue(p.range, p.get(d));
}

// Every parameter of two detectors, compared one by one.
void expectSameParameters(const LSDAdvance& expected, const LSDAdvance& actual)
{
    for (const ParameterAccess& p : everyParameter())
        EXPECT_EQ(p.get(expected), p.get(actual)) << p.name;
}

std::string written(const LSDAdvance& d)
{
    FileStorage out("params.yml", FileStorage::WRITE | FileStorage::MEMORY);
    d.write(out);
    return out.releaseAndGetString();
}

void readText(LSDAdvance& d, const std::string& text)
{
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    CV_Assert(in.isOpened());
    d.read(in.root());
}

// What read() writes to the log (standard error) while reading text.
std::string logOfReading(LSDAdvance& d, const std::string& text)
{
    testing::internal::CaptureStderr();
    readText(d, text);
    return testing::internal::GetCapturedStderr();
}

// The public header as text: it sits beside the tests in the module's tree, in both builds.
std::string publicHeader()
{
    std::string dir = __FILE__;
    dir = dir.substr(0, dir.find_last_of("/\\") + 1);
    const std::string path = dir + "../include/opencv2/lsd_advance/lsd_advance.hpp";
    std::ifstream file(path.c_str());
    CV_Assert(file.good() && "the public header is next to the tests");
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// The range of a real parameter as the header writes it: "[0.1, 200]", "(0, 10]", and with an extra
// value "-1 (from the image size) or [9, 100000]".
std::string interval(const lsda::Range& r)
{
    const std::string extra = r.hasExtra ? format("%g (%s) or ", r.extra, r.extraMeaning) : "";
    return extra + format("%c%g, %g%c", r.loBound == lsda::OPEN ? '(' : '[', r.lo, r.hi, r.hiBound == lsda::OPEN ? ')' : ']');
}

// A default as the header writes it: the name of an enumerated value, true/false, or a number.
double documentedValue(const lsda::Range& r, const std::string& text)
{
    if (r.kind == lsda::Range::FLAG)
        return text == "true" ? 1 : (text == "false" ? 0 : -1);
    for (int k = 0; r.names && k < r.count; k++)
        if (text == r.names[k])
            return k;
    return r.kind == lsda::Range::ENUM ? -1 : std::stod(text);
}

// Every field of struct S in the header's struct `name` says "Default X." with the table's default,
// and a real one says "in <its range>".
template <class S>
void expectHeaderDocumentsTheTable(const std::string& header, const std::string& name)
{
    const std::string begin = "struct CV_EXPORTS_W_SIMPLE " + name + "\n";
    const size_t at = header.find(begin);
    ASSERT_NE(std::string::npos, at) << name;
    const std::string body = header.substr(at, header.find("\n    };", at) - at);
    const S defaults;
    int documented = 0;
    for (const lsda::Field<S>& f : lsda::fieldsOf<S>())
    {
        SCOPED_TRACE(name + "::" + f.name);
        const std::regex line(std::string("CV_PROP_RW \\w+ ") + f.name + ";\\s*//!<([^\n]*)");
        std::smatch m;
        ASSERT_TRUE(std::regex_search(body, m, line));
        const std::string doc = m[1];
        std::smatch d;
        ASSERT_TRUE(std::regex_search(doc, d, std::regex("Default ([-\\w.]+)\\.\\s*$")));
        EXPECT_EQ(f.get(defaults), documentedValue(f.range, d[1]));
        if (f.range.kind == lsda::Range::REAL)
        {
            EXPECT_NE(std::string::npos, doc.find("in " + interval(f.range))) << doc;
        }
        else if (f.range.kind == lsda::Range::LIST)
        {
            EXPECT_NE(std::string::npos, doc.find(f.range.describe())) << doc;
        }
        documented++;
    }
    int fields = 0;
    for (size_t p = body.find("CV_PROP_RW"); p != std::string::npos; p = body.find("CV_PROP_RW", p + 1))
        fields++;
    EXPECT_EQ(fields, documented) << "a field the table lacks";
}

TEST(LSDAdvance_Parameters, header_documents_each_default_and_range_of_the_tables)
{
    const std::string header = publicHeader();
    expectHeaderDocumentsTheTable<LSDAdvance::Params>(header, "Params");
    expectHeaderDocumentsTheTable<LSDAdvance::LSDParams>(header, "LSDParams");
    expectHeaderDocumentsTheTable<LSDAdvance::FLDParams>(header, "FLDParams");
    // EdgeDrawing's own fields keep EdgeDrawing's defaults: setEDLinesParams() documents the ranges.
    const size_t at = header.find("@brief Sets the parameters of BASE_EDLINES.");
    ASSERT_NE(std::string::npos, at);
    const std::string doc = std::regex_replace(header.substr(at, header.find("*/", at) - at), std::regex("\\s+"), " ");
    for (const lsda::Field<EdgeDrawing::Params>& f : lsda::fieldsOf<EdgeDrawing::Params>())
    {
        if (f.range.kind != lsda::Range::REAL)
            continue;
        SCOPED_TRACE(f.name);
        EXPECT_NE(std::string::npos, doc.find(std::string(f.name) + " " + interval(f.range))) << doc;
    }
}

TEST(LSDAdvance_Parameters, every_parameter_round_trips_every_value_its_range_accepts)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::vector<ParameterAccess> parameters = everyParameter();
    for (int base : { -1, (int)LSDAdvance::BASE_LSD, (int)LSDAdvance::BASE_FLD, (int)LSDAdvance::BASE_EDLINES })
        EXPECT_TRUE(std::any_of(parameters.begin(), parameters.end(), [&](const ParameterAccess& p) { return p.base == base; }))
            << base;
    for (const ParameterAccess& p : parameters)
        for (double v : insideValues(p.range))
        {
            SCOPED_TRACE(cv::format("%s = %g", p.name.c_str(), v));
            p.set(*detector, v);
            // EdgeDrawing::Params::Sigma is a float.
            EXPECT_EQ(p.name == "EdgeDrawing::Params::Sigma" ? (double)(float)v : v, p.get(*detector));
        }
}

// Sets a struct with one field out of range and another one changed: the call must throw and
// change nothing.
template <class S>
void expectEveryFieldChecked(S (LSDAdvance::*get)() const, void (LSDAdvance::*set)(const S&))
{
    const std::vector<lsda::Field<S> >& fields = lsda::fieldsOf<S>();
    for (size_t k = 0; k < fields.size(); k++)
        for (double bad : outsideValues(fields[k].range))
        {
            SCOPED_TRACE(cv::format("%s = %g", fields[k].name, bad));
            Ptr<LSDAdvance> detector = createLSDAdvance();
            S s = ((*detector).*get)();
            const lsda::Field<S>& other = fields[k == 0 ? 1 : 0];
            other.set(s, otherValue(other.range, other.get(s)));
            fields[k].set(s, bad);
            EXPECT_THROW(((*detector).*set)(s), cv::Exception);
            expectSameParameters(*createLSDAdvance(), *detector);
        }
}

TEST(LSDAdvance_Parameters, setting_a_struct_checks_every_field_before_changing_any)
{
    expectEveryFieldChecked(&LSDAdvance::getParams, &LSDAdvance::setParams);
    expectEveryFieldChecked(&LSDAdvance::getLSDParams, &LSDAdvance::setLSDParams);
    expectEveryFieldChecked(&LSDAdvance::getFLDParams, &LSDAdvance::setFLDParams);
    expectEveryFieldChecked(&LSDAdvance::getEDLinesParams, &LSDAdvance::setEDLinesParams);
}

TEST(LSDAdvance_Parameters, getParams_and_setParams_carry_every_field)
{
    Ptr<LSDAdvance> source = createLSDAdvance(), target = createLSDAdvance();
    for (const ParameterAccess& p : everyParameter())
        p.set(*source, otherValue(p, *source));
    target->setParams(source->getParams());
    target->setLSDParams(source->getLSDParams());
    target->setFLDParams(source->getFLDParams());
    target->setEDLinesParams(source->getEDLinesParams());
    expectSameParameters(*source, *target);
}

TEST(LSDAdvance_Parameters, presets_are_the_documented_configurations)
{
    const LSDAdvance::Params defaults;
    const Ptr<LSDAdvance> accurate = createLSDAdvance(LSDAdvance::PRESET_MOST_ACCURATE);
    expectSameParameters(*createLSDAdvance(), *accurate);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_ADAPTIVE, accurate->getLengthFilterMode());
    EXPECT_FALSE(accurate->getKeepStrongSegments());

    // The fastest: the defaults, the base at OpenCV LSD's scale.
    const Ptr<LSDAdvance> fastest = createLSDAdvance(LSDAdvance::PRESET_FASTEST);
    LSDAdvance::LSDParams fastestLsd = fastest->getLSDParams();
    EXPECT_EQ(0.8, fastestLsd.scale);
    fastestLsd.scale = LSDAdvance::LSDParams().scale;
    fastest->setLSDParams(fastestLsd);
    expectSameParameters(*createLSDAdvance(), *fastest);
    const Ptr<LSDAdvance> sequence = createLSDAdvance(LSDAdvance::PRESET_SEQUENCE);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING, sequence->getLengthFilterMode());
    EXPECT_TRUE(sequence->getKeepStrongSegments());

    // The paper's: OpenCV's LSD set-up as the base, its threshold rule, order, merging and Dth.
    const Ptr<LSDAdvance> paper = createLSDAdvance(LSDAdvance::PRESET_PAPER);
    const LSDAdvance::LSDParams lsd = paper->getLSDParams();
    EXPECT_EQ(LSD_REFINE_STD, lsd.refine);
    EXPECT_EQ(0.8, lsd.scale);
    EXPECT_EQ(LSDAdvance::BASE_LSD, paper->getBaseDetector());
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_INTERFRAME, paper->getLengthFilterMode());
    EXPECT_EQ(LSDAdvance::LENGTH_THRESHOLD_PAPER, paper->getLengthThresholdRule());
    EXPECT_EQ(LSDAdvance::FILTER_THEN_MERGE, paper->getStageOrder());
    EXPECT_EQ(LSDAdvance::MERGE_BASELINES, paper->getMergeStrategy());
    EXPECT_EQ(0.1, paper->getProximityRatio());
    EXPECT_FALSE(paper->getKeepStrongSegments());
    EXPECT_EQ(defaults.baselineRatio, paper->getBaselineRatio());
    EXPECT_EQ(defaults.directionWeight, paper->getDirectionWeight());

    // Each gives its own lines on building.jpg.
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<std::vector<Vec4f> > lines(4);
    for (int preset = 0; preset < 4; preset++)
        createLSDAdvance((LSDAdvance::Preset)preset)->detect(img, lines[preset]);
    EXPECT_NE(lines[0], lines[1]);
    EXPECT_NE(lines[0], lines[2]);
    EXPECT_NE(lines[0], lines[3]);
    // The first frame of a sequence has alpha = 1: the defaults with strong segments.
    Ptr<LSDAdvance> strong = createLSDAdvance();
    strong->setKeepStrongSegments(true);
    std::vector<Vec4f> strongLines;
    strong->detect(img, strongLines);
    EXPECT_EQ(strongLines, lines[3]);
}

TEST(LSDAdvance_Parameters, write_read_round_trip_preserves_every_parameter)
{
    Ptr<LSDAdvance> saved = createLSDAdvance();
    for (const ParameterAccess& p : everyParameter())
        p.set(*saved, otherValue(p, *saved));
    Ptr<LSDAdvance> loaded = createLSDAdvance();
    readText(*loaded, written(*saved));
    expectSameParameters(*saved, *loaded);
    EXPECT_EQ(String("LSDAdvance"), loaded->getDefaultName());
}

TEST(LSDAdvance_Parameters, write_names_enumerated_values_and_read_takes_names_or_numbers)
{
    Ptr<LSDAdvance> detector = createLSDAdvance(LSDAdvance::PRESET_SEQUENCE);
    detector->setBaseDetector(LSDAdvance::BASE_FLD);
    const std::string text = written(*detector);
    for (const char* line : { "lengthFilterMode: LENGTH_FILTER_COUNT_TRACKING", "baseDetector: BASE_FLD",
                              "stageOrder: MERGE_THEN_FILTER", "refine: LSD_REFINE_NONE", "EdgeDetectionOperator: PREWITT" })
        EXPECT_NE(std::string::npos, text.find(line)) << line << " not in\n" << text;

    Ptr<LSDAdvance> byName = createLSDAdvance(), byNumber = createLSDAdvance();
    readText(*byName, "%YAML:1.0\n---\nmergeStrategy: MERGE_BASELINES\nlsd: { refine: LSD_REFINE_ADV }\n");
    readText(*byNumber, "%YAML:1.0\n---\nmergeStrategy: 1\nlsd: { refine: 2 }\n");
    EXPECT_EQ(LSDAdvance::MERGE_BASELINES, byName->getMergeStrategy());
    EXPECT_EQ(LSD_REFINE_ADV, byName->getLSDParams().refine);
    expectSameParameters(*byName, *byNumber);

    try
    {
        readText(*byName, "%YAML:1.0\n---\nmergeStrategy: MERGE_BASELINE\n");
        ADD_FAILURE() << "an unknown name was accepted";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find("mergeStrategy must be one of MERGE_NONE (0), MERGE_BASELINES (1), "
                                                "MERGE_LONGEST_FIRST (2), got 'MERGE_BASELINE'")) << e.err;
    }
}

TEST(LSDAdvance_Parameters, read_takes_the_flat_files_of_version_4_6_0)
{
    // As write() of version 4.6.0 wrote them: one flat map, numbers for modes.
    const std::string old = "%YAML:1.0\n---\nformat: 3\nlsdRefine: 1\nlsdScale: 0.8\nlengthFilterMode: 2\n"
                            "lengthThreshold: 0\nfldDoMerge: 1\nfldCannyApertureSize: 5\nedSigma: 0.5\n"
                            "edMinLineLength: 20\nedNfaValidation: 0\nmergeThreshold: 0.7\n";
    Ptr<LSDAdvance> detector = createLSDAdvance();
    EXPECT_EQ(std::string::npos, logOfReading(*detector, old).find("unknown key"));
    EXPECT_EQ(LSD_REFINE_STD, detector->getLSDParams().refine);
    EXPECT_EQ(0.8, detector->getLSDParams().scale);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_INTERFRAME, detector->getLengthFilterMode());
    EXPECT_EQ(LSDAdvance::LENGTH_THRESHOLD_PAPER, detector->getLengthThresholdRule());
    EXPECT_TRUE(detector->getFLDParams().doMerge);
    EXPECT_EQ(5, detector->getFLDParams().cannyApertureSize);
    EXPECT_EQ(0.5f, detector->getEDLinesParams().Sigma);
    EXPECT_EQ(20, detector->getEDLinesParams().MinLineLength);
    EXPECT_FALSE(detector->getEDLinesParams().NFAValidation);
    EXPECT_EQ(0.7, detector->getMergeThreshold());
}

TEST(LSDAdvance_Parameters, read_warns_about_an_unknown_key_naming_the_closest_and_reads_the_rest)
{
    Ptr<LSDAdvance> detector = createLSDAdvance();
    const std::string log = logOfReading(
        *detector, "%YAML:1.0\n---\nmergeTreshold: 0.9\nendpointDistance: 4\nlsd: { scal: 0.5, quant: 3 }\n");
    EXPECT_NE(std::string::npos, log.find("unknown key 'mergeTreshold' ignored; the closest known key is "
                                          "'mergeThreshold'")) << log;
    EXPECT_NE(std::string::npos, log.find("unknown key 'lsd.scal' ignored; the closest known key is 'lsd.scale'"))
        << log;
    EXPECT_EQ(LSDAdvance::Params().mergeThreshold, detector->getMergeThreshold());
    EXPECT_EQ(4.0, detector->getEndpointDistance());
    EXPECT_EQ(LSDAdvance::LSDParams().scale, detector->getLSDParams().scale);
    EXPECT_EQ(3.0, detector->getLSDParams().quant);

    // What write() writes has no unknown key.
    EXPECT_EQ(std::string::npos, logOfReading(*detector, written(*detector)).find("unknown key"));
}

TEST(LSDAdvance_Parameters, read_keeps_the_values_of_missing_keys)
{
    Ptr<LSDAdvance> detector = createLSDAdvance(LSDAdvance::PRESET_PAPER);
    readText(*detector, "%YAML:1.0\n---\nmergeThreshold: 0.9\nlsd: { quant: 3 }\n");
    EXPECT_EQ(0.9, detector->getMergeThreshold());
    EXPECT_EQ(0.8, detector->getLSDParams().scale);
    EXPECT_EQ(LSDAdvance::LENGTH_FILTER_INTERFRAME, detector->getLengthFilterMode());
}

// Each of LSDAdvance's own parameters changes the lines of building.jpg: a value to set, and what
// to set before on both detectors for the parameter to act.
TEST(LSDAdvance_Parameters, every_own_parameter_changes_the_output)
{
    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    const std::vector<EffectOf> effects = {
        { "baseDetector", LSDAdvance::BASE_FLD, nullptr, 0 },
        { "lengthFilterMode", LSDAdvance::LENGTH_FILTER_NONE, nullptr, 0 },
        { "lengthThresholdRule", LSDAdvance::LENGTH_THRESHOLD_PAPER, nullptr, 0 },
        { "lengthThresholdScale", 0.5, nullptr, 0 },
        { "keepStrongSegments", 1, nullptr, 0 },
        { "stageOrder", LSDAdvance::FILTER_THEN_MERGE, nullptr, 0 },
        { "angleBinWidth", 3.0, nullptr, 0 },
        { "angleBinning", LSDAdvance::ANGLE_BINS_STRICT, nullptr, 0 },
        { "endpointDistance", 2.0, nullptr, 0 },
        { "mergeStrategy", LSDAdvance::MERGE_BASELINES, nullptr, 0 },
        { "baselineRatio", 0.3, "mergeStrategy", LSDAdvance::MERGE_BASELINES },
        { "directionWeight", 0.0, nullptr, 0 },
        { "proximityWeight", 0.0, nullptr, 0 },
        { "lengthWeight", 0.6, nullptr, 0 },
        { "proximityRatio", 0.1, nullptr, 0 },
        { "mergeThreshold", 1.0, nullptr, 0 },
        { "maxPerpendicularOffset", 4.0, nullptr, 0 },
        { "minLineLength", 60.0, nullptr, 0 },
        { "minLineLengthRatio", 0.125, nullptr, 0 },
        { "maxLines", 20, nullptr, 0 },
        { "lineOrder", LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS, nullptr, 0 },
        { "directionBins", 3, "lineOrder", LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS },
        { "gridCells", 2, "lineOrder", LSDAdvance::LINE_ORDER_ACROSS_DIRECTIONS },
    };
    expectEveryParameterChangesTheLines(effects, img, [](const ParameterAccess& p) { return p.base < 0; },
                                        [](const ParameterAccess&) { return createLSDAdvance(); });
}

TEST(LSDAdvance_Parameters, user_workflow_set_parameters_save_load_and_detect)
{
    // A program of the documented basics: setters, a FileStorage file, detect().
    Ptr<LSDAdvance> configured = createLSDAdvance();
    configured->setMergeThreshold(0.65);
    configured->setLengthFilterMode(LSDAdvance::LENGTH_FILTER_COUNT_TRACKING);
    const String path = cv::tempfile(".yml");
    configured->save(path);  // the parameters under a node named getDefaultName()
    Ptr<LSDAdvance> loaded = createLSDAdvance();
    {
        FileStorage fs(path, FileStorage::READ);
        ASSERT_TRUE(fs.isOpened());
        loaded->read(fs[loaded->getDefaultName()]);
    }
    std::remove(path.c_str());
    expectSameParameters(*configured, *loaded);

    const Mat img = imread(samples::findFile("building.jpg"), IMREAD_GRAYSCALE);
    ASSERT_FALSE(img.empty());
    std::vector<Vec4f> ours, lsd;
    loaded->detect(img, ours);
    createLineSegmentDetector()->detect(img, lsd);
    EXPECT_LT(ours.size(), lsd.size());
    EXPECT_GT(line_evaluation::longSegmentShare(ours, 60.0), line_evaluation::longSegmentShare(lsd, 60.0));
}

}} // namespace
