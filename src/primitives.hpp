// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The primitives that several stages share, written once: the layout of the tasks of a
// cv::parallel_for_ (TaskLayout, runTasks), union-find (findRoot, UnionFind) and compressed rows
// (compressRows: a stable counting sort). Each is header-only, so that it inlines where it is hot.

#ifndef OPENCV_LSD_ADVANCE_PRIMITIVES_HPP
#define OPENCV_LSD_ADVANCE_PRIMITIVES_HPP

#include "opencv2/core.hpp"
#include "opencv2/core/utility.hpp"
#include "opencv2/core/hal/intrin.hpp"
#include <algorithm>
#include <vector>

// LSD_ADVANCE_SCALAR (CMake option of the same name; scripts/check_scalar.sh, run by CI): the
// module's universal-intrinsics paths compiled out, every `#if CV_SIMD128` taking its scalar
// `#else`, as on a platform without them. Debian's OpenCV headers set CV_SIMD128 from the
// compiler's target (__SSE2__, always there on x86-64), whatever CV_DISABLE_OPTIMIZATION says:
// the switch is made here, after them, and every source file of the module sees it first (through
// precomp.hpp, or stages.hpp for the tests).
#ifdef LSD_ADVANCE_SCALAR
#undef CV_SIMD128
#define CV_SIMD128 0
#undef CV_SIMD128_64F
#define CV_SIMD128_64F 0
#endif

namespace cv {
namespace ximgproc {
namespace lsda {

/** @brief The tasks of a cv::parallel_for_: consecutive ranges of items, laid out from the items
alone and never from the number of threads.

What a task computes must not depend on the layout (so that results do not depend on the thread
count); the layout only sets the grain: a task of too little work costs the pool more than it
does. A layout kept from call to call allocates nothing once warm. Usage:
@code
    TaskLayout tasks;                                        // a member: reused by every call
    tasks.evenly(rows, 16);                                  // or, by the work of each item:
    tasks.byWeight(groups, 64, [&](int g) { return size[g]; });
    runTasks(tasks, [&](int task, const Range& items) {      // task: for a buffer per task
        for (int i = items.start; i < items.end; i++)
            work(i);
    });
@endcode */
class TaskLayout
{
public:
    //! Tasks of perTask (>= 1) items each, the last one of the rest; none for no item.
    void evenly(int items, int perTask)
    {
        CV_DbgAssert(perTask >= 1 && items >= 0);
        itemCount = items;
        evenSize = perTask;
        start.clear();
    }
    //! Consecutive items, a task closed once its items weigh at least minWeight together (weightOf(i)
    //! is item i's work, e.g. its pixels or segments); none for no item.
    template <typename WeightOf>
    void byWeight(int items, int minWeight, WeightOf weightOf)
    {
        itemCount = items;
        evenSize = 0;
        start.clear();
        int weight = 0;
        for (int i = 0; i < items; i++)
        {
            if (start.empty() || weight >= minWeight)
            {
                start.push_back(i);
                weight = 0;
            }
            weight += weightOf(i);
        }
        start.push_back(items);
    }
    int count() const
    {
        return evenSize > 0 ? (itemCount + evenSize - 1) / evenSize : (int)start.size() - 1;
    }
    //! The items of a task.
    Range items(int task) const
    {
        if (evenSize > 0)
            return Range(task * evenSize, std::min(itemCount, (task + 1) * evenSize));
        return Range(start[task], start[task + 1]);
    }

private:
    int itemCount = 0, evenSize = 1;
    std::vector<int> start;  //!< the first item of each task, and the count at the end (byWeight)
};

//! Whether the module's vector paths were compiled (CV_SIMD128; false in the LSD_ADVANCE_SCALAR build).
CV_EXPORTS bool compiledWithUniversalIntrinsics();

//! Rows of an image per task of a pass over its rows (the gradient, the smoothing at scale 1): a
//! row is a few microseconds of work.
constexpr int kImageRowsPerTask = 16;

//! The loop body of runTasks (a template rather than a std::function, which would allocate).
template <typename Body>
class TaskLoop CV_FINAL : public ParallelLoopBody
{
public:
    TaskLoop(const TaskLayout& layout_, const Body& body_) : layout(layout_), body(body_) {}
    void operator()(const Range& tasks) const CV_OVERRIDE
    {
        for (int t = tasks.start; t < tasks.end; t++)
            body(t, layout.items(t));
    }

private:
    const TaskLayout& layout;
    const Body& body;
};

//! Runs body(task, items) for every task of the layout in cv::parallel_for_, one stripe per task.
template <typename Body>
void runTasks(const TaskLayout& layout, const Body& body)
{
    const int tasks = layout.count();
    if (tasks > 0)
        parallel_for_(Range(0, tasks), TaskLoop<Body>(layout, body), tasks);
}

//! The root of i in a union-find forest (parent[r] == r at a root), halving the path on the way.
inline int findRoot(int* parent, int i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

//! Union-find over 0..n-1 whose root is always the smallest index of its set, so that what is
//! numbered by root does not depend on the order in which the unions came.
class UnionFind
{
public:
    void reset(int n)
    {
        parent.resize(n);
        for (int i = 0; i < n; i++)
            parent[i] = i;
    }
    int find(int i) { return findRoot(parent.data(), i); }
    //! Points a, b and their roots at the smaller root, without a branch on the depth of the trees
    //! where it can: two hops reach the root of nearly every item when the unions point both items
    //! at it.
    void unite(int a, int b)
    {
        int* const p = parent.data();
        int rootA = p[p[a]], rootB = p[p[b]];
        if (p[rootA] != rootA || p[rootB] != rootB)
        {
            rootA = findRoot(p, rootA);
            rootB = findRoot(p, rootB);
        }
        const int root = std::min(rootA, rootB);
        p[std::max(rootA, rootB)] = root;
        p[a] = root;
        p[b] = root;
    }

private:
    std::vector<int> parent;
};

//! values[i] becomes values[0] + ... + values[i], four at a time.
inline void runningSum(int* values, int count)
{
    int i = 0, sum = 0;
#if CV_SIMD128
    v_int32x4 carry = v_setzero_s32();
    for (; i + 4 <= count; i += 4)
    {
        v_int32x4 v = v_load(values + i);
        v = v + v_rotate_left<1>(v);
        v = v + v_rotate_left<2>(v) + carry;
        v_store(values + i, v);
        carry = v_broadcast_element<3>(v);
    }
    sum = v_extract_n<3>(carry);
#endif
    for (; i < count; i++)
    {
        sum += values[i];
        values[i] = sum;
    }
}

/** @brief Compressed rows of items by key (a stable counting sort).
@param count items 0..count-1.
@param keys keys 0..keys-1; keyOf(i) is item i's (called twice per item).
@param rowStart output, keys + 1 entries: row k holds the positions [rowStart[k], rowStart[k + 1]).
@param place place(i, position) puts item i at its position: rows in increasing key, items of a row
in increasing order. */
template <typename KeyOf, typename Place>
void compressRows(int count, int keys, KeyOf keyOf, std::vector<int>& rowStart, Place place)
{
    // The count of key k at k + 2 and their running sum; each item then filed at the start of its
    // row, kept at k + 1 and moved on, which leaves the start of row k at k.
    rowStart.assign((size_t)keys + 2, 0);
    int* const start = rowStart.data();
    for (int i = 0; i < count; i++)
        start[keyOf(i) + 2]++;
    runningSum(start + 2, keys);
    for (int i = 0; i < count; i++)
        place(i, start[keyOf(i) + 1]++);
    rowStart.pop_back();
}

}}} // namespace cv::ximgproc::lsda

#endif
