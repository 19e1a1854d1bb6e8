// TetGen in a child process bounded in memory and time (base/ChildProcess.h): its crashes,
// aborts, thrown ints and limits reached become InputErrors in the caller.
#pragma once
#include <string>
#include <vector>

#include "base/ChildProcess.h"
#include "tet/VolumeBoundary.h"

namespace tetglow {

// What TetGen hands back from the child process.
struct RawTets {
    std::vector<double> points;
    std::vector<int> tets, neighbours;
    // Per tet, with -A: the region of the inside point its cell holds + 1, or TetGen's own number.
    std::vector<double> attributes;
};

// The bounds of a child process that meshes a surface of `triangles` (TetGen, CGAL's
// autorefinement): half the machine's memory, and ten minutes plus a millisecond per triangle,
// which only a loop reaches (they take tens of microseconds per triangle, and the tet count is
// bounded by kMaxTets).
inline ChildLimits meshingLimits(size_t triangles) { return {defaultChildMemory(), 600 + 1e-3 * double(triangles)}; }

// Whether two of `points` lie nearer than TetGen's tolerance (1e-8 of their bounding diagonal,
// its -T; twice that here, to be safe). TetGen merges the second of such a pair into the first and
// drops it from its output, renumbering the points after it; runIsolated then keeps every point
// (-M0/1). A repaired surface has such pairs, valid for the exact predicates, where a crossing's
// exact point rounds to float beside a vertex of the input; a mesh without one keeps its switches
// and its tets.
bool hasCloseVertices(const std::vector<glm::dvec3>& points);

// TetGen died of a signal (1.5 fails assertions on some configurations of points and facets).
struct TetGenCrash : InputError {
    using InputError::InputError;
};

// TetGen on boundary.surface (and its inside points, with -A) under `switches`, in a forked child,
// stopped after `seconds` where that is positive and below meshingLimits'. Throws TetGenCrash when
// it dies of a signal, InputError for any other failure.
RawTets runIsolated(const VolumeBoundary& boundary, const std::string& switches, double seconds = 0);

}  // namespace tetglow
