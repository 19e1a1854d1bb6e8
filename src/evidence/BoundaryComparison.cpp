#include "evidence/BoundaryComparison.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "integrators/MarchStep.h"
#include "sampling/Rng.h"
#include "sampling/Sampling.h"
#include "tet/WindingNumber.h"

namespace tetglow {

namespace {

// Runs f(i) for i in [0, n) and returns the seconds per call.
template <class F>
double timePerCall(size_t n, F&& f) {
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < n; ++i) f(i);
    return n ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / double(n) : 0;
}

}  // namespace

std::vector<InsideTest> insideTests(const TetTraversal* tets, const SurfaceBVH& bvh, const Bounds3& box) {
    std::vector<InsideTest> tests;
    if (tets) tests.push_back({"tets", [tets](const glm::dvec3& p) { return tets->locate(p) >= 0; }});
    for (int rays : {1, 3, 5})
        tests.push_back({"parity " + std::to_string(rays),
                         [&bvh, rays](const glm::dvec3& p) { return insideByParity(bvh, p, rays); }});
    tests.push_back({"bbox", [box](const glm::dvec3& p) { return box.contains(p); }});
    return tests;
}

std::vector<PointRegion> samplePoints(const TriangleMesh& surface, const std::vector<double>& offsets, size_t perRegion,
                                      uint64_t seed) {
    const Bounds3 box = bounds(surface);
    const double diagonal = box.diagonal();
    std::vector<double> cdf;  // triangle areas, summed
    double area = 0;
    for (uint32_t t = 0; t < surface.triangles.size(); ++t)
        cdf.push_back(area += glm::length(glm::cross(surface.corner(t, 1) - surface.corner(t, 0),
                                                     surface.corner(t, 2) - surface.corner(t, 0))));
    std::vector<PointRegion> regions;
    for (size_t r = 0; r <= offsets.size(); ++r) {
        PointRegion region;
        region.offset = r ? offsets[r - 1] : 0;
        for (size_t i = 0; i < perRegion; ++i) {
            Rng rng(seed, i, r);
            const glm::dvec3 u(rng.uniform(), rng.uniform(), rng.uniform());
            if (r == 0) {
                region.points.push_back(box.lo + (box.hi - box.lo) * u);
                continue;
            }
            const auto t = uint32_t(sampleCdf(cdf, u.x));
            const glm::dvec2 b = sampleUniformTriangle({u.y, u.z});
            const glm::dvec3 a = surface.corner(t, 0), e1 = surface.corner(t, 1) - a, e2 = surface.corner(t, 2) - a;
            const double side = rng.uniform() < 0.5 ? -1 : 1;
            region.points.push_back(a + b.x * e1 + b.y * e2 +
                                    glm::normalize(glm::cross(e1, e2)) * (side * region.offset * diagonal));
        }
        regions.push_back(std::move(region));
    }
    return regions;
}

std::vector<ClassificationRow> compareClassification(const std::vector<PointRegion>& regions,
                                                     const std::vector<InsideTest>& tests, const InsideTruth& truth) {
    std::vector<ClassificationRow> rows;
    for (const auto& region : regions) {
        ClassificationRow row;
        row.offset = region.offset;
        const size_t n = region.points.size();
        std::vector<std::optional<bool>> expected(n);
        for (size_t i = 0; i < n; ++i) {
            expected[i] = truth(region.points[i]);
            row.scored += expected[i].has_value();
            row.inside += expected[i].value_or(false);
        }
        std::vector<char> answer(n);
        for (const auto& test : tests) {
            ClassificationScore score{test.name};
            score.secondsPerQuery = timePerCall(n, [&](size_t i) { answer[i] = test.inside(region.points[i]); });
            for (size_t i = 0; i < n; ++i) score.errors += expected[i] && *expected[i] != bool(answer[i]);
            row.methods.push_back(score);
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<Line> sampleLines(const Bounds3& box, size_t count, uint64_t seed) {
    std::vector<Line> lines;
    const double diagonal = box.diagonal();
    for (size_t i = 0; i < count; ++i) {
        Rng rng(seed, i, 1u << 20);
        const glm::dvec3 u(rng.uniform(), rng.uniform(), rng.uniform());
        const glm::dvec3 target = box.lo + (box.hi - box.lo) * u;
        const glm::dvec3 d = sampleUniformSphere({rng.uniform(), rng.uniform()});
        // The origin lies a diagonal outside the box, so every walk starts outside the medium.
        Line line{Ray{target - d * diagonal, d}, 0, INFINITY, rng.uniform()};
        if (clip(box, line.ray, line.t0, line.t1)) lines.push_back(line);
    }
    return lines;
}

double tetChord(const TetTraversal& tets, const Line& line) {
    double length = 0;
    tets.traverse(
        line.ray, 0, INFINITY,
        [&](const WalkSegment& s) {
            length += s.tOut - s.tIn;
            return true;
        },
        TetTraversal::kOutside);
    return length;
}

std::vector<ChordTest> chordTests(const TetTraversal* tets, const SurfaceBVH& bvh, const std::vector<double>& steps) {
    std::vector<ChordTest> tests;
    if (tets) tests.push_back({"tets", 0, [tets](const Line& line) { return tetChord(*tets, line); }});
    for (double h : steps)
        tests.push_back({"parity march", h, [&bvh, h](const Line& line) {
                             double length = 0;
                             for (double t = line.t0 + line.u * h; t < line.t1; t += h)
                                 if (insideByParity(bvh, line.ray.at(t), 1)) length += h;
                             return length;
                         }});
    tests.push_back({"bbox", 0, [](const Line& line) { return line.t1 - line.t0; }});
    return tests;
}

ChordTable compareChords(const std::vector<Line>& lines, const std::vector<ChordTest>& tests,
                         const std::function<double(const Line&)>& truth) {
    ChordTable table;
    table.lines = lines.size();
    std::vector<double> expected(lines.size()), measured(lines.size());
    double total = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        expected[i] = truth(lines[i]);
        table.crossing += expected[i] > 0;
        total += expected[i];
    }
    const double n = std::max<double>(1, double(lines.size()));
    table.meanLength = total / n;
    for (const auto& test : tests) {
        ChordScore score{test.name, test.step};
        score.secondsPerRay = timePerCall(lines.size(), [&](size_t i) { measured[i] = test.length(lines[i]); });
        double sumAbs = 0, sum = 0;
        for (size_t i = 0; i < lines.size(); ++i) {
            const double e = measured[i] - expected[i];
            sumAbs += std::abs(e);
            sum += e;
            score.maxAbsError = std::max(score.maxAbsError, std::abs(e));
        }
        score.meanAbsError = sumAbs / n;
        score.meanError = sum / n;
        score.relativeError = total > 0 ? sumAbs / total : 0;
        table.methods.push_back(score);
    }
    return table;
}

BoundaryComparison compareBoundary(const TetTraversal& volume, const ComparisonOptions& options,
                                   const TriangleMesh* input) {
    const TriangleMesh surface = volume.mesh().surfaceMesh();
    const Bounds3& box = volume.bounds();
    // A repaired mesh: parity on the input as it was, beside its winding number.
    std::unique_ptr<SurfaceBVH> inputBvh =
        input ? std::make_unique<SurfaceBVH>(input->positions, input->triangles) : nullptr;
    const SurfaceBVH& bvh = inputBvh ? *inputBvh : volume.bvh();
    auto tests = insideTests(&volume, bvh, box);
    std::unique_ptr<WindingNumber> winding = input ? std::make_unique<WindingNumber>(*input) : nullptr;
    if (winding)
        tests.push_back({"winding number", [&winding](const glm::dvec3& p) { return winding->classify(p) > 0.5; }});
    BoundaryComparison result;
    result.classification =
        compareClassification(samplePoints(surface, options.shells, options.points, options.seed), tests,
                              [&](const glm::dvec3& p) { return std::optional(volume.locate(p) >= 0); });
    std::vector<double> steps = options.steps;
    if (steps.empty())
        for (double fraction : {1.0 / 20, 1.0 / 100, 1.0 / 500}) steps.push_back(fraction * box.diagonal());
    for (double h : steps)
        checkMarchStep("--steps", h, box.diagonal(), resolutionOf(box, box.lo));  // lines within the box
    result.chords = compareChords(sampleLines(box, options.rays, options.seed), chordTests(&volume, bvh, steps),
                                  [&](const Line& line) { return tetChord(volume, line); });
    return result;
}

}  // namespace tetglow
