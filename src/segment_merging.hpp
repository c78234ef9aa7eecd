// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stage 3's pruning machinery: the projection sweep that keeps merging near-linear, and the
// buffers merging reuses from group to group and from task to task. Internal to segment_merging.cpp and
// projection_sweep.cpp (the sweep), the
// implementation class (which owns a workspace) and the tests of the sweep.

#ifndef OPENCV_LSD_ADVANCE_SEGMENT_MERGING_HPP
#define OPENCV_LSD_ADVANCE_SEGMENT_MERGING_HPP

#include "stages.hpp"

namespace cv {
namespace ximgproc {
namespace lsda {

//! Rounding slack of the merging's pruning bounds: they may only ever let more pairs through.
inline double withSlack(double distance)
{
    return distance + 1e-9 * std::abs(distance) + 1e-6;
}

//! The segments of one group that may still fuse, filed by the start of their projection on a
//! fixed direction, in lanes across it (by the position of their midpoint along the normal),
//! with removal. Two segments are at least as far apart as their projections, and a segment
//! within a perpendicular distance of a base's line has its midpoint in the few lanes that line
//! crosses: merging looks at the segments of those lanes whose projections come near the base's,
//! never at the whole group. This keeps a group of thousands of collinear pieces, or of
//! hundreds of parallel ones (a textured facade), near-linear.
class ProjectionSweep
{
public:
    //! Files the segments geometry[ids[k]], projected on the unit vector direction, in lanes at
    //! least laneWidth px wide (wider when the group would need more lanes than segments).
    void build(const std::vector<Vec4f>& geometry, const std::vector<int>& ids, const Point2d& direction,
               double laneWidth);
    //! Interval [min, max] of the projection of a segment's endpoints on the direction.
    Vec2d project(const Vec4f& segment) const;
    //! Lanes [first, last] holding every segment whose midpoint projects into [low, high] and
    //! lies within maxOffset px of the line through base (all lanes for a point or a base
    //! steeper than 45 degrees to the direction).
    void lanesNear(const Vec4f& base, double low, double high, double maxOffset, int& first, int& last) const;
    //! Removes segment id (an index into geometry); it is no longer visited.
    void remove(int id);
    int lanes() const { return (int)laneStart.size() - 1; }
    //! Positions of lane l are laneBegin(l) .. laneEnd(l) - 1.
    int laneBegin(int lane) const { return laneStart[lane]; }
    int laneEnd(int lane) const { return laneStart[lane + 1]; }
    //! Position of the first segment of the lane, filed or removed, whose projection starts at or
    //! after value; laneEnd(lane) when none.
    int lowerBound(int lane, double value) const;
    //! The first filed position at or after position; at least the end of its lane when none.
    int filedFrom(int position) { return findNext(position); }
    //! The last filed position before position; below the beginning of its lane when none.
    int filedBefore(int position) { return findPrevious(position - 1); }
    int next(int position) { return findNext(position + 1); }
    int previous(int position) { return findPrevious(position - 1); }
    int id(int position) const { return ids[position]; }
    //! The segment filed at position, as it was filed (a filed segment does not change).
    const Vec4f& segment(int position) const { return segments[position]; }
    double start(int position) const { return starts[position]; }
    double end(int position) const { return ends[position]; }

private:
    // Defined here to be inlined: merging calls them for every segment it visits.
    int findNext(int p) { return findRoot(nextFiled.data(), p); }
    int findPrevious(int p) { return findRoot(previousFiled.data(), p + 1) - 1; }

    Point2d direction, normal;
    double laneOrigin = 0, laneSize = 1;
    std::vector<double> starts, ends;
    std::vector<int> ids;
    std::vector<Vec4f> segments;    //!< geometry of each position
    std::vector<int> laneStart;     //!< compressed rows: the positions of each lane
    std::vector<int> positionOf;    //!< position of each geometry index (-1: not filed)
    std::vector<int> nextFiled;     //!< union-find links to the next filed position (size() is a sentinel)
    std::vector<int> previousFiled; //!< the same backwards, shifted by one (0 is a sentinel)
    std::vector<std::pair<std::pair<int, double>, int> > sortBuffer;
    std::vector<double> across;
};

struct MergeCandidate
{
    double score;
    int segment;   //!< index into the group's members
    int baseline;  //!< index into the group's members; -1 for none
};

//! Buffers of the merging of one group, reused from group to group and call to call.
struct GroupWorkspace
{
    std::vector<Vec4f> geometry;  //!< the current group's segments, fused in place
    std::vector<char> consumed;
    std::vector<int> fusedInto;   //!< the segment each consumed one was fused into
    std::vector<int> outputOf;    //!< index in the merged output of each surviving segment
    std::vector<double> length;
    std::vector<std::pair<double, int> > byLength;  //!< (-length, index) of each segment
    std::vector<int> order, rank, ids;
    std::vector<double> ranked[4];  //!< x0, y0, x1, y1 of segment order[k] as it was in the input
    std::vector<int> baselines, pending, changed;
    std::vector<char> dirty, isChanged;
    std::vector<MergeCandidate> candidates, bestOf;
    std::vector<std::pair<double, int> > baselineStarts;
    ProjectionSweep sweep;
};

//! Buffers of stage 3, reused from call to call: the groups are merged in tasks of consecutive
//! groups (laid out from the groups alone), each with its own GroupWorkspace, into the places of
//! their members; the survivors are then gathered in group order.
struct MergeWorkspace
{
    TaskLayout tasks;                  //!< consecutive groups, by their members
    std::vector<GroupWorkspace> taskWorkspaces;
    std::vector<Vec4f> placed;         //!< the survivors of each group, from its first member's place
    std::vector<int> survivors;        //!< per group
    std::vector<int> outputIndex;      //!< index in the merged output of each place
};

}}} // namespace cv::ximgproc::lsda

#endif
