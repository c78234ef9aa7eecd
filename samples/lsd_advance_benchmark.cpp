// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Benchmarks line detectors on real data, all in one run:
//  --dataset=yorkurban: structural AP / AR / F against YorkUrban-LineSegment ground truth,
//    segments per image, long-segment share and median time per image (the paper's Table 2);
//  --dataset=sequence: mean and standard deviation over frames of segments per frame,
//    long-segment share and time per frame (the paper's Table 1).
// Prints Markdown tables on stdout, optionally writes CSV, and reports progress on stderr.

#include "line_methods.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/lsd_advance/evaluation.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::ximgproc;

namespace {

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
        CV_Assert(out && "cannot write the CSV file");
        for (size_t i = 0; i < header.size(); i++)
            out << (i ? "," : "") << header[i];
        out << "\n";
        for (const auto& row : rows)
        {
            for (size_t i = 0; i < row.size(); i++)
                out << (i ? "," : "") << row[i];
            out << "\n";
        }
    }
};

Table benchmarkYorkUrban(const std::vector<LineMethod>& methods, const std::vector<LabelledImage>& images,
                         int repeats, double longLength)
{
    Table table;
    table.header = { "method", "AP", "AR", "F", "segments / image", "long share", "ms / image (median)" };
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
                               format("%.1f", median(ms[m])) });
    }
    return table;
}

Table benchmarkSequence(const std::vector<LineMethod>& methods, const std::vector<String>& frames, double longLength)
{
    Table table;
    table.header = { "method", "segments / frame (mean)", "segments / frame (std)", "long share (mean)",
                     "long share (std)", "ms / frame (mean)", "ms / frame (std)", "ms / frame (median)" };
    std::vector<std::vector<double> > counts(methods.size()), shares(methods.size()), ms(methods.size());
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
        }
    }
    std::cerr << "\n";
    for (size_t m = 0; m < methods.size(); m++)
    {
        double cm, cs, sm, ss, tm, ts;
        meanStd(counts[m], cm, cs);
        meanStd(shares[m], sm, ss);
        meanStd(ms[m], tm, ts);
        table.rows.push_back({ methods[m].name, format("%.1f", cm), format("%.1f", cs), format("%.3f", sm),
                               format("%.3f", ss), format("%.1f", tm), format("%.1f", ts),
                               format("%.1f", median(ms[m])) });
    }
    return table;
}

} // namespace

int main(int argc, char** argv)
{
    const String keys =
        "{help h   |            | print this help }"
        "{dataset  | yorkurban  | yorkurban (structural precision/recall) or sequence (counts over frames) }"
        "{data     |            | data folder: YorkUrban layout (images/, gt/) or a sequence (image_l/, cam0/data/ or images) }"
        "{methods  | lsd,fld,fld_merge,edlines,plvins,lsdadvance | comma-separated methods }"
        "{params   |            | YAML/XML of LSDAdvance parameters (write() or save()) for the lsdadvance method }"
        "{subset   | all        | yorkurban images to use: all, even or odd (by index in list.txt) }"
        "{repeats  | 1          | detections per image for the time (median) }"
        "{threads  | 1          | cv::setNumThreads for the whole run (times in the tables are one core by default) }"
        "{long     | 60         | length in pixels from which a segment is long }"
        "{csv      |            | also write the table to this CSV file }";
    CommandLineParser parser(argc, argv, keys);
    parser.about("LSDAdvance benchmark: " + std::string(lineMethodNames()));
    if (parser.has("help") || !parser.has("data"))
    {
        parser.printMessage();
        return parser.has("help") ? 0 : 1;
    }
    const std::string dataset = parser.get<std::string>("dataset");
    const String data = parser.get<String>("data");
    const std::string subset = parser.get<std::string>("subset");
    const String paramsPath = parser.get<String>("params");
    const int repeats = std::max(1, parser.get<int>("repeats"));
    const double longLength = parser.get<double>("long");
    const String csv = parser.get<String>("csv");
    setNumThreads(parser.get<int>("threads"));
    if (!parser.check())
    {
        parser.printErrors();
        return 1;
    }

    FileStorage params;
    if (!paramsPath.empty() && !params.open(paramsPath, FileStorage::READ))
    {
        std::cerr << "Cannot open " << paramsPath << std::endl;
        return 1;
    }
    std::vector<LineMethod> methods;
    for (const std::string& name : splitList(parser.get<std::string>("methods")))
        methods.push_back(makeLineMethod(name, params.isOpened() && name == "lsdadvance" ? params.root() : FileNode()));

    Table table;
    if (dataset == "yorkurban")
    {
        std::vector<LabelledImage> all = loadYorkUrban(data), images;
        for (size_t k = 0; k < all.size(); k++)
            if (subset == "all" || (subset == "even") == (k % 2 == 0))
                images.push_back(all[k]);
        std::cout << "YorkUrban: " << images.size() << " images (" << subset << ") from " << data
                  << ", structural protocol (1 px, 5 deg, 75% coverage, +0.5 px), " << getNumThreads()
                  << " thread(s), median of " << repeats << " run(s) per image\n\n";
        table = benchmarkYorkUrban(methods, images, repeats, longLength);
    }
    else if (dataset == "sequence")
    {
        const SequenceData sequence = loadSequence(data);
        std::cout << "Sequence: " << sequence.imagePaths.size() << " frames from " << data << ", "
                  << getNumThreads() << " thread(s), long = " << longLength << " px\n\n";
        table = benchmarkSequence(methods, sequence.imagePaths, longLength);
    }
    else
    {
        std::cerr << "Unknown dataset '" << dataset << "' (yorkurban or sequence)" << std::endl;
        return 1;
    }
    table.print(std::cout);
    if (!csv.empty())
        table.writeCsv(csv);
    return 0;
}
