// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The stage trace: the base segments each returned line is made of (LSDAdvance::getLastSources)
// and the responses known so far, followed through the stages of a call.

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
    // The base segments of each line in increasing order (compressed rows; those of no line in a
    // last row).
    std::vector<int> rowStart, order(lineOf.size());
    compressRows((int)lineOf.size(), lineCount + 1, [&](int i) { return lineOf[i] < 0 ? lineCount : lineOf[i]; },
                 rowStart, [&](int i, int k) { order[k] = i; });
    out.create(lineCount, 1, CV_32S);
    for (int j = 0; j < lineCount; j++)
    {
        const int count = rowStart[j + 1] - rowStart[j];
        out.create(count, 1, CV_32S, j);
        if (count > 0)
            std::copy(order.begin() + rowStart[j], order.begin() + rowStart[j + 1], out.getMat(j).ptr<int>());
    }
}

void StageTrace::start(const std::vector<Vec4f>& base)
{
    provenance.start(base.size());
    responses.clear();
}

void StageTrace::followKept(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out,
                            const std::vector<int>& keptFrom)
{
    provenance.followKept(keptFrom, in.size());
    responses.followKept(in, out, keptFrom);
}

void StageTrace::followMerged(const std::vector<Vec4f>& in, const std::vector<Vec4f>& out,
                              const std::vector<int>& mergedInto)
{
    provenance.followMerged(mergedInto);
    responses.followMerged(in, out, mergedInto);
}

void StageTrace::followSelected(const std::vector<int>& keptFrom, size_t inputSize)
{
    provenance.followKept(keptFrom, inputSize);
    responses.clear();
}

}}} // namespace cv::ximgproc::lsda
