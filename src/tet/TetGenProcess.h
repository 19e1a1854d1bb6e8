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

// TetGen died of a signal (1.5 fails assertions on some configurations of points and facets).
struct TetGenCrash : InputError {
    using InputError::InputError;
};

// TetGen on boundary.surface (and its inside points, with -A) under `switches`, in a forked child.
// Throws TetGenCrash when it dies of a signal, InputError for any other failure.
RawTets runIsolated(const VolumeBoundary& boundary, const std::string& switches);

}  // namespace tetglow
