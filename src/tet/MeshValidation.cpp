#include "tet/MeshValidation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "tet/FloodFill.h"
#include "tet/Predicates.h"
#include "tet/SelfIntersection.h"
#include "tet/ShellNesting.h"
#include "tet/SoupEdges.h"

namespace tetglow {

std::string formatPosition(const glm::dvec3& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x, p.y, p.z);
    return buf;
}

namespace {

std::string face(uint32_t t) { return "triangle " + std::to_string(t); }

}  // namespace

void checkFinite(const TriangleMesh& mesh) {
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const auto& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InputError("vertex " + std::to_string(v) + " has a non-finite coordinate " + formatPosition(p));
        if (std::abs(p.x) > 1e30 || std::abs(p.y) > 1e30 || std::abs(p.z) > 1e30)
            throw InputError("vertex " + std::to_string(v) + " is too large for float precision " + formatPosition(p));
    }
    if (const std::string problem = precisionProblem(bounds(mesh)); !problem.empty())
        throw InputError("the mesh " + problem);
}

std::string precisionProblem(const Bounds3& box) {
    if (box.empty()) return "";
    const glm::dvec3 extent = box.hi - box.lo;
    const double size = std::max({extent.x, extent.y, extent.z});
    if (size == 0) return "";  // a point: every triangle has zero area, as validation says
    char text[256];
    if (size < kSmallestMesh) {
        std::snprintf(text, sizeof text,
                      "is too small to represent: %.3g across (float coordinates shape nothing under %g): scale it up",
                      size, kSmallestMesh);
        return text;
    }
    const double far = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z), std::abs(box.hi.x),
                                 std::abs(box.hi.y), std::abs(box.hi.z)});
    const double step = far * std::numeric_limits<float>::epsilon();
    if (size < kFloatStepsAcross * step) {
        std::snprintf(text, sizeof text,
                      "is beyond float precision: %.3g across at %.3g from the origin, where floats step by %.3g: "
                      "move it nearer the origin or scale it up",
                      size, far, step);
        return text;
    }
    return "";
}

WeldCounts weldVertices(TriangleMesh& mesh) {
    WeldCounts report;
    for (auto& p : mesh.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
    std::vector<uint32_t> order(mesh.positions.size());
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](uint32_t a, uint32_t b) {
        const auto &p = mesh.positions[a], &q = mesh.positions[b];
        return std::tie(p.x, p.y, p.z, a) < std::tie(q.x, q.y, q.z, b);
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<uint32_t> canonical(mesh.positions.size());
    for (size_t i = 0; i < order.size(); ++i) {
        const bool same = i > 0 && mesh.positions[order[i]] == mesh.positions[order[i - 1]];
        canonical[order[i]] = same ? canonical[order[i - 1]] : order[i];
        report.welded += same;
    }
    std::vector<uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    std::vector<glm::dvec3> kept;
    for (auto& t : mesh.triangles)
        for (auto& v : t) {
            uint32_t c = canonical[v];
            if (remap[c] == UINT32_MAX) {
                remap[c] = static_cast<uint32_t>(kept.size());
                kept.push_back(mesh.positions[c]);
            }
            v = remap[c];
        }
    report.unused = mesh.positions.size() - report.welded - kept.size();
    mesh.positions = std::move(kept);
    return report;
}

namespace {

// Faces with the same three corners wound opposite ways, marked in `cancelled`; the pairs.
size_t cancelOppositeTriangles(const TriangleMesh& mesh, std::vector<char>& cancelled) {
    // Per set of corners, the faces on it wound each way: a face is "even" when its corners run
    // in the cyclic order of the sorted corners.
    std::map<std::array<uint32_t, 3>, std::array<std::vector<uint32_t>, 2>> faces;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& v = mesh.triangles[t];
        const int first = int(std::min_element(v.begin(), v.end()) - v.begin());
        auto key = v;
        std::sort(key.begin(), key.end());
        faces[key][v[(first + 1) % 3] < v[(first + 2) % 3] ? 0 : 1].push_back(t);
    }
    size_t pairs = 0;
    for (const auto& [key, ways] : faces) {
        const size_t n = std::min(ways[0].size(), ways[1].size());
        // The first faces of the way that outnumbers the other stay.
        for (const auto& way : ways)
            for (size_t i = way.size() - n; i < way.size(); ++i) cancelled[way[i]] = 1;
        pairs += n;
    }
    return pairs;
}

// The same for flat convex quads split along different diagonals, as two cells of a volume mesh
// that list their shared face from different corners give it: two triangles that share an edge,
// lie in one plane and make a convex quad cancel two that make the same quad wound the other way.
size_t cancelOppositeQuads(const TriangleMesh& mesh, std::vector<char>& cancelled) {
    // Directed edges a -> b with the face running each, sorted: a run of one key is its faces.
    std::vector<std::pair<uint64_t, uint32_t>> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        if (!cancelled[t])
            for (int k = 0; k < 3; ++k)
                edges.push_back({uint64_t(mesh.triangles[t][k]) << 32 | mesh.triangles[t][(k + 1) % 3], t});
    std::sort(edges.begin(), edges.end());
    // The one face running `key`, or none.
    const auto only = [&](uint64_t key) -> std::optional<uint32_t> {
        const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{key, 0u});
        if (it == edges.end() || it->first != key || (it + 1 != edges.end() && (it + 1)->first == key))
            return std::nullopt;
        return it->second;
    };
    const auto apex = [&](uint32_t t, uint32_t a, uint32_t b) {
        for (uint32_t v : mesh.triangles[t])
            if (v != a && v != b) return v;
        return a;
    };
    // Per set of four corners, the pairs of faces making that quad, by winding.
    std::map<std::array<uint32_t, 4>, std::array<std::vector<std::pair<uint32_t, uint32_t>>, 2>> quads;
    for (const auto& [key, face] : edges) {
        const auto u = uint32_t(key >> 32), v = uint32_t(key);
        if (u > v) continue;
        const auto first = only(key), back = only(uint64_t(v) << 32 | u);
        if (!first || !back) continue;
        const uint32_t s = *first, t = *back;
        const uint32_t p = apex(s, u, v), q = apex(t, u, v);
        const auto &U = mesh.positions[u], &V = mesh.positions[v], &P = mesh.positions[p], &Q = mesh.positions[q];
        if (p == q || orient3d(U, V, P, Q) != 0) continue;
        // Convex: u and v on either side of p-q, p and q on either side of u-v, in the plane
        // seen along the axis its normal is closest to.
        const glm::dvec3 n = glm::abs(glm::cross(V - U, P - U));
        const int axis = n.x >= n.y && n.x >= n.z ? 0 : n.y >= n.z ? 1 : 2;
        const auto flat = [&](const glm::dvec3& x) { return glm::dvec2(x[(axis + 1) % 3], x[(axis + 2) % 3]); };
        const auto side = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
            const double o = orient2d(flat(a), flat(b), flat(c));
            return (o > 0) - (o < 0);
        };
        if (side(U, V, P) * side(U, V, Q) != -1 || side(P, Q, U) * side(P, Q, V) != -1) continue;
        // The quad's boundary runs v, p, u, q; from its smallest corner, one way or the other.
        std::array<uint32_t, 4> cycle{v, p, u, q};
        std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
        std::array<uint32_t, 4> corners = cycle;
        std::sort(corners.begin(), corners.end());
        quads[corners][cycle[1] < cycle[3] ? 0 : 1].push_back({s, t});
    }
    size_t pairs = 0;
    for (const auto& [corners, ways] : quads)
        for (const auto& [a, b] : ways[0])
            for (const auto& [c, d] : ways[1])
                if (!cancelled[a] && !cancelled[b] && !cancelled[c] && !cancelled[d]) {
                    cancelled[a] = cancelled[b] = cancelled[c] = cancelled[d] = 1;
                    pairs += 2;
                }
    return pairs;
}

}  // namespace

size_t cancelOppositeFaces(TriangleMesh& mesh) {
    TriangleMesh welded = mesh;
    weldVertices(welded);
    std::vector<char> cancelled(welded.triangles.size(), 0);
    size_t pairs = cancelOppositeTriangles(welded, cancelled);
    pairs += cancelOppositeQuads(welded, cancelled);
    if (pairs == 0) return 0;  // the mesh as it was, not even welded
    std::vector<std::array<uint32_t, 3>> kept;
    for (uint32_t t = 0; t < welded.triangles.size(); ++t)
        if (!cancelled[t]) kept.push_back(welded.triangles[t]);
    welded.triangles = std::move(kept);
    weldVertices(welded);  // drops the vertices only cancelled faces used
    mesh = std::move(welded);
    return pairs;
}

bool collinear(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // Collinear in 3D exactly when collinear in all three coordinate-plane projections.
    return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 && orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
           orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

namespace {

void checkTriangles(const TriangleMesh& mesh) {
    std::map<std::array<uint32_t, 3>, uint32_t> seen;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        auto v = mesh.triangles[t];
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
            throw InputError("degenerate " + face(t) + ": a vertex is repeated");
        if (collinear(mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]))
            throw InputError("degenerate " + face(t) + ": zero area (collinear corners) at " +
                             formatPosition(mesh.positions[v[0]]));
        std::sort(v.begin(), v.end());
        auto [it, inserted] = seen.emplace(v, t);
        if (!inserted)
            throw InputError("duplicate faces: " + face(it->second) + " and " + face(t) + " have the same corners");
    }
}

bool pinched(size_t triangles) { return triangles >= 4 && triangles % 2 == 0; }

void checkManifold(const TriangleMesh& mesh, const std::unordered_map<uint64_t, std::vector<uint32_t>>& edges,
                   bool pinchedEdges) {
    // Report the edge whose first triangle comes first, so the message does not depend on hashing.
    const std::pair<const uint64_t, std::vector<uint32_t>>* worst = nullptr;
    for (const auto& e : edges)
        if (e.second.size() != 2 && !(pinchedEdges && pinched(e.second.size())) &&
            (!worst || e.second[0] < worst->second[0]))
            worst = &e;
    if (!worst) return;
    const uint32_t a = uint32_t(worst->first >> 32), b = uint32_t(worst->first);
    const std::string edge =
        "edge (" + std::to_string(a) + ", " + std::to_string(b) + ") at " + formatPosition(mesh.positions[a]);
    if (worst->second.size() == 1)
        throw InputError("mesh is not closed: " + edge + " belongs only to " + face(worst->second[0]) + " (a hole)");
    throw InputError("non-manifold " + edge + " is shared by " + std::to_string(worst->second.size()) +
                     " triangles (first: " + face(worst->second[0]) + ")");
}

bool sameDirection(const std::array<uint32_t, 3>& s, const std::array<uint32_t, 3>& t, uint32_t a, uint32_t b) {
    // True when both triangles traverse edge a->b in the same direction (inconsistent winding).
    auto has = [&](const std::array<uint32_t, 3>& f) {
        for (int k = 0; k < 3; ++k)
            if (f[k] == a && f[(k + 1) % 3] == b) return true;
        return false;
    };
    return has(s) == has(t);
}

// Makes winding consistent within each connected shell by flood fill; returns shell id per triangle.
// Shells connect across edges of two triangles only: parts pinched together along an edge stay two.
std::vector<uint32_t> orientShells(TriangleMesh& mesh, const std::unordered_map<uint64_t, std::vector<uint32_t>>& edges,
                                   ValidationReport& report) {
    return floodFill(
        mesh.triangles.size(), [&](uint32_t) { ++report.components; },
        [&](uint32_t t, uint32_t, const auto& reach) {
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
                const auto& pair = edges.at(edgeKey(a, b));
                if (pair.size() != 2) continue;
                const uint32_t n = pair[0] == t ? pair[1] : pair[0];
                const bool flip = sameDirection(mesh.triangles[t], mesh.triangles[n], a, b);
                if (reach(n)) {
                    if (flip) {
                        std::swap(mesh.triangles[n][1], mesh.triangles[n][2]);
                        ++report.flippedTriangles;
                    }
                } else if (flip) {
                    throw InputError("mesh is not orientable (like a Moebius strip): " + face(t) + " and " + face(n) +
                                     " cannot be wound consistently");
                }
            }
        });
}

double shellVolume(const TriangleMesh& mesh, const std::vector<uint32_t>& shell) {
    double volume = 0;
    const glm::dvec3 o = mesh.corner(shell[0], 0);
    for (uint32_t t : shell)
        volume += glm::dot(mesh.corner(t, 0) - o, glm::cross(mesh.corner(t, 1) - o, mesh.corner(t, 2) - o));
    return volume;
}

// Inside is where the winding number of the mesh as given is above 1/2, the sign taken from the
// outermost shell around (so a mesh wound inward throughout is the same solid). Each shell then
// winds outward from the inside it bounds: a cavity is one whose own winding says so (inward in
// an outward shell). A shell with inside on both sides (nested shells wound alike: winding
// number 2) bounds nothing and is dropped.
void orientOutward(TriangleMesh& mesh, const std::vector<uint32_t>& shell, ValidationReport& report) {
    std::vector<std::vector<uint32_t>> members(report.components);
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) members[shell[t]].push_back(t);
    std::vector<double> volume(members.size());
    for (size_t s = 0; s < members.size(); ++s) volume[s] = shellVolume(mesh, members[s]);
    const auto sign = [&](size_t s) { return volume[s] > 0 ? 1 : -1; };
    const auto containers = containingShells(mesh, members);
    std::vector<char> dropped(members.size(), 0);
    for (size_t s = 0; s < members.size(); ++s) {
        int windingOutside = 0;
        size_t outermost = s;
        for (uint32_t o : containers[s]) {
            windingOutside += sign(o);
            if (std::abs(volume[o]) > std::abs(volume[outermost])) outermost = o;
        }
        const bool insideOutside = sign(outermost) * windingOutside >= 1;
        const bool insideInside = sign(outermost) * (windingOutside + sign(s)) >= 1;
        if (insideOutside == insideInside) {
            dropped[s] = 1;
            ++report.droppedShells;
        } else if ((volume[s] > 0) != insideInside) {
            for (uint32_t t : members[s]) std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
            report.flippedTriangles += members[s].size();
        }
    }
    if (!report.droppedShells) return;
    std::vector<std::array<uint32_t, 3>> kept;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        if (!dropped[shell[t]]) kept.push_back(mesh.triangles[t]);
    mesh.triangles = std::move(kept);
    weldVertices(mesh);  // the dropped shells' vertices
}

}  // namespace

ValidationReport validateAndRepair(TriangleMesh& mesh, bool pinchedEdges) {
    ValidationReport report;
    if (mesh.triangles.empty()) throw InputError("mesh has no triangles");
    checkFinite(mesh);
    const WeldCounts weld = weldVertices(mesh);
    report.weldedVertices = weld.welded;
    report.unusedVertices = weld.unused;
    checkTriangles(mesh);
    const auto edges = edgeTriangles(mesh.triangles);
    checkManifold(mesh, edges, pinchedEdges);
    // Before orientation: nesting of shells means nothing once they cross.
    if (auto hit = findSelfIntersection(mesh))
        throw InputError("mesh intersects itself: " + face(hit->first) + " crosses " + face(hit->second));
    const auto shell = orientShells(mesh, edges, report);
    // A surface with pinched edges bounds a set of cells and is wound outward from them: a shell
    // through a pinched edge need not close on its own, so it says nothing of nesting by itself.
    if (!pinchedEdges) orientOutward(mesh, shell, report);
    report.volume = signedVolume(mesh);
    if (!(report.volume > 0))
        throw InputError("mesh encloses no volume (signed volume " + std::to_string(report.volume) + ")");
    if (report.weldedVertices)
        report.notes.push_back("welded " + std::to_string(report.weldedVertices) + " duplicate vertices");
    if (report.unusedVertices)
        report.notes.push_back("removed " + std::to_string(report.unusedVertices) + " unused vertices");
    if (report.flippedTriangles)
        report.notes.push_back("flipped " + std::to_string(report.flippedTriangles) + " inward-wound triangles");
    if (report.droppedShells)
        report.notes.push_back(
            "dropped " + std::to_string(report.droppedShells) + (report.droppedShells == 1 ? " shell" : " shells") +
            " inside the solid, wound as the shell around it (winding number 2: inside on both sides)");
    return report;
}

}  // namespace tetglow
