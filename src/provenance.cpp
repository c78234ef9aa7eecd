// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Provenance: the base segments each returned line is made of (LSDAdvance::getLastSources),
// followed through the stages of a call.

#include "precomp.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

void SegmentProvenance::start(size_t baseCount)
{
    lineOf.resize(baseCount);
    for (size_t i = 0; i < baseCount; i++)
        lineOf[i] = (int)i;
}

void SegmentProvenance::followMerged(const std::vector<int>& mergedInto)
{
    for (int& k : lineOf)
        k = k < 0 ? -1 : mergedInto[k];
}

void SegmentProvenance::followKept(const std::vector<int>& keptFrom, size_t inputSize)
{
    into.assign(inputSize, -1);
    for (size_t j = 0; j < keptFrom.size(); j++)
        into[keptFrom[j]] = (int)j;
    followMerged(into);
}

void SegmentProvenance::sources(int lineCount, OutputArrayOfArrays out) const
{
    std::vector<int> count(lineCount, 0);
    for (int line : lineOf)
        if (line >= 0)
            count[line]++;
    out.create(lineCount, 1, CV_32S);
    std::vector<Mat> lists(lineCount);
    for (int j = 0; j < lineCount; j++)
    {
        out.create(count[j], 1, CV_32S, j);
        lists[j] = out.getMat(j);
        count[j] = 0;
    }
    for (size_t i = 0; i < lineOf.size(); i++)
    {
        const int j = lineOf[i];
        if (j >= 0)
            lists[j].at<int>(count[j]++) = (int)i;
    }
}

}}} // namespace cv::ximgproc::lsda
