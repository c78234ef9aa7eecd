// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Benchmarks line detectors on real data, all in one run:
//  --dataset=yorkurban: structural AP / AR / F against YorkUrban-LineSegment ground truth,
//    segments per image, long-segment share and median time per image (the paper's Table 2);
//  --dataset=sequence: mean and standard deviation over frames of segments per frame,
//    long-segment share and time per frame (the paper's Table 1), LBD matching between
//    consecutive frames checked against the epipolar geometry of the poses (doc/matching.md),
//    and the tracks these matches chain into; with --frontend, what a point-line SLAM front end
//    does per frame (minimum length, line budget, LBD, one-way gated matching, tracks), with
//    the diagnostics of why lines do not match (doc/matching.md, "In a SLAM front end");
//  --dataset=homography: LBD matching between image pairs related by a known homography:
//    matches, correct matches, precision, repeatability and localisation error (doc/matching.md).
// Prints Markdown tables on stdout, optionally writes CSV and SVG bar charts of time, F and
// long-segment share per method (--chart), and reports progress on stderr.

#include "command_line.hpp"
#include "line_methods.hpp"
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
#include "line_matching.hpp"
#include "pose_benchmark.hpp"
#endif

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::ximgproc;
using namespace cv::ximgproc::line_evaluation;

namespace {

// Median time in ms of `repeats` detections on one image; lines of the last one. With
// independent, the sequence is reset before each detection (outside the timed call).
double timedDetect(const LineMethod& method, const Mat& gray, int repeats, std::vector<Vec4f>& lines, bool independent)
{
    std::vector<double> ms;
    for (int r = 0; r < repeats; r++)
    {
        if (independent)
            method.reset();
        TickMeter tm;
        tm.start();
        method.detect(gray, lines);
        tm.stop();
        ms.push_back(tm.getTimeMilli());
    }
    return median(ms);
}

void meanStd(const std::vector<double>& v, double& mean, double& stddev)
{
    Scalar m, s;
    meanStdDev(v, m, s);
    mean = m[0];
    stddev = s[0];
}

std::vector<std::string> splitList(const std::string& list)
{
    std::vector<std::string> items;
    std::stringstream ss(list);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty())
            items.push_back(item);
    return items;
}

struct Table
{
    std::vector<std::string> header;
    std::vector<std::vector<std::string> > rows;

    void print(std::ostream& out) const
    {
        out << "|";
        for (const std::string& h : header)
            out << " " << h << " |";
        out << "\n|";
        for (size_t i = 0; i < header.size(); i++)
            out << (i == 0 ? "---|" : "---:|");
        out << "\n";
        for (const auto& row : rows)
        {
            out << "|";
            for (const std::string& cell : row)
                out << " " << cell << " |";
            out << "\n";
        }
    }
    void writeCsv(const std::string& path) const
    {
        std::ofstream out(path.c_str());
        if (!out)
            throw std::runtime_error("cannot write " + path);
        // RFC 4180: a field with a comma or a quote is quoted, its quotes doubled.
        const auto field = [](const std::string& text) {
            if (text.find_first_of(",\"") == std::string::npos)
                return text;
            std::string quoted = "\"";
            for (char c : text)
                quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
            return quoted + "\"";
        };
        for (size_t i = 0; i < header.size(); i++)
            out << (i ? "," : "") << field(header[i]);
        out << "\n";
        for (const auto& row : rows)
        {
            for (size_t i = 0; i < row.size(); i++)
                out << (i ? "," : "") << field(row[i]);
            out << "\n";
        }
    }
};

// Text as SVG character data.
std::string xmlEscaped(const std::string& text)
{
    std::string out;
    for (char c : text)
    {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else
            out += c;
    }
    return out;
}

// Spacing of about five axis ticks up to maxValue: 1, 2 or 5 times a power of ten.
double tickStep(double maxValue)
{
    const double raw = maxValue / 5.0;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : { 1.0, 2.0, 5.0 })
        if (m * power >= raw)
            return m * power;
    return 10.0 * power;
}

// A horizontal bar chart, one bar per method with its value written at its end, as a
// self-contained SVG file (vector: crisp at any size in the docs).
struct BarChart
{
    std::string title, note;
    std::vector<std::string> labels, valueTexts;
    std::vector<double> values;

    void writeSvg(const std::string& path) const
    {
        // One value far above the others (FLD+merge's time) would squeeze the other bars: the axis
        // then ends at three times the median, and longer bars are drawn cut, with their value.
        const double largest = values.empty() ? 1.0 : std::max(1e-9, *std::max_element(values.begin(), values.end()));
        const double typical = median(values), shown = largest > 5 * typical && typical > 0 ? 3 * typical : largest;
        const double step = tickStep(shown), axisMax = std::ceil(shown / step) * step;
        size_t longestLabel = 0, longestValue = 0;
        for (size_t i = 0; i < labels.size(); i++)
        {
            longestLabel = std::max(longestLabel, labels[i].size());
            longestValue = std::max(longestValue, valueTexts[i].size());
        }
        // Character widths of 12-15 px sans-serif fonts, on the safe side.
        const int labelWidth = (int)(8.2 * longestLabel) + 20, valueWidth = (int)(7.5 * longestValue) + 12;
        const int plotWidth = 440, barHeight = 22, gap = 8, top = note.empty() ? 44 : 62;
        const int width = std::max(labelWidth + plotWidth + 24 + valueWidth + 10,
                                   (int)(9.0 * std::max(title.size(), note.size() * 4 / 5)) + 20);
        const int plotHeight = (int)values.size() * (barHeight + gap);
        const int height = top + plotHeight + 30;

        std::ofstream out(path.c_str());
        if (!out)
            CV_Error_(Error::StsError, ("cannot write the chart %s", path.c_str()));
        out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
            << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
        out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
        out << "<text x=\"10\" y=\"24\" font-size=\"15\" font-weight=\"bold\">" << xmlEscaped(title) << "</text>\n";
        if (!note.empty())
            out << "<text x=\"10\" y=\"44\" font-size=\"12\" fill=\"#555\">" << xmlEscaped(note) << "</text>\n";
        for (double tick = 0; tick <= axisMax + step / 2; tick += step)
        {
            const double x = labelWidth + plotWidth * tick / axisMax;
            out << format("<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n", x, top - 4, x,
                          top + plotHeight);
            out << format("<text x=\"%.1f\" y=\"%d\" font-size=\"11\" fill=\"#555\" text-anchor=\"middle\">%g</text>\n",
                          x, top + plotHeight + 16, tick);
        }
        for (size_t i = 0; i < values.size(); i++)
        {
            const int y = top + (int)i * (barHeight + gap);
            const bool cut = values[i] > axisMax;
            const double barWidth = cut ? plotWidth + 24.0 : plotWidth * std::max(0.0, values[i]) / axisMax;
            // LSDAdvance's variants in one colour, the other detectors in another.
            const char* colour = labels[i].compare(0, 10, "LSDAdvance") == 0 ? "#d95f02" : "#7570b3";
            out << format("<text x=\"%d\" y=\"%d\" font-size=\"13\" text-anchor=\"end\">", labelWidth - 8,
                          y + barHeight - 6)
                << xmlEscaped(labels[i]) << "</text>\n";
            out << format("<rect x=\"%d\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"%s\"/>\n", labelWidth, y,
                          barWidth, barHeight, colour);
            if (cut)  // a white gap across the bar just beyond the axis end
                out << format("<path d=\"M%.1f %d l6 %d M%.1f %d l6 %d\" stroke=\"white\" stroke-width=\"2.5\"/>\n",
                              labelWidth + plotWidth + 4.0, y - 2, barHeight + 4, labelWidth + plotWidth + 10.0, y - 2,
                              barHeight + 4);
            out << format("<text x=\"%.1f\" y=\"%d\" font-size=\"12\">", labelWidth + barWidth + 5, y + barHeight - 6)
                << xmlEscaped(valueTexts[i]) << "</text>\n";
        }
        out << format("<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#333\"/>\n", labelWidth, top - 4,
                      labelWidth, top + plotHeight);
        out << "</svg>\n";
    }
};

// The column of the table whose header starts with `prefix`; -1 when there is none.
int columnOf(const Table& table, const std::string& prefix)
{
    for (size_t c = 0; c < table.header.size(); c++)
        if (table.header[c].compare(0, prefix.size(), prefix) == 0)
            return (int)c;
    return -1;
}

// One bar per row of the table's column, labelled with the table's own text of the value.
BarChart chartOf(const Table& table, int column, const std::string& title, const std::string& note)
{
    BarChart chart;
    chart.title = title;
    chart.note = note;
    for (const auto& row : table.rows)
    {
        chart.labels.push_back(row[0]);
        chart.values.push_back(std::stod(row[column]));
        chart.valueTexts.push_back(row[column]);
    }
    return chart;
}

// <prefix>_time.svg, <prefix>_f.svg and <prefix>_long.svg from the columns the table has;
// returns the files written.
std::vector<std::string> writeCharts(const Table& table, const std::string& prefix, const std::string& runInfo,
                                     double longLength)
{
    std::vector<std::string> written;
    const int time = std::max(columnOf(table, "ms / image (median)"), columnOf(table, "ms / frame (median)"));
    if (time >= 0)
    {
        const bool perFrame = table.header[time].find("frame") != std::string::npos;
        BarChart chart = chartOf(table, time, perFrame ? "Time per frame, ms (median)" : "Time per image, ms (median)", runInfo);
        // Times compare within one run only: each bar also gives its ratio to LSD's.
        for (size_t i = 0; i < table.rows.size(); i++)
            if (table.rows[i][0] == "LSD" && chart.values[i] > 0)
            {
                for (size_t k = 0; k < chart.values.size(); k++)
                    chart.valueTexts[k] += format(" ms (%.2fx LSD)", chart.values[k] / chart.values[i]);
                chart.note += ", ratio to LSD in this run";
            }
        written.push_back(prefix + "_time.svg");
        chart.writeSvg(written.back());
    }
    const int f = columnOf(table, "F");
    if (f >= 0 && table.header[f] == "F")
    {
        written.push_back(prefix + "_f.svg");
        chartOf(table, f, "F score (structural, 2 AP AR / (AP + AR))", runInfo).writeSvg(written.back());
    }
    const int longShare = columnOf(table, "long share");
    if (longShare >= 0)
    {
        written.push_back(prefix + "_long.svg");
        chartOf(table, longShare,
                format("Share of segments >= %g px%s", longLength,
                       table.header[longShare] == "long share" ? "" : " (mean over frames)"),
                runInfo).writeSvg(written.back());
    }
    return written;
}

// The time of a method divided by OpenCV LSD's on the same images, the median over the images
// (the ratio of each image, so that a comparison holds while the machine's speed drifts), when the
// methods hold OpenCV's LSD; "-" otherwise.
std::string medianTimeRatio(const std::vector<LineMethod>& methods, const std::vector<std::vector<double> >& ms, size_t m)
{
    for (size_t lsd = 0; lsd < methods.size(); lsd++)
        if (methods[lsd].name == "LSD")
        {
            std::vector<double> ratios;
            for (size_t k = 0; k < ms[m].size(); k++)
                if (ms[lsd][k] > 0)
                    ratios.push_back(ms[m][k] / ms[lsd][k]);
            return ratios.empty() ? std::string("-") : format("%.3f", median(ratios));
        }
    return "-";
}

Table benchmarkYorkUrban(const std::vector<LineMethod>& methods, const std::vector<LabelledImage>& images,
                         int repeats, double longLength)
{
    Table table;
    table.header = { "method", "AP", "AR", "F", "segments / image", "long share", "ms / image (median)",
                     "time / LSD (median)" };
    std::vector<std::vector<double> > precision(methods.size()), recall(methods.size()), ms(methods.size());
    std::vector<double> segments(methods.size(), 0.0), longOnes(methods.size(), 0.0);
    for (size_t k = 0; k < images.size(); k++)
    {
        std::cerr << "\r[yorkurban] image " << k + 1 << "/" << images.size() << std::flush;
        const Mat gray = imread(images[k].imagePath, IMREAD_GRAYSCALE);
        CV_Assert(!gray.empty());
        for (size_t m = 0; m < methods.size(); m++)
        {
            std::vector<Vec4f> lines;
            ms[m].push_back(timedDetect(methods[m], gray, repeats, lines, true));
            const StructuralScore score = evaluateStructural(lines, images[k].groundTruth);
            precision[m].push_back(score.precision);
            recall[m].push_back(score.recall);
            segments[m] += (double)lines.size();
            longOnes[m] += longSegmentShare(lines, longLength) * (double)lines.size();
        }
    }
    std::cerr << "\n";
    for (size_t m = 0; m < methods.size(); m++)
    {
        const double ap = mean(precision[m])[0], ar = mean(recall[m])[0];
        table.rows.push_back({ methods[m].name, format("%.3f", ap), format("%.3f", ar), format("%.3f", fScore(ap, ar)),
                               format("%.1f", segments[m] / images.size()),
                               format("%.3f", segments[m] > 0 ? longOnes[m] / segments[m] : 0.0),
                               format("%.1f", median(ms[m])), medianTimeRatio(methods, ms, m) });
    }
    return table;
}

// Whether and how the benchmarks match lines.
struct LineMatchOptions
{
    bool enabled = false;
    //! Line budgets: each method matches only its N lines of highest response, for each N here
    //! (0: all its lines).
    std::vector<int> budgets = { 0 };
    std::string rank = "own";  //!< the response that ranks them: own, length or contrast
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    LineMatchParams params;
#endif
};

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
// A front end's line budget: the method's `budget` lines of highest response (all when budget <= 0).
// "own" is the KeyLine response the method's own detector gives: LSDAdvance's
// computeLineResponses, LSDDetector's length for the others; "length" and "contrast" rank every
// method alike, by the one or the other.
std::vector<Vec4f> budgetLines(const LineMethod& method, const Mat& gray, const std::vector<Vec4f>& lines,
                               const LineMatchOptions& matching, int budget)
{
    if (budget <= 0)
        return lines;
    std::vector<float> responses;
    if (matching.rank == "contrast" || (matching.rank == "own" && method.lsdAdvance))
        computeLineResponses(gray, lines, responses);
    else
        responses = lengthResponses(lines, gray.size());
    return bestLines(lines, responses, budget);
}

// The matching rows are per budget when one is set: a column says which.
bool budgetColumn(const LineMatchOptions& matching)
{
    return matching.budgets.size() > 1 || matching.budgets[0] > 0;
}

// Matches of one method accumulated over image pairs.
struct MatchTotals
{
    int pairs = 0;
    double matches = 0, correct = 0, undecidable = 0, decided = 0;
    double repeated = 0, visible = 0, errorSum = 0;

    void addHomography(const ximgproc::line_evaluation::HomographyMatchScore& s)
    {
        pairs++;
        matches += s.matches;
        correct += s.correct;
        decided += s.matches;
        repeated += s.repeated;
        visible += s.visible;
        errorSum += s.localisationError * s.repeated;
    }
    void addEpipolar(const ximgproc::line_evaluation::EpipolarMatchScore& s)
    {
        pairs++;
        matches += s.matches;
        correct += s.consistent;
        decided += s.consistent + s.inconsistent;
        undecidable += s.undecidable;
    }
    double perPair(double total) const { return pairs > 0 ? total / pairs : 0.0; }
    double precision() const { return decided > 0 ? correct / decided : 0.0; }
};
#endif

Table benchmarkSequence(const std::vector<LineMethod>& methods, const SequenceData& sequence, double longLength,
                        const LineMatchOptions& matching)
{
    const std::vector<String>& frames = sequence.imagePaths;
    Table table;
    table.header = { "method", "segments / frame (mean)", "segments / frame (std)", "long share (mean)",
                     "long share (std)", "ms / frame (mean)", "ms / frame (std)", "ms / frame (median)",
                     "time / LSD (median)" };
    std::vector<std::vector<double> > counts(methods.size()), shares(methods.size()), ms(methods.size());
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    const bool withPoses = !sequence.P0.empty() && !sequence.poses.empty();
    if (matching.enabled)
    {
        if (budgetColumn(matching))
            table.header.insert(table.header.begin() + 1, "lines / frame (budget)");
        table.header.push_back("matches / pair");
        if (withPoses)
            for (const char* h : { "consistent / pair", "undecidable / pair", "precision (consistent / decidable)" })
                table.header.push_back(h);
        for (const char* h : { "tracks / frame", "track length (frames, mean)", "tracks >= 5 frames",
                               "computeLBD ms / frame (median)", "line_descriptor LBD ms / frame (median)" })
            table.header.push_back(h);
    }
    // Per budget b and method m, at b * methods.size() + m.
    const size_t runs = matching.budgets.size() * methods.size();
    std::vector<MatchTotals> totals(runs);
    std::vector<LineTracks> tracks(runs);
    std::vector<DescribedLines> previous(runs);
    std::vector<LbdTimes> lbd(runs);
#else
    CV_UNUSED(matching);
#endif
    for (const LineMethod& m : methods)
        m.reset();
    for (size_t k = 0; k < frames.size(); k++)
    {
        std::cerr << "\r[sequence] frame " << k + 1 << "/" << frames.size() << std::flush;
        const Mat gray = imread(frames[k], IMREAD_GRAYSCALE);
        CV_Assert(!gray.empty());
        for (size_t m = 0; m < methods.size(); m++)
        {
            std::vector<Vec4f> lines;
            ms[m].push_back(timedDetect(methods[m], gray, 1, lines, false));
            counts[m].push_back((double)lines.size());
            shares[m].push_back(longSegmentShare(lines, longLength));
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
            if (!matching.enabled)
                continue;
            for (size_t b = 0; b < matching.budgets.size(); b++)
            {
                const size_t r = b * methods.size() + m;
                DescribedLines current =
                    describeLinesTimed(gray, budgetLines(methods[m], gray, lines, matching, matching.budgets[b]), lbd[r]);
                std::vector<DMatch> matches;
                if (k > 0)
                {
                    matches = matchLines(previous[r], current, matching.params);
                    if (withPoses)
                    {
                        const Mat F = fundamentalFromPoses(sequence.P0, sequence.poses[k - 1], sequence.poses[k]);
                        totals[r].addEpipolar(evaluateEpipolarMatches(previous[r].lines, current.lines, matches, F));
                    }
                    else
                    {
                        totals[r].pairs++;
                        totals[r].matches += (double)matches.size();
                    }
                }
                tracks[r].addFrame(current.lines.size(), matches);
                previous[r] = current;
            }
#endif
        }
    }
    std::cerr << "\n";
    const size_t rowsPerMethod = matching.enabled ? matching.budgets.size() : 1;
    for (size_t b = 0; b < rowsPerMethod; b++)
        for (size_t m = 0; m < methods.size(); m++)
        {
            double cm, cs, sm, ss, tm, ts;
            meanStd(counts[m], cm, cs);
            meanStd(shares[m], sm, ss);
            meanStd(ms[m], tm, ts);
            table.rows.push_back({ methods[m].name, format("%.1f", cm), format("%.1f", cs), format("%.3f", sm),
                                   format("%.3f", ss), format("%.1f", tm), format("%.1f", ts),
                                   format("%.1f", median(ms[m])), medianTimeRatio(methods, ms, m) });
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
            if (!matching.enabled)
                continue;
            std::vector<std::string>& row = table.rows.back();
            if (budgetColumn(matching))
                row.insert(row.begin() + 1, format("%d", matching.budgets[b]));
            const size_t r = b * methods.size() + m;
            const MatchTotals& t = totals[r];
            row.push_back(format("%.1f", t.perPair(t.matches)));
            if (withPoses)
                for (const std::string& cell : { format("%.1f", t.perPair(t.correct)), format("%.1f", t.perPair(t.undecidable)),
                                                 format("%.3f", t.precision()) })
                    row.push_back(cell);
            for (const std::string& cell : { format("%.1f", tracks[r].perFrame()), format("%.2f", tracks[r].meanLength()),
                                             format("%d", tracks[r].atLeast(5)), format("%.2f", median(lbd[r].computeLbd)),
                                             format("%.1f", median(lbd[r].lineDescriptor)) })
                row.push_back(cell);
#endif
        }
    return table;
}

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
// The reference of the front-end mode's time ratio: PL-VINS's LSD front end.
const char* const kFrontEndReference = "PL-VINS LSD";

// What one method's front end did over a sequence, and what kept its lines from matching.
struct FrontEndRun
{
    std::vector<double> detected, kept, matches, consistent, undecidable;  // per frame (matches: per pair)
    std::vector<double> detectMs, keepMs, matchMs, totalMs;                // per frame
    LbdTimes lbd;                                                          // per frame, both LBDs
    double consistentSum = 0, decidedSum = 0;
    LineTracks tracks;
    // The diagnostics, pooled over the pairs: the current frame's kept lines ...
    double lines = 0, withoutCandidate = 0, eligibleCandidate = 0;  // ... without a previous kept line within the
                                                                    // gates; of them, with an eligible previous line
    double withCandidate = 0, belowGate = 0;                        // ... with one; whose nearest is below the gate
    double halves[2][2][2] = {};  // [by length, by response/length][lower, upper half][lines, below the gate]
    std::vector<double> nearestHamming, lengthRatio, consistentLengthRatio, endpointShift;
};

// Whether some segment of the earlier frame's is within the front end's gates of `line`.
bool hasGateCandidate(const std::vector<Vec4f>& earlier, const Vec4f& line, const FrontEndParams& params)
{
    for (const Vec4f& e : earlier)
        if (withinFrontEndGates(e, line, params))
            return true;
    return false;
}

// The diagnostics of one pair: previous and current kept lines, the previous frame's eligible lines
// (long enough, before the budget), the one-way nearest neighbours and the kept matches.
void addFrontEndDiagnostics(FrontEndRun& run, const Mat& gray, const DescribedLines& previous,
                            const std::vector<Vec4f>& previousEligible, const DescribedLines& current,
                            const std::vector<DMatch>& matches, const std::vector<int>& verdicts,
                            const FrontEndParams& params)
{
    std::vector<DMatch> nearest;
    if (!previous.descriptors.empty() && !current.descriptors.empty())
        line_descriptor::BinaryDescriptorMatcher::createBinaryDescriptorMatcher()->match(current.descriptors,
                                                                                       previous.descriptors, nearest);
    std::vector<float> responses;
    if (!current.lines.empty())
        responses = frontEndResponses(gray, current.lines);
    std::vector<double> lengths, contrasts;
    for (size_t i = 0; i < current.lines.size(); i++)
    {
        lengths.push_back(segmentLength(current.lines[i]));
        contrasts.push_back(responses[i] / std::max(lengths.back(), 1.0));
    }
    const double medianLength = median(lengths), medianContrast = median(contrasts);
    for (const DMatch& m : nearest)
    {
        const int i = m.queryIdx;
        run.lines++;
        if (!hasGateCandidate(previous.lines, current.lines[i], params))
        {
            run.withoutCandidate++;
            run.eligibleCandidate += hasGateCandidate(previousEligible, current.lines[i], params);
            continue;
        }
        const bool below = m.distance < params.maxHamming;
        run.withCandidate++;
        run.belowGate += below;
        run.nearestHamming.push_back(m.distance);
        const bool upper[2] = { lengths[i] >= medianLength, contrasts[i] >= medianContrast };
        for (int by = 0; by < 2; by++)
        {
            run.halves[by][upper[by]][0]++;
            run.halves[by][upper[by]][1] += below;
        }
    }
    for (size_t k = 0; k < matches.size(); k++)
    {
        const Vec4f &a = previous.lines[matches[k].queryIdx], &b = current.lines[matches[k].trainIdx];
        const double la = segmentLength(a), lb = segmentLength(b);
        const double ratio = std::min(la, lb) / std::max(std::max(la, lb), 1e-9);
        run.lengthRatio.push_back(ratio);
        if (!verdicts.empty() && verdicts[k] == EPIPOLAR_CONSISTENT)
            run.consistentLengthRatio.push_back(ratio);
        run.endpointShift.push_back(0.5 * (std::hypot(b[0] - a[0], b[1] - a[1]) + std::hypot(b[2] - a[2], b[3] - a[3])));
    }
}

// The front-end mode: per frame, what a point-line SLAM front end does with each method's lines
// (detect; keep by the minimum length and the budget; LBD on the kept lines; one-way matching
// to the previous frame's kept lines under the gates; tracks). Two tables: the front end's
// figures, and the diagnostics of why lines do not match.
std::pair<Table, Table> benchmarkFrontEnd(const std::vector<LineMethod>& methods, const SequenceData& sequence,
                                          const FrontEndParams& params, int trackFrames, bool clahe)
{
    // PL-VINS equalises each frame before it detects and describes (CLAHE, clip limit 3, 8 x 8
    // tiles); the same for every method, so outside the times.
    const Ptr<CLAHE> equaliser = createCLAHE(3.0, Size(8, 8));
    const std::vector<String>& frames = sequence.imagePaths;
    const bool withPoses = !sequence.P0.empty() && !sequence.poses.empty();
    std::vector<FrontEndRun> runs(methods.size());
    std::vector<DescribedLines> previous(methods.size());
    std::vector<std::vector<Vec4f> > previousEligible(methods.size());
    for (const LineMethod& m : methods)
    {
        m.reset();
        // A front end gives LSDAdvance its rules (the budget belongs to the user), so that the
        // detector's order chooses among the lines the front end keeps; the others it applies itself.
        if (m.lsdAdvance)
        {
            m.lsdAdvance->setMinLineLength(params.minLength);
            m.lsdAdvance->setMinLineLengthRatio(params.minLengthRatio);
            m.lsdAdvance->setMaxLines(params.maxLines);
        }
    }
    for (size_t k = 0; k < frames.size(); k++)
    {
        std::cerr << "\r[frontend] frame " << k + 1 << "/" << frames.size() << std::flush;
        Mat gray = imread(frames[k], IMREAD_GRAYSCALE);
        CV_Assert(!gray.empty());
        if (clahe)
            equaliser->apply(gray, gray);
        for (size_t m = 0; m < methods.size(); m++)
        {
            FrontEndRun& run = runs[m];
            TickMeter detectTime, keepTime, matchTime;
            std::vector<Vec4f> detected;
            detectTime.start();
            methods[m].detect(gray, detected);
            detectTime.stop();
            keepTime.start();
            const std::vector<Vec4f> kept = frontEndLines(gray, detected, params);
            keepTime.stop();
            const DescribedLines current = describeLinesTimed(gray, kept, run.lbd);
            std::vector<DMatch> matches;
            matchTime.start();
            if (k > 0)
                matches = matchFrontEnd(previous[m], current, params);
            matchTime.stop();

            run.detected.push_back((double)detected.size());
            run.kept.push_back((double)kept.size());
            run.detectMs.push_back(detectTime.getTimeMilli());
            run.keepMs.push_back(keepTime.getTimeMilli());
            run.matchMs.push_back(matchTime.getTimeMilli());
            // The LBD each front end runs: computeLBD with the module's lines, line_descriptor's with the others'.
            const double lbdMs = methods[m].lsdAdvance ? run.lbd.computeLbd.back() : run.lbd.lineDescriptor.back();
            run.totalMs.push_back(run.detectMs.back() + run.keepMs.back() + lbdMs + run.matchMs.back());
            if (k > 0)
            {
                std::vector<int> verdicts;
                run.matches.push_back((double)matches.size());
                if (withPoses)
                {
                    const Mat F = fundamentalFromPoses(sequence.P0, sequence.poses[k - 1], sequence.poses[k]);
                    int consistent = 0, undecidable = 0;
                    for (const DMatch& match : matches)
                    {
                        verdicts.push_back(checkEpipolar(previous[m].lines[match.queryIdx], current.lines[match.trainIdx], F));
                        consistent += verdicts.back() == EPIPOLAR_CONSISTENT;
                        undecidable += verdicts.back() == EPIPOLAR_UNDECIDABLE;
                    }
                    run.decidedSum += (double)matches.size() - undecidable;
                    run.consistent.push_back(consistent);
                    run.undecidable.push_back(undecidable);
                    run.consistentSum += consistent;
                }
                addFrontEndDiagnostics(run, gray, previous[m], previousEligible[m], current, matches, verdicts, params);
            }
            run.tracks.addFrame(kept.size(), matches);
            previous[m] = current;
            const double minLength = params.minLengthIn(gray.size());
            previousEligible[m].clear();
            for (const Vec4f& l : detected)
                if (segmentLength(l) >= minLength)
                    previousEligible[m].push_back(l);
        }
    }
    std::cerr << "\n";

    size_t reference = methods.size();
    for (size_t m = 0; m < methods.size(); m++)
        if (methods[m].name == kFrontEndReference)
            reference = m;
    Table figures, why;
    figures.header = { "method", "lines detected", "lines kept", "matches" };
    if (withPoses)
        for (const char* h : { "consistent share (pooled)", "consistent matches", "undecidable matches" })
            figures.header.push_back(h);
    for (const std::string& h : { format("tracks >= %d frames", trackFrames), std::string("track length (frames, mean)"),
                                  std::string("detect ms"),
                                  std::string("keep ms"), std::string("computeLBD ms"),
                                  std::string("line_descriptor LBD ms"), std::string("match ms"),
                                  std::string("total ms"), std::string("total / ") + kFrontEndReference })
        figures.header.push_back(h);
    why.header = { "method", "kept lines without a candidate", "of them, one among all long-enough",
                   "nearest Hamming (median)", "below the gate", "longer half", "shorter half",
                   "higher contrast half", "lower contrast half", "length ratio of matches",
                   "of consistent matches", "endpoint shift px" };
    for (size_t m = 0; m < methods.size(); m++)
    {
        const FrontEndRun& run = runs[m];
        std::vector<std::string> row = { methods[m].name, format("%.0f", median(run.detected)),
                                         format("%.0f", median(run.kept)), format("%.0f", median(run.matches)) };
        if (withPoses)
        {
            row.push_back(format("%.3f", run.decidedSum > 0 ? run.consistentSum / run.decidedSum : 0.0));
            row.push_back(format("%.0f", median(run.consistent)));
            row.push_back(format("%.0f", median(run.undecidable)));
        }
        std::string ratio = "-";
        if (reference < methods.size())
        {
            std::vector<double> ratios;
            for (size_t k = 0; k < run.totalMs.size(); k++)
                if (runs[reference].totalMs[k] > 0)
                    ratios.push_back(run.totalMs[k] / runs[reference].totalMs[k]);
            ratio = format("%.2f", median(ratios));
        }
        for (const std::string& cell :
             { format("%d", run.tracks.atLeast(trackFrames)), format("%.2f", run.tracks.meanLength()),
               format("%.1f", median(run.detectMs)),
               format("%.2f", median(run.keepMs)), format("%.2f", median(run.lbd.computeLbd)),
               format("%.1f", median(run.lbd.lineDescriptor)),
               format("%.2f", median(run.matchMs)), format("%.1f", median(run.totalMs)), ratio })
            row.push_back(cell);
        figures.rows.push_back(row);

        const auto share = [](double part, double whole) { return format("%.3f", whole > 0 ? part / whole : 0.0); };
        why.rows.push_back({ methods[m].name, share(run.withoutCandidate, run.lines),
                             share(run.eligibleCandidate, run.withoutCandidate),
                             format("%.0f", median(run.nearestHamming)), share(run.belowGate, run.withCandidate),
                             share(run.halves[0][1][1], run.halves[0][1][0]), share(run.halves[0][0][1], run.halves[0][0][0]),
                             share(run.halves[1][1][1], run.halves[1][1][0]), share(run.halves[1][0][1], run.halves[1][0][0]),
                             format("%.3f", median(run.lengthRatio)),
                             withPoses ? format("%.3f", median(run.consistentLengthRatio)) : std::string("-"),
                             format("%.1f", median(run.endpointShift)) });
    }
    return { figures, why };
}
#endif

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
// The LBD mode: each method's lines of each image described by the module's computeLBD and by
// line_descriptor's BinaryDescriptor::compute, the same KeyLines, `repeats` times each in
// alternating order (their medians per image; the descriptors compared every time).
void printLbdNote(int repeats)
{
    std::cout << "LBD: each method's lines of each image (as KeyLines) described by computeLBD and by "
                 "line_descriptor's BinaryDescriptor::compute, " << repeats << " time(s) each, alternating, "
                 "the same descriptors; medians per image, then over images\n\n";
}

Table benchmarkLbd(const std::vector<LineMethod>& methods, const std::vector<String>& imagePaths, int repeats)
{
    Table table;
    table.header = { "method", "lines / image (median)", "computeLBD ms / image (median)",
                     "line_descriptor LBD ms / image (median)", "computeLBD / line_descriptor (median)" };
    std::vector<std::vector<double> > counts(methods.size()), ours(methods.size()), theirs(methods.size()),
        ratios(methods.size());
    for (const LineMethod& m : methods)
        m.reset();
    for (size_t k = 0; k < imagePaths.size(); k++)
    {
        std::cerr << "\r[lbd] image " << k + 1 << "/" << imagePaths.size() << std::flush;
        const Mat gray = imread(imagePaths[k], IMREAD_GRAYSCALE);
        CV_Assert(!gray.empty());
        for (size_t m = 0; m < methods.size(); m++)
        {
            std::vector<Vec4f> lines;
            methods[m].detect(gray, lines);
            LbdTimes times;
            for (int r = 0; r < repeats; r++)
                describeLinesTimed(gray, lines, times);
            counts[m].push_back((double)lines.size());
            ours[m].push_back(median(times.computeLbd));
            theirs[m].push_back(median(times.lineDescriptor));
            if (!lines.empty())
                ratios[m].push_back(ours[m].back() / theirs[m].back());
        }
    }
    std::cerr << "\n";
    for (size_t m = 0; m < methods.size(); m++)
        table.rows.push_back({ methods[m].name, format("%.0f", median(counts[m])), format("%.2f", median(ours[m])),
                               format("%.2f", median(theirs[m])), format("%.3f", median(ratios[m])) });
    return table;
}

Table benchmarkHomography(const std::vector<LineMethod>& methods, const std::vector<HomographyPair>& pairs,
                          const LineMatchOptions& matching, int repeats)
{
    Table table;
    table.header = { "method", "segments / image", "matches / pair", "correct / pair", "precision",
                     "repeatability", "localisation error (px)", "ms / image (median)",
                     "computeLBD ms / image (median)", "line_descriptor LBD ms / image (median)" };
    if (budgetColumn(matching))
        table.header.insert(table.header.begin() + 1, "lines / image (budget)");
    // Per budget b and method m, at b * methods.size() + m.
    const size_t runs = matching.budgets.size() * methods.size();
    std::vector<MatchTotals> totals(runs);
    std::vector<double> segments(runs, 0.0);
    std::vector<LbdTimes> lbd(runs);
    std::vector<std::vector<double> > ms(methods.size());
    for (size_t k = 0; k < pairs.size(); k++)
    {
        std::cerr << "\r[homography] pair " << k + 1 << "/" << pairs.size() << std::flush;
        const Mat gray1 = imread(pairs[k].image1Path, IMREAD_GRAYSCALE);
        const Mat gray2 = imread(pairs[k].image2Path, IMREAD_GRAYSCALE);
        CV_Assert(!gray1.empty() && !gray2.empty());
        for (size_t m = 0; m < methods.size(); m++)
        {
            std::vector<Vec4f> lines1, lines2;
            ms[m].push_back(timedDetect(methods[m], gray1, repeats, lines1, true));
            ms[m].push_back(timedDetect(methods[m], gray2, repeats, lines2, true));
            for (size_t b = 0; b < matching.budgets.size(); b++)
            {
                const size_t r = b * methods.size() + m;
                const std::vector<Vec4f> kept1 = budgetLines(methods[m], gray1, lines1, matching, matching.budgets[b]);
                const std::vector<Vec4f> kept2 = budgetLines(methods[m], gray2, lines2, matching, matching.budgets[b]);
                segments[r] += (double)(kept1.size() + kept2.size());
                const DescribedLines described1 = describeLinesTimed(gray1, kept1, lbd[r]);
                const DescribedLines described2 = describeLinesTimed(gray2, kept2, lbd[r]);
                const std::vector<DMatch> matches = matchLines(described1, described2, matching.params);
                totals[r].addHomography(
                    evaluateHomographyMatches(kept1, kept2, matches, pairs[k].H, gray1.size(), gray2.size()));
            }
        }
    }
    std::cerr << "\n";
    for (size_t b = 0; b < matching.budgets.size(); b++)
        for (size_t m = 0; m < methods.size(); m++)
        {
            const size_t r = b * methods.size() + m;
            const MatchTotals& t = totals[r];
            table.rows.push_back({ methods[m].name, format("%.1f", segments[r] / (2.0 * pairs.size())),
                                   format("%.1f", t.perPair(t.matches)), format("%.1f", t.perPair(t.correct)),
                                   format("%.3f", t.precision()), format("%.3f", t.visible > 0 ? t.repeated / t.visible : 0.0),
                                   format("%.2f", t.repeated > 0 ? t.errorSum / t.repeated : 0.0),
                                   format("%.1f", median(ms[m])), format("%.2f", median(lbd[r].computeLbd)),
                                   format("%.1f", median(lbd[r].lineDescriptor)) });
            if (budgetColumn(matching))
                table.rows.back().insert(table.rows.back().begin() + 1, format("%d", matching.budgets[b]));
        }
    return table;
}
#endif

#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
std::string featuresName(const PoseRow& row)
{
    switch (row.features)
    {
    case PoseFeatures::Points: return "points";
    case PoseFeatures::PointsAndLines: return "points + lines";
    default: return row.selection.byLength ? "lines, by length" : "lines";
    }
}

// The row of OpenCV's LSD that a row compares with: the same features, rank and budget (LSD's own
// rank is its length); null when there is none.
const PoseRow* lsdRowFor(const std::vector<PoseRow>& rows, const PoseRow& row)
{
    for (const PoseRow& r : rows)
        if (r.method == "LSD" && r.features == row.features && r.selection.budget == row.selection.budget)
            return &r;
    return nullptr;
}

std::string withInterval(const Vec3d& m, double scale, const char* fmt)
{
    const auto text = [&](double v) { return std::isinf(v) ? std::string("fail") : format(fmt, v * scale); };
    return text(m[0]) + " [" + text(m[1]) + ", " + text(m[2]) + "]";
}

// The pose table: per row, what its lines gave and the estimations' errors over pairs and seeds,
// compared pair by pair with OpenCV's LSD under the same budget.
Table poseTable(const std::vector<PoseRow>& rows, const PoseBenchmarkParams& params)
{
    Table table;
    table.header = { "method", "features", "budget", "lines / image", "3D lines / pair", "matches / pair",
                     "line matches the true pose fits", "matched line length, px (median)", "inliers (solved, mean)", "solved", "rotation error, deg (median [95 % CI])",
                     "translation error, % of step (median [95 % CI])", "success", "pose AUC", "AUC / LSD",
                     "wins : losses vs LSD (sign test p)", "ms / image (median)", "time / LSD (median)" };
    for (const PoseRow& row : rows)
    {
        std::vector<std::vector<double> > rotation, translation;
        double matches = 0, inliers = 0, score = 0;
        int solved = 0, successes = 0, trials = 0;
        for (const std::vector<PoseTrial>& pair : row.pairs)
        {
            rotation.emplace_back();
            translation.emplace_back();
            for (const PoseTrial& t : pair)
            {
                rotation.back().push_back(t.rotationError);
                translation.back().push_back(t.translationError);
                matches += t.lineCorrespondences + t.pointCorrespondences;
                solved += t.solved;
                inliers += t.solved ? t.inliers : 0;
                successes += t.rotationError < params.successRotation && t.translationError < params.successTranslation;
                score += poseScore(t, params);
                trials++;
            }
        }
        const PoseRow* lsd = lsdRowFor(rows, row);
        std::string versusAuc = "-", versus = "-", timeRatio = "-";
        if (lsd && lsd != &row)
        {
            int wins = 0, losses = 0;
            double lsdScore = 0;
            for (size_t k = 0; k < row.pairs.size(); k++)
                for (size_t s = 0; s < row.pairs[k].size(); s++)
                {
                    const double a = poseScore(row.pairs[k][s], params), b = poseScore(lsd->pairs[k][s], params);
                    wins += a > b;
                    losses += a < b;
                    lsdScore += b;
                }
            versusAuc = lsdScore > 0 ? format("%.2f", score / lsdScore) : std::string("-");
            versus = format("%d : %d (%.2g)", wins, losses, signTestP(wins, losses));
            if (!row.detectMs.empty() && lsd->detectMs.size() == row.detectMs.size())
            {
                std::vector<double> ratios;
                for (size_t k = 0; k < row.detectMs.size(); k++)
                    if (lsd->detectMs[k] > 0)
                        ratios.push_back(row.detectMs[k] / lsd->detectMs[k]);
                timeRatio = format("%.3f", median(ratios));
            }
        }
        const auto meanOf = [](const std::vector<double>& v) { return v.empty() ? 0.0 : mean(v)[0]; };
        table.rows.push_back({ row.method, featuresName(row),
                               row.features == PoseFeatures::Points ? std::string("-") : budgetName(row.selection.budget),
                               row.features == PoseFeatures::Points ? std::string("-") : format("%.1f", meanOf(row.linesPerImage)),
                               row.features == PoseFeatures::Points ? std::string("-") : format("%.1f", meanOf(row.liftedPerPair)),
                               format("%.1f", trials ? matches / trials : 0.0),
                               row.lineMatches ? format("%.2f", (double)row.trueLineInliers / row.lineMatches) : std::string("-"),
                               row.matchedLineLengths.empty() ? std::string("-") : format("%.0f", median(row.matchedLineLengths)),
                               solved ? format("%.1f", inliers / solved) : std::string("-"), format("%d/%d", solved, trials),
                               withInterval(medianWithInterval(rotation), 1.0, "%.3f"),
                               withInterval(medianWithInterval(translation), 100.0, "%.1f"),
                               format("%d/%d", successes, trials), format("%.3f", trials ? score / trials : 0.0), versusAuc,
                               versus, row.detectMs.empty() ? std::string("-") : format("%.1f", median(row.detectMs)),
                               timeRatio });
    }
    return table;
}
#endif

// Whether OpenCV reads the image; an unreadable one is reported, counted in skipped, and left out of the run.
bool readable(const std::string& path, size_t& skipped)
{
    if (!readGrayImage(path).empty())
        return true;
    reportSkipped(path);
    skipped++;
    return false;
}

int run(const AppOptions& args)
{
    const std::string dataset = args.oneOf("dataset", { "yorkurban", "sequence", "homography", "stereo", "multiview" });
    const String data = args.text("data");
    const std::string subset = args.oneOf("subset", { "all", "even", "odd" });
    const int repeats = args.integer("repeats", 1);
    const double longLength = args.number("long", 0, kUnbounded, true);
    const String csv = args.text("csv");
    const String chartPrefix = args.text("chart");
    LineMatchOptions matching;
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    matching.enabled = !args.has("no-match");
    matching.params.maxHamming = args.integer("max-hamming", 0, 256);
    matching.budgets = args.integers("top", 0);
    matching.rank = args.oneOf("rank", { "own", "length", "contrast" });
    PoseBenchmarkParams pose;
    pose.budgets = args.integers("budgets", 0);
    pose.seeds = args.integer("seeds", 1, 1000);
    pose.orbFeatures = args.integer("orb", 1);
    pose.pairs = args.integer("pairs", 0);
    pose.subset = subset == "all" ? -1 : subset == "odd";
    pose.maxHamming = args.integer("pose-hamming", 0, 256);
    const double scale = args.number("scale", 0, 1, true);
    if (dataset == "multiview")
    {
        // A relocalisation-like regime of wide baselines: looser limits than a stereo odometry step's.
        pose.rotationLimit = 2.0;
        pose.successRotation = 1.0;
    }
#else
    if (dataset == "homography" || dataset == "stereo" || dataset == "multiview")
        throw std::runtime_error("--dataset=" + dataset + " needs OpenCV's line_descriptor module, absent from this build");
#endif
    const bool frontEnd = args.has("frontend"), lbd = args.has("lbd");
    FrontEndParams frontEndParams;
    int trackFrames = 5;
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    if (frontEnd && dataset != "sequence")
        throw std::runtime_error("--frontend needs --dataset=sequence");
    frontEndParams.minLength = args.number("min-length", 0);
    frontEndParams.minLengthRatio = args.number("min-length-ratio", 0, 1);
    frontEndParams.maxLines = args.integer("max-lines", 0);
    frontEndParams.rankByLength = args.oneOf("frontend-rank", { "response", "length" }) == "length";
    frontEndParams.maxHamming = matching.params.maxHamming;
    frontEndParams.maxShift = args.number("max-shift", 0, kUnbounded, true);
    frontEndParams.maxAngle = args.number("max-angle", 0, CV_PI, true);
    trackFrames = args.integer("track-frames", 2);
    if (lbd && (frontEnd || dataset == "homography"))
        throw std::runtime_error("--lbd needs --dataset=yorkurban or sequence, without --frontend");
#else
    if (frontEnd || lbd)
        throw std::runtime_error("--frontend and --lbd need OpenCV's line_descriptor module, absent from this build");
#endif
    setNumThreads(args.integer("threads", 1, 1024));
    // Every option is checked before the first error is reported on the data.
    const FileStorage params = openParamsFile(args.text("params"));
    std::vector<LineMethod> methods;
    for (const std::string& name : splitList(args.text("methods")))
        methods.push_back(makeLineMethod(name, params.isOpened() && name == "lsdadvance" ? params.root() : FileNode()));
    if (methods.empty())
        throw std::runtime_error("--methods is empty; known: " + lineMethodList());
    checkOutputFolder("csv", csv);
    checkOutputFolder("chart", chartPrefix);

    const bool onePair = dataset == "homography" && data.empty();
    if (onePair && (!args.has("image1") || !args.has("image2") || !args.has("homography")))
        throw std::runtime_error("--dataset=homography needs --data=<HPatches folder>, or --image1, --image2 and "
                                 "--homography");
    const std::string expectedData = dataset == "yorkurban"  ? "YorkUrban-LineSegment (images/, gt/, list.txt)"
                                     : dataset == "sequence" ? "a sequence (image_l/, cam0/data/ or images)"
                                     : dataset == "stereo"   ? "a stereo sequence (image_l/, image_r/, calib.txt, poses.txt)"
                                     : dataset == "multiview" ? "a multi-view scene (images/, gt_dense_cameras/)"
                                                              : "an HPatches folder (1.ppm ... 6.ppm, H_1_2 ... H_1_6)";
    if (!onePair && data.empty())
        throw std::runtime_error("--data=<folder> is required for --dataset=" + dataset + ": " + expectedData);
    if (!data.empty() && !utils::fs::isDirectory(data))
        throw std::runtime_error("--data=" + data + ": no such folder; expected " + expectedData);

    Table table;
    std::string runInfo;  // the charts' subtitle
    size_t skipped = 0;   // unreadable image files left out
    if (dataset == "yorkurban")
    {
        std::vector<LabelledImage> all = loadYorkUrban(data), images;
        for (size_t k = 0; k < all.size(); k++)
            if ((subset == "all" || (subset == "even") == (k % 2 == 0)) && readable(all[k].imagePath, skipped))
                images.push_back(all[k]);
        if (images.empty())
            throw std::runtime_error("no readable image in " + data);
        std::cout << "YorkUrban: " << images.size() << " images (" << subset << ") from " << data
                  << ", structural protocol (1 px, 5 deg, 75% coverage, +0.5 px), " << getNumThreads()
                  << " thread(s), median of " << repeats << " run(s) per image"
                  << (skipped ? format(", %zu unreadable skipped", skipped) : std::string()) << "\n\n";
        runInfo = format("YorkUrban, %zu images (%s), %d thread(s)", images.size(), subset.c_str(), getNumThreads());
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
        if (lbd)
        {
            printLbdNote(repeats);
            std::vector<String> paths;
            for (const LabelledImage& image : images)
                paths.push_back(image.imagePath);
            table = benchmarkLbd(methods, paths, repeats);
        }
        else
#endif
            table = benchmarkYorkUrban(methods, images, repeats, longLength);
    }
    else if (dataset == "sequence")
    {
        const SequenceData all = loadSequence(data);
        SequenceData sequence = all;
        sequence.imagePaths.clear();
        sequence.poses.clear();
        for (size_t k = 0; k < all.imagePaths.size(); k++)
            if (readable(all.imagePaths[k], skipped))
            {
                sequence.imagePaths.push_back(all.imagePaths[k]);
                if (k < all.poses.size())
                    sequence.poses.push_back(all.poses[k]);
            }
        if (sequence.imagePaths.empty())
            throw std::runtime_error("no readable frame in " + data);
        std::cout << "Sequence: " << sequence.imagePaths.size() << " frames from " << data << ", "
                  << getNumThreads() << " thread(s), long = " << longLength << " px"
                  << (skipped ? format(", %zu unreadable skipped", skipped) : std::string()) << "\n\n";
        runInfo = format("%zu frames of %s, %d thread(s)", sequence.imagePaths.size(), data.c_str(), getNumThreads());
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
        if (frontEnd)
        {
            std::cout << format("Front end: lines of at least max(%g px, %g min(W, H)), the %d of highest %s (0: all), "
                                "LBD on them, one-way matching to the previous frame's with Hamming < %d, endpoint "
                                "shifts < %g px, angle < %g rad%s; medians per frame (matches: per pair); LBD "
                                "timed twice on the same lines, the module's computeLBD and line_descriptor's "
                                "BinaryDescriptor::compute (the same descriptors), the total with computeLBD for "
                                "LSDAdvance's lines and line_descriptor's for the others, as each front end runs\n\n",
                                frontEndParams.minLength, frontEndParams.minLengthRatio, frontEndParams.maxLines,
                                frontEndParams.rankByLength ? "length" : "response", frontEndParams.maxHamming,
                                frontEndParams.maxShift, frontEndParams.maxAngle,
                                args.has("clahe") ? "; frames equalised by CLAHE" : "");
            const std::pair<Table, Table> tables = benchmarkFrontEnd(methods, sequence, frontEndParams, trackFrames,
                                                                     args.has("clahe"));
            table = tables.first;
            table.print(std::cout);
            std::cout << "\nWhy lines do not match (pooled over the pairs; a candidate: a previous kept line within "
                         "the shift and angle gates; the halves: of the lines with a candidate, split at the frame's "
                         "median length or response / length; the shares: nearest LBD neighbour below the Hamming "
                         "gate):\n\n";
            tables.second.print(std::cout);
            if (!csv.empty())
                table.writeCsv(csv);
            return skipped == 0 ? 0 : kExitSkipped;
        }
#endif
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
        if (lbd)
        {
            printLbdNote(repeats);
            table = benchmarkLbd(methods, sequence.imagePaths, repeats);
        }
        else
#endif
            table = benchmarkSequence(methods, sequence, longLength, matching);
    }
#ifdef HAVE_OPENCV_LINE_DESCRIPTOR
    else if (dataset == "stereo" || dataset == "multiview")
    {
        std::vector<PoseRow> rows;
        std::string what;  // the run's first line, printed once it succeeded
        if (dataset == "stereo")
        {
            rows = runStereoPose(methods, loadSequence(data), pose);
            what = format("Stereo pose: %zu pairs of consecutive frames of %s", rows[0].pairs.size(), data.c_str());
        }
        else
        {
            rows = runMultiViewPose(methods, loadMultiView(data), scale, pose);
            what = format("Multi-view pose: %zu ordered triplets of consecutive views (each triplet in both orders) of %s at scale %g",
                          rows[0].pairs.size(), data.c_str(), scale);
        }
        if (rows[0].pairs.empty())
            throw std::runtime_error("--pairs and --subset leave no pair to estimate");
        if (subset != "all")
            what += format(" (the %s ones)", subset.c_str());
        std::cout << what << format(", %d RANSAC seed(s) per pair, %d thread(s); LBD mutual nearest neighbours (Hamming <= %d; "
                            "between the map's two views also within %g px of the epipolar band), ORB %d points "
                            "(Hamming <= %d); success: rotation < %g deg and translation < %g %% of the step; pose AUC: "
                            "the mean of 1 - min(1, max(rotation / %g deg, translation / %g %% of the step)), 0 when "
                            "not solved (doc/pose.md)\n\n",
                            pose.seeds, getNumThreads(), pose.maxHamming, pose.epipolarTolerance, pose.orbFeatures,
                            pose.orbMaxHamming, pose.successRotation, 100 * pose.successTranslation, pose.rotationLimit,
                            100 * pose.translationLimit);
        table = poseTable(rows, pose);
    }
    else
    {
        std::vector<HomographyPair> pairs;
        if (!onePair)
        {
            for (const HomographyPair& pair : loadHomographyPairs(data))
                if (readable(pair.image1Path, skipped) && readable(pair.image2Path, skipped))
                    pairs.push_back(pair);
        }
        else
        {
            HomographyPair pair;
            pair.H = readHomography(samples::findFile(args.text("homography"), true, true));
            pair.image1Path = samples::findFile(args.text("image1"), true, true);
            pair.image2Path = samples::findFile(args.text("image2"), true, true);
            for (const String& path : { pair.image1Path, pair.image2Path })
                if (readGrayImage(path).empty())
                    throw std::runtime_error("cannot read " + path + " as an image");
            pairs.push_back(pair);
        }
        if (pairs.empty())
            throw std::runtime_error("no readable image pair in " + data);
        std::cout << "Homography pairs: " << pairs.size() << " from " << (data.empty() ? pairs[0].image1Path : data)
                  << ", LBD, mutual nearest neighbours with Hamming distance <= " << matching.params.maxHamming
                  << ", correct within 3 px (doc/matching.md), " << getNumThreads() << " thread(s)"
                  << (skipped ? format(", %zu unreadable file(s) skipped", skipped) : std::string()) << "\n\n";
        runInfo = format("%zu homography pair(s), %d thread(s)", pairs.size(), getNumThreads());
        table = benchmarkHomography(methods, pairs, matching, repeats);
    }
#endif
    table.print(std::cout);
    if (!csv.empty())
        table.writeCsv(csv);
    if (!chartPrefix.empty())
        for (const std::string& file : writeCharts(table, chartPrefix, runInfo, longLength))
            std::cerr << "wrote " << file << "\n";
    return skipped == 0 ? 0 : kExitSkipped;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |            | print this help }"
        "{dataset  | yorkurban  | yorkurban (structural precision/recall), sequence (counts over frames, LBD matching "
                                  "of consecutive frames), homography (LBD matching of image pairs), stereo (the pose of "
                                  "frame t+1 from the lines of the stereo pair of frame t) or multiview (the pose of view "
                                  "i+2 from the lines of views i and i+1) }"
        "{data     |            | data folder: YorkUrban layout (images/, gt/), a sequence (image_l/, cam0/data/ or "
                                  "images; calib.txt + poses.txt for the epipolar check; image_r/ too for stereo), an HPatches folder (1.ppm..6.ppm, "
                                  "H_1_k) or a multi-view scene (images/, gt_dense_cameras/) }"
        "{image1   |            | homography without --data: the first image of one pair (OpenCV sample names are found) }"
        "{image2   |            | homography without --data: the second image }"
        "{homography |          | homography without --data: 3x3 matrix file from image1 to image2 (text, or OpenCV XML) }"
        "{max-hamming | 30      | LBD matching: largest Hamming distance of a kept mutual nearest neighbour (the front end: "
                                  "its matches are below it), 0 to 256 }"
        "{no-match |            | sequence: skip the LBD matching columns }"
        "{frontend |            | sequence: the front-end mode, what a point-line SLAM front end does per frame "
                                  "(keep lines by --min-length, --min-length-ratio and the budget --max-lines, LBD on "
                                  "them, one-way matching to the previous frame's under the gates --max-hamming "
                                  "(below it), --max-shift and --max-angle, tracks) }"
        "{lbd      |            | yorkurban or sequence: the LBD mode, each method's lines of each image described "
                                  "by the module's computeLBD and by line_descriptor's BinaryDescriptor::compute (the "
                                  "same KeyLines, --repeats times each, alternating; the descriptors compared), their "
                                  "times and the median over images of their ratio }"
        "{min-length | 0        | front end: lines shorter than this many px are dropped, >= 0 }"
        "{min-length-ratio | 0.125 | front end: and those shorter than this times min(W, H), in [0, 1] }"
        "{max-lines | 60        | front end: the budget, the lines of highest --frontend-rank kept per frame (0: all), >= 0 }"
        "{frontend-rank | response | front end: the rank of the budget, the same for every method: response "
                                  "(computeLineResponses, the brighter side taken as left) or length }"
        "{max-shift | 200       | front end: largest shift of each endpoint of a match, px, > 0 }"
        "{max-angle | 0.1       | front end: largest change of direction of a match, rad, in (0, 3.14159] }"
        "{clahe    |            | front end: equalise each frame with CLAHE (clip limit 3, 8 x 8 tiles) before detection "
                                  "and LBD, as PL-VINS does (outside the times) }"
        "{track-frames | 5      | front end: the tracks counted are those of at least this many frames, >= 2 }"
        "{budgets  | 60,100,150,0 | stereo, multiview: the line budgets of the pose rows, lines per image (0: all), "
                                  "comma-separated, each >= 0 }"
        "{pose-hamming | 60     | stereo, multiview: LBD matches are mutual nearest neighbours at most this far, 0 to 256 "
                                  "(the value that gives OpenCV's LSD its best poses on KITTI at 60 and 150 lines) }"
        "{seeds    | 3          | stereo, multiview: RANSAC seeds per pair, 1 to 1000 }"
        "{orb      | 500        | stereo, multiview: ORB points per image of the point rows, >= 1 }"
        "{pairs    | 0          | stereo, multiview: only the first N pairs (ordered triplets) (0: all), >= 0 }"
        "{scale    | 1          | multiview: the images and cameras scaled by this, in (0, 1] }"
        "{top      | 0          | LBD matching: each method matches only its N lines of highest response per image (0: all), >= 0; "
                                  "a comma-separated list gives one row per N and method }"
        "{rank     | own        | the response --top ranks by: own (each method's KeyLine response: LSDAdvance's "
                                  "computeLineResponses, the length for the others), length, or contrast "
                                  "(computeLineResponses for every method) }"
        "{methods  | lsd,fld,fld_merge,edlines,plvins,lsdadvance | comma-separated methods (LSDAdvance's variants: "
                                  "the files methods/<name>.yml) }"
        "{params   |            | YAML/XML of LSDAdvance parameters (write() or save()) for the lsdadvance method }"
        "{subset   | all        | yorkurban images (by index in list.txt), stereo pairs or multiview triplets (by their first frame or view) to use: all, even or odd }"
        "{repeats  | 1          | detections per image for the time (median), >= 1; with --lbd, descriptions by each LBD }"
        "{threads  | 1          | cv::setNumThreads for the whole run, 1 to 1024 (times in the tables are one core by default) }"
        "{long     | 60         | length in pixels from which a segment is long, > 0 }"
        "{csv      |            | also write the table to this CSV file }"
        "{chart    |            | also write the table as SVG bar charts <chart>_time.svg, <chart>_f.svg and "
                                  "<chart>_long.svg (those of the dataset's columns) }";
    const String about = "LSDAdvance benchmark, e.g. lsd_advance_benchmark --data=<YorkUrban folder>. Methods: " +
                         lineMethodList() +
                         ". Exit status: 0, 1 on an error, 2 when unreadable image files were left out.";
    return runApp(argc, argv, keys, about, { "no-match", "frontend", "clahe", "lbd" }, run);
}
