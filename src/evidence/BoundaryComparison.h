// Where is the medium? The exact tets against the parity baseline's test and the bounding box, on
// the same points and the same rays: error against a ground truth and time per query. The
// truth is the tets by default; the tests give an analytic shape instead.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tet/TetTraversal.h"

namespace tetglow {

// An inside test under comparison.
struct InsideTest {
    std::string name;
    std::function<bool(const glm::dvec3&)> inside;
};

// The truth for a point, or nothing where it is not to be scored (an analytic shape's facet gap).
using InsideTruth = std::function<std::optional<bool>(const glm::dvec3&)>;

// tets (when `tets` is given: locate from the start grid, exact), parity with 1, 3 and 5 rays
// (majority), and `box` (inside the bounding box).
std::vector<InsideTest> insideTests(const TetTraversal* tets, const SurfaceBVH& bvh, const Bounds3& box);

// Random points: offset 0 is the whole bounding box of `surface`; offset s > 0 is the shell
// reached from a point uniform on the surface (by area) along its face normal, outwards or
// inwards with equal odds, by s diagonals.
struct PointRegion {
    double offset = 0;
    std::vector<glm::dvec3> points;
};
std::vector<PointRegion> samplePoints(const TriangleMesh& surface, const std::vector<double>& offsets, size_t perRegion,
                                      uint64_t seed);

struct ClassificationScore {
    std::string method;
    size_t errors = 0;
    double secondsPerQuery = 0;  // one thread, every point of the region
};
struct ClassificationRow {
    double offset = 0;
    size_t scored = 0, inside = 0;  // points the truth scores, and how many of them are inside
    std::vector<ClassificationScore> methods;
};
std::vector<ClassificationRow> compareClassification(const std::vector<PointRegion>& regions,
                                                     const std::vector<InsideTest>& tests, const InsideTruth& truth);

// A line across the bounding box: [t0, t1] is the part inside it; u is the march's random offset.
struct Line {
    Ray ray;
    double t0, t1, u;
};
std::vector<Line> sampleLines(const Bounds3& box, size_t count, uint64_t seed);

// A way to measure the medium's length along a line (optical depth over sigma_t).
struct ChordTest {
    std::string name;
    double step = 0;  // the march's step; 0 for the others
    std::function<double(const Line&)> length;
};

// tets (the walk's segments, exact), the parity baseline's march (1 parity ray per step, each step's
// sample standing for the whole step) at each step, and `box` (the whole box is medium).
std::vector<ChordTest> chordTests(const TetTraversal* tets, const SurfaceBVH& bvh, const std::vector<double>& steps);
double tetChord(const TetTraversal& tets, const Line& line);

struct ChordScore {
    std::string method;
    double step = 0;
    double meanAbsError = 0, maxAbsError = 0, meanError = 0;  // length units; meanError is the bias
    double relativeError = 0;                                 // sum |error| / sum of true lengths
    double secondsPerRay = 0;
};
struct ChordTable {
    size_t lines = 0, crossing = 0;  // crossing: lines whose true length is > 0
    double meanLength = 0;           // true length, over all lines
    std::vector<ChordScore> methods;
};
ChordTable compareChords(const std::vector<Line>& lines, const std::vector<ChordTest>& tests,
                         const std::function<double(const Line&)>& truth);

struct ComparisonOptions {
    size_t points = 20000;  // per region
    size_t rays = 2000;
    std::vector<double> shells{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};  // diagonals from the surface
    std::vector<double> steps;  // march steps, world units; empty: diagonal / 20, / 100, / 500
    uint64_t seed = 1;
};

struct BoundaryComparison {
    std::vector<ClassificationRow> classification;  // the bounding box first, then the shells
    ChordTable chords;
};

// Every method against the tets. With `input` (a broken mesh the tets repaired), the parity
// tests use the input as it was, and the input's winding number (> 1/2) joins them.
BoundaryComparison compareBoundary(const TetTraversal& volume, const ComparisonOptions& options,
                                   const TriangleMesh* input = nullptr);

}  // namespace tetglow
