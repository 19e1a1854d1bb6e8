#include "tet/InteriorRepair.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "tet/HoleLattice.h"
#include "tet/InsideLabels.h"
#include "tet/IntersectionResolution.h"
#include "tet/PartWinding.h"
#include "tet/Predicates.h"
#include "tet/RepairClock.h"
#include "tet/SelfIntersection.h"
#include "tet/ShellNesting.h"
#include "tet/TetGenProcess.h"
#include "tet/VolumeBoundary.h"
#include "tet/WindingGrid.h"
#include "tet/WindingNumber.h"

namespace tetglow {
namespace {

void keep(std::vector<glm::dvec3>& list, const glm::dvec3& p) {
    if (list.size() < RepairReport::kMaxPositions) list.push_back(p);
}

double area(const TriangleMesh& m, uint32_t t) {
    return 0.5 * glm::length(glm::cross(m.corner(t, 1) - m.corner(t, 0), m.corner(t, 2) - m.corner(t, 0)));
}

glm::dvec3 centroid(const TriangleMesh& m, uint32_t t) {
    return (m.corner(t, 0) + m.corner(t, 1) + m.corner(t, 2)) / 3.0;
}

// Consistent winding across every edge that two triangles share (a patch), keeping the winding
// of the larger area of each patch. Patches that meet only at non-manifold edges or cross keep
// their own winding. A closed patch (each of its edges shared by two of its triangles) takes the
// winding of the outermost closed patch around it, turned outward, as on the exact path (a part
// wound inward throughout is the same solid; one wound against the part around it is its
// cavity); the open patches are turned outward together (positive volume), and a closed patch
// that lies inside them (their winding number above 1/2) keeps its winding against them.
// Returns which triangles belong to closed patches.
std::vector<char> orientPatches(TriangleMesh& soup, const EdgeMap& edges, RepairReport& report) {
    const size_t n = soup.triangles.size();
    std::vector<char> flipped(n, 0), visited(n, 0), closed(n, 0);
    std::vector<uint32_t> stack;
    std::vector<std::vector<uint32_t>> patches;
    std::vector<char> patchClosed;
    const auto flip = [&](uint32_t t) {
        std::swap(soup.triangles[t][1], soup.triangles[t][2]);
        flipped[t] ^= 1;
    };
    for (uint32_t start = 0; start < n; ++start) {
        if (visited[start]) continue;
        visited[start] = 1;
        stack = {start};
        std::vector<uint32_t> patch;
        bool isClosed = true;
        double flippedArea = 0, keptArea = 0;
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            patch.push_back(t);
            (flipped[t] ? flippedArea : keptArea) += area(soup, t);
            const auto& f = soup.triangles[t];
            for (int k = 0; k < 3; ++k) {
                const auto& users = edges.at(edgeKey(f[k], f[(k + 1) % 3]));
                if (users.size() != 2) {
                    isClosed = false;
                    continue;
                }
                const uint32_t other = users[0] == t ? users[1] : users[0];
                if (visited[other]) continue;
                visited[other] = 1;
                // Consistent neighbours traverse the shared edge in opposite directions.
                if (traverses(soup.triangles[other], f[k], f[(k + 1) % 3])) {
                    std::swap(soup.triangles[other][1], soup.triangles[other][2]);
                    flipped[other] = 1;
                }
                stack.push_back(other);
            }
        }
        if (flippedArea > keptArea)
            for (uint32_t t : patch) flip(t);
        for (uint32_t t : patch) closed[t] = isClosed;
        patches.push_back(std::move(patch));
        patchClosed.push_back(isClosed);
    }
    TriangleMesh open = soup;
    open.triangles.clear();
    for (uint32_t t = 0; t < n; ++t)
        if (!closed[t]) open.triangles.push_back(soup.triangles[t]);
    if (signedVolume(open) < 0) {
        for (uint32_t t = 0; t < n; ++t)
            if (!closed[t]) flip(t);
        for (auto& f : open.triangles) std::swap(f[1], f[2]);
    }
    std::vector<std::vector<uint32_t>> shells;
    std::vector<double> volume;
    for (size_t i = 0; i < patches.size(); ++i)
        if (patchClosed[i]) {
            shells.push_back(patches[i]);
            double v = 0;
            const glm::dvec3 o = soup.corner(patches[i][0], 0);
            for (uint32_t t : patches[i])
                v += glm::dot(soup.corner(t, 0) - o, glm::cross(soup.corner(t, 1) - o, soup.corner(t, 2) - o));
            volume.push_back(v);
        }
    const auto containers = containingShells(soup, shells);
    const WindingNumber openWinding(open);
    for (size_t s = 0; s < shells.size(); ++s) {
        size_t outermost = s;
        for (uint32_t o : containers[s])
            if (std::abs(volume[o]) > std::abs(volume[outermost])) outermost = o;
        const uint32_t t = shells[outermost][0];
        if (std::abs(openWinding.approximate(centroid(soup, t))) > 0.5) continue;  // wound against the open parts
        if (volume[outermost] < 0)
            for (uint32_t u : shells[s]) flip(u);
    }
    for (uint32_t t = 0; t < n; ++t) {
        if (!flipped[t]) continue;
        ++report.flippedTriangles;
        keep(report.flippedAt, centroid(soup, t));
    }
    return closed;
}

// Parts: triangles connected through shared edges. Those that cross another part are unioned.
size_t crossingParts(const TriangleMesh& soup, const EdgeMap& edges,
                     const std::vector<std::pair<uint32_t, uint32_t>>& pairs) {
    UnionFind parts(soup.triangles.size());
    for (const auto& [key, users] : edges)
        for (size_t i = 1; i < users.size(); ++i) parts.unite(users[0], users[i]);
    std::set<uint32_t> crossing;
    for (const auto& [i, j] : pairs)
        if (parts.find(i) != parts.find(j)) crossing.insert({parts.find(i), parts.find(j)});
    return crossing.size();
}

// The box TetGen fills: the triangles' bounds, a tenth of their diagonal larger on every side,
// with float corners. Its 12 triangles are appended to `plc`.
void addPaddedBox(TriangleMesh& plc) {
    const Bounds3 b = bounds(plc);
    const double pad = 0.1 * b.diagonal() + 1e-30;
    const glm::dvec3 lo = b.lo - pad, hi = b.hi + pad;
    const auto f = [](double x, bool up) {
        const float r = float(x);
        return double(up ? (double(r) < x ? std::nextafter(r, INFINITY) : r)
                         : (double(r) > x ? std::nextafter(r, -INFINITY) : r));
    };
    const uint32_t base = uint32_t(plc.positions.size());
    for (int i = 0; i < 8; ++i)
        plc.positions.push_back({i & 1 ? f(hi.x, true) : f(lo.x, false), i & 2 ? f(hi.y, true) : f(lo.y, false),
                                 i & 4 ? f(hi.z, true) : f(lo.z, false)});
    static constexpr uint32_t kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : kQuads) {
        plc.triangles.push_back({base + q[0], base + q[1], base + q[2]});
        plc.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    }
}

struct Tets {
    std::vector<glm::dvec3> points;
    std::vector<std::array<uint32_t, 4>> tets;
    std::vector<std::array<int, 4>> neighbours;  // across the face opposite each vertex; -1 on the box
};

Tets unpack(const RawTets& raw) {
    Tets t;
    for (size_t i = 0; i + 2 < raw.points.size(); i += 3)
        t.points.push_back({raw.points[i], raw.points[i + 1], raw.points[i + 2]});
    const size_t n = raw.tets.size() / 4;
    if (raw.neighbours.size() != 4 * n) throw InputError("TetGen returned no neighbours");
    t.tets.resize(n);
    t.neighbours.resize(n);
    for (size_t i = 0; i < n; ++i)
        for (int j = 0; j < 4; ++j) {
            t.tets[i][j] = uint32_t(raw.tets[4 * i + j]);
            t.neighbours[i][j] = raw.neighbours[4 * i + j];
            if (t.tets[i][j] >= t.points.size() || t.neighbours[i][j] >= int(n))
                throw InputError("TetGen returned an index out of range");
        }
    return t;
}

bool isBoundary(const Tets& t, const std::vector<char>& inside, size_t i, int j) {
    const int n = t.neighbours[i][j];
    return inside[i] && (n < 0 || !inside[size_t(n)]);
}

// The inside's boundary faces, wound outward, as a mesh of their own vertices; `spanned` marks
// those that are not constraint triangles (the box's count as not).
TriangleMesh boundaryOf(const Tets& t, const std::vector<char>& inside,
                        const std::set<std::array<uint32_t, 3>>& constraints, std::vector<uint32_t>& spanned) {
    TriangleMesh out;
    std::vector<uint32_t> remap(t.points.size(), UINT32_MAX);
    for (size_t i = 0; i < t.tets.size(); ++i)
        for (int j = 0; j < 4; ++j) {
            if (!isBoundary(t, inside, i, j)) continue;
            auto f = faceOf(t.tets[i], j);
            // Outward: the tet's fourth vertex behind the face (Shewchuk's orient3d > 0).
            if (orient3d(t.points[f[0]], t.points[f[1]], t.points[f[2]], t.points[t.tets[i][j]]) < 0)
                std::swap(f[1], f[2]);
            auto key = f;
            std::sort(key.begin(), key.end());
            if (!constraints.count(key)) spanned.push_back(uint32_t(out.triangles.size()));
            for (auto& v : f) {
                if (remap[v] == UINT32_MAX) {
                    remap[v] = uint32_t(out.positions.size());
                    out.positions.push_back(t.points[v]);
                }
                v = remap[v];
            }
            out.triangles.push_back(f);
        }
    return out;
}

// Holes: spanned faces connected through shared edges.
void describeHoles(const TriangleMesh& surface, const std::vector<uint32_t>& spanned, RepairReport& report) {
    std::vector<std::array<uint32_t, 3>> tris;
    for (uint32_t s : spanned) tris.push_back(surface.triangles[s]);
    const EdgeMap edges = edgeTriangles(tris);
    UnionFind holes(tris.size());
    for (const auto& [key, users] : edges)
        for (size_t i = 1; i < users.size(); ++i) holes.unite(users[0], users[i]);
    std::unordered_map<uint32_t, size_t> index;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        auto [it, added] = index.emplace(holes.find(i), report.holes.size());
        if (added) report.holes.emplace_back();
        RepairReport::Hole& h = report.holes[it->second];
        const double a = area(surface, spanned[i]);
        h.centre += a * centroid(surface, spanned[i]);
        h.area += a;
        ++h.faces;
        report.spannedArea += a;
    }
    for (auto& h : report.holes)
        if (h.area > 0) h.centre /= h.area;
    for (uint32_t t = 0; t < surface.triangles.size(); ++t) report.boundaryArea += area(surface, t);
}

std::string plural(size_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The soup the winding number is taken of: welded, without zero-area and duplicate triangles,
// each patch wound consistently (orientPatches). Returns its edges and which triangles belong to
// closed patches.
struct OrientedSoup {
    EdgeMap edges;
    std::vector<char> closed;
};
OrientedSoup cleanAndOrient(TriangleMesh& soup, RepairReport& report) {
    report.applied = true;
    weldVertices(soup);
    const SoupCleaning cleaning = dropDegenerateAndDuplicates(soup);
    report.degenerateDropped = cleaning.degenerate;
    report.duplicatesDropped = cleaning.duplicates;
    for (const auto& p : cleaning.degenerateAt) keep(report.degenerateAt, p);
    for (const auto& p : cleaning.duplicateAt) keep(report.duplicateAt, p);
    if (soup.triangles.empty()) throw InputError("mesh encloses no volume: every triangle has zero area");
    EdgeMap edges = edgeTriangles(soup.triangles);
    for (const auto& [key, users] : edges) {
        report.holeEdges += users.size() == 1;
        report.nonManifoldEdges += users.size() > 2;
    }
    std::vector<char> closed = orientPatches(soup, edges, report);
    return {std::move(edges), std::move(closed)};
}

}  // namespace

std::string RepairReport::summary() const {
    char share[64];
    std::snprintf(share, sizeof share, "%.3g%%", boundaryArea > 0 ? 100 * spannedArea / boundaryArea : 0.0);
    if (!approximateReason.empty())
        return "the boundary is approximate, from the winding number on a grid of " +
               std::to_string(kWindingGridCells) + " cells across, because " + approximateReason;
    std::string s = plural(holes.size(), "hole", "holes") + " spanned (" + share + " of the surface), " +
                    plural(crossingPairs, "crossing pair", "crossing pairs") + " resolved, " +
                    plural(partsUnioned, "part", "parts") + " unioned, " + plural(flippedTriangles, "face", "faces") +
                    " flipped, " + plural(duplicatesDropped, "duplicate face", "duplicate faces") + " and " +
                    plural(degenerateDropped, "zero-area triangle", "zero-area triangles") + " dropped";
    if (nonManifoldEdges)
        s += ", " + plural(nonManifoldEdges, "non-manifold edge", "non-manifold edges") + " kept as constraints";
    if (unsplitTriangles)
        s += ", " + plural(unsplitTriangles, "crossing triangle", "crossing triangles") + " left unsplit (" +
             unsplitReason + "; the boundary near them follows the tets)";
    return s + " (inside: winding number above 1/2, smoothed by a minimum cut where within 1/4 of it)";
}

RepairReport repairInterior(TriangleMesh& mesh, const RepairClock& clock) {
    RepairReport report;
    TriangleMesh soup = mesh;
    const auto [edges, closed] = cleanAndOrient(soup, report);
    clock.stage("cleaning: " + grouped(soup.triangles.size()) + " triangles welded and oriented");
    const auto pairs = findSelfIntersections(soup);
    clock.stage("crossings: " + grouped(pairs.size()) + " pairs found, none split yet");
    report.crossingPairs = pairs.size();
    for (const auto& [i, j] : pairs) keep(report.crossingAt, centroid(soup, i));
    report.partsUnioned = crossingParts(soup, edges, pairs);

    // The constraints: the input's triangles with their crossings split, in a box, and a lattice
    // around each hole. Their vertices come first in TetGen's output, then the box's, the
    // lattice's, then Steiner points.
    VolumeBoundary plc;
    ResolvedSurface resolved = resolveIntersections(soup, pairs);
    clock.stage("crossings: " + grouped(pairs.size()) + " pairs split into " +
                grouped(resolved.surface.triangles.size()) + " triangles");
    plc.surface = std::move(resolved.surface);
    report.unsplitTriangles = resolved.unsplit;
    report.unsplitReason = resolved.unsplitReason;
    if (plc.surface.triangles.empty())
        throw InputError(
            "cannot repair the crossing parts: every triangle crosses another and they could not be split (" +
            resolved.unsplitReason + ")");
    std::set<std::array<uint32_t, 3>> constraints;
    for (auto f : plc.surface.triangles) {
        std::sort(f.begin(), f.end());
        constraints.insert(f);
    }
    addPaddedBox(plc.surface);
    // Labels from the cleaned and oriented input, not from its split pieces: the same field,
    // without the rounding of the split points.
    const PartWinding winding(soup, closed);
    // TetGen 1.5 fails an assertion on some lattices near the input (flip41 on an open sphere of
    // 8 rings and 64 sides without its top three bands); the lattice moved within its cell
    // avoids the configuration.
    static constexpr glm::dvec3 kLatticeOffsets[] = {
        {0.3183, 0.2718, 0.4142}, {0.1183, 0.5718, 0.2142}, {0.7071, 0.1618, 0.5772}};
    const Bounds3 box = bounds(plc.surface);
    const size_t constrained = plc.surface.positions.size();
    Tets tets;
    for (const glm::dvec3& offset : kLatticeOffsets) {
        const std::vector<glm::dvec3> lattice = holeLattice(soup, edges, winding, box, offset);
        plc.surface.positions.resize(constrained);
        plc.surface.positions.insert(plc.surface.positions.end(), lattice.begin(), lattice.end());
        const std::string box = "box: TetGen on " + grouped(plc.surface.triangles.size()) + " triangles and " +
                                grouped(lattice.size()) + " lattice points";
        try {
            tets = unpack(runIsolated(plc, "pYnQz", clock.left()));
            report.latticePoints = lattice.size();
            clock.stage(box + ": " + grouped(tets.tets.size()) + " tets");
            break;
        } catch (const TetGenCrash&) {
            if (&offset == &kLatticeOffsets[std::size(kLatticeOffsets) - 1]) throw;
        } catch (const InputError&) {
            if (clock.expired()) clock.stop(box + ", not finished");
            throw;
        }
    }
    if (tets.tets.empty()) throw InputError("TetGen produced no tetrahedra");

    std::vector<double> w(tets.tets.size());
    std::atomic<size_t> done{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, w.size()), [&](const auto& range) {
        if (clock.expired()) return;
        done += range.size();
        for (size_t i = range.begin(); i != range.end(); ++i) {
            const auto& v = tets.tets[i];
            w[i] = winding.classify((tets.points[v[0]] + tets.points[v[1]] + tets.points[v[2]] + tets.points[v[3]]) *
                                    0.25);
        }
    });
    const std::string windings = "winding number: " + grouped(done) + " of " + grouped(w.size()) + " tets";
    if (done < w.size()) clock.stop(windings);
    clock.stage(windings);
    report.minWinding = *std::min_element(w.begin(), w.end());
    report.maxWinding = *std::max_element(w.begin(), w.end());
    const std::vector<char> inside = report.maxWinding > 0.5 ? insideLabels(tets.points, tets.tets, tets.neighbours, w,
                                                                            constraints, kCutGammaPerEdge)
                                                             : std::vector<char>(w.size(), 0);
    if (std::find(inside.begin(), inside.end(), 1) == inside.end()) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "mesh encloses no volume: its winding number stays at or below 1/2 everywhere (at most %.3f), "
                      "so it is an open sheet, not a closed surface with holes",
                      report.maxWinding);
        throw InputError(text);
    }
    mesh = boundaryOf(tets, inside, constraints, report.spannedTriangles);
    describeHoles(mesh, report.spannedTriangles, report);
    return report;
}

std::string surveyProblems(const TriangleMesh& input) {
    TriangleMesh mesh = input;
    weldVertices(mesh);
    const SoupCleaning cleaning = dropDegenerateAndDuplicates(mesh);
    std::vector<std::string> found;
    const auto add = [&](size_t n, const std::string& one, const std::string& many, const glm::dvec3& first) {
        if (n) found.push_back(plural(n, one, many) + " (first at " + formatPosition(first) + ")");
    };
    if (cleaning.degenerate)
        add(cleaning.degenerate, "zero-area triangle", "zero-area triangles", cleaning.degenerateAt[0]);
    if (cleaning.duplicates) add(cleaning.duplicates, "duplicate face", "duplicate faces", cleaning.duplicateAt[0]);
    const EdgeMap edges = edgeTriangles(mesh.triangles);
    size_t holes = 0, nonManifold = 0;
    glm::dvec3 firstHole{0}, firstNonManifold{0};
    uint64_t holeKey = UINT64_MAX, nonManifoldKey = UINT64_MAX;  // the lowest edge, not the first hashed
    for (const auto& [key, users] : edges) {
        const glm::dvec3 p = mesh.positions[uint32_t(key >> 32)];
        if (users.size() == 1 && ++holes && key < holeKey) {
            holeKey = key;
            firstHole = p;
        }
        if (users.size() > 2 && ++nonManifold && key < nonManifoldKey) {
            nonManifoldKey = key;
            firstNonManifold = p;
        }
    }
    add(holes, "hole edge", "hole edges", firstHole);
    add(nonManifold, "non-manifold edge", "non-manifold edges", firstNonManifold);
    const auto pairs = findSelfIntersections(mesh);
    if (!pairs.empty()) add(pairs.size(), "crossing pair", "crossing pairs", centroid(mesh, pairs[0].first));
    std::string s;
    for (const auto& f : found) s += (s.empty() ? "" : ", ") + f;
    return s;
}

ValidationReport prepareSurface(TriangleMesh& mesh, bool strict, double timeLimit) {
    if (mesh.triangles.empty()) throw InputError("mesh has no triangles");
    checkFinite(mesh);
    const size_t oppositePairs = cancelOppositeFaces(mesh);
    if (mesh.triangles.empty()) throw InputError("mesh has no triangles once its opposite pairs of faces cancel");
    const auto noteCancelled = [&](ValidationReport report) {
        report.oppositePairs = oppositePairs;
        if (oppositePairs)
            report.notes.push_back("removed " + std::to_string(oppositePairs) +
                                   " pairs of faces with the same corners wound opposite ways (they cancel)");
        return report;
    };
    TriangleMesh original = mesh;
    try {
        return noteCancelled(validateAndRepair(mesh));
    } catch (const InputError& refusal) {
        if (strict) {
            const std::string all = surveyProblems(original);
            throw InputError(std::string(refusal.what()) + (all.empty() ? "" : "; in all: " + all));
        }
        const TriangleMesh input = original;
        mesh = std::move(original);
        ValidationReport report;
        try {
            RepairReport repair = repairInterior(mesh, RepairClock(timeLimit));
            repair.reason = refusal.what();
            try {
                report = validateAndRepair(mesh, true);
            } catch (const InputError& e) {
                throw InputError(std::string("the repaired mesh is still invalid (") + e.what() + ")");
            }
            report.repair = std::move(repair);
            report.notes = {report.repair.summary()};
        } catch (const InputError& failure) {
            // A mesh that encloses nothing has nothing to approximate either.
            if (std::string(failure.what()).rfind("mesh encloses no volume", 0) == 0) throw;
            mesh = input;
            report = approximateSurface(mesh, failure.what());
            report.repair.reason = refusal.what();
        }
        return noteCancelled(std::move(report));
    }
}

ValidationReport approximateSurface(TriangleMesh& mesh, const std::string& reason) {
    const std::string problems = surveyProblems(mesh);
    RepairReport repair;
    cleanAndOrient(mesh, repair);
    mesh = windingGridBoundary(mesh);
    ValidationReport report = validateAndRepair(mesh, true);
    report.repair = std::move(repair);
    report.repair.approximateReason = reason + (problems.empty() ? "" : "; the input has " + problems);
    report.notes = {report.repair.summary()};
    return report;
}

}  // namespace tetglow
