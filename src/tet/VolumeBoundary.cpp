#include "tet/VolumeBoundary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "tet/InteriorRepair.h"
#include "tet/Nesting.h"
#include "tet/SelfIntersection.h"

namespace tetglow {
namespace {

struct PositionHash {
    size_t operator()(const glm::dvec3& p) const {
        const std::hash<double> h;
        return h(p.x) ^ (h(p.y) * 0x9E3779B97F4A7C15ull) ^ (h(p.z) * 0xC2B2AE3D27D4EB4Full);
    }
};

bool sameWinding(const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
    for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
    return false;
}

// A surface holding a triangle of the boundary: its own index of the triangle, and whether it
// winds it the other way.
struct Holder {
    uint32_t surface, triangle;
    bool reversed;
};

// The regions on the two sides of a triangle. The space behind it is inside every surface that
// holds it with its winding, so it is the innermost one's region; where no surface holds it the
// other way, the front is the region around the outermost holder.
std::array<int32_t, 2> sidesOf(const std::vector<Holder>& holders, const std::vector<int32_t>& parent,
                               const std::vector<int>& depth) {
    const auto side = [&](bool reversed) {
        int32_t inner = -1, outer = -1;
        for (const Holder& h : holders) {
            if (h.reversed != reversed) continue;
            if (inner < 0 || depth[h.surface] > depth[inner]) inner = int32_t(h.surface);
        }
        if (inner >= 0) return inner;
        for (const Holder& h : holders)
            if (outer < 0 || depth[h.surface] < depth[outer]) outer = int32_t(h.surface);
        return parent[outer];
    };
    return {side(false), side(true)};
}

// A point strictly inside surface r and outside its children, found by stepping inward from
// the centres of r's largest triangles by shrinking fractions of their size; each candidate is
// checked exactly, so the point is certain, and the first steps are long, so it lies well
// away from the surfaces where the region allows.
glm::dvec3 placeInsidePoint(const TriangleMesh& surface, const std::vector<const TriangleMesh*>& children,
                            const std::string& name) {
    std::vector<uint32_t> order(surface.triangles.size());
    std::iota(order.begin(), order.end(), 0u);
    std::vector<glm::dvec3> normals(order.size());
    for (uint32_t t : order)
        normals[t] =
            glm::cross(surface.corner(t, 1) - surface.corner(t, 0), surface.corner(t, 2) - surface.corner(t, 0));
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return glm::length(normals[a]) > glm::length(normals[b]); });
    order.resize(std::min<size_t>(order.size(), 64));
    for (uint32_t t : order) {
        const glm::dvec3 centre = (surface.corner(t, 0) + surface.corner(t, 1) + surface.corner(t, 2)) / 3.0;
        const double size = std::sqrt(glm::length(normals[t]));
        const glm::dvec3 inward = -glm::normalize(normals[t]);
        for (double step = 0.3; step > 1e-7; step *= 0.1) {
            const glm::dvec3 p = centre + step * size * inward;
            if (classifyPoint(surface, p) != PointSide::Inside) continue;
            if (std::all_of(children.begin(), children.end(),
                            [&](const TriangleMesh* c) { return classifyPoint(*c, p) == PointSide::Outside; }))
                return p;
        }
    }
    throw InputError((name.empty() ? std::string("mesh") : name) +
                     ": found no point inside it that is outside the media nested in it (do they fill it?)");
}

// TetGen takes points closer than this fraction of the input's bounding box as one (its -T
// tolerance, 1e-8 by default), so vertices of two surfaces that close would be merged by TetGen
// behind our back: its regions then disagree with the surfaces. Refused here with the cause.
constexpr double kTetGenTolerance = 1e-8;

void refuseNearVertices(const std::vector<glm::dvec3>& positions, const std::vector<uint32_t>& owner,
                        const std::vector<std::vector<uint32_t>>& vertexIds, const std::vector<std::string>& names) {
    Bounds3 box;
    for (const glm::dvec3& p : positions) box.extend(p);
    const double cell = kTetGenTolerance * box.diagonal();
    if (!(cell > 0)) return;
    // A grid of cells of the tolerance's size: near vertices lie in the same or adjacent cells.
    using Cell = std::array<int64_t, 3>;
    const auto cellOf = [&](const glm::dvec3& p) {
        return Cell{int64_t((p.x - box.lo.x) / cell), int64_t((p.y - box.lo.y) / cell),
                    int64_t((p.z - box.lo.z) / cell)};
    };
    std::map<Cell, std::vector<uint32_t>> grid;
    for (uint32_t v = 0; v < positions.size(); ++v) grid[cellOf(positions[v])].push_back(v);
    const auto local = [&](size_t surface, uint32_t v) {  // the vertex's index in that surface's own list
        return uint32_t(std::find(vertexIds[surface].begin(), vertexIds[surface].end(), v) -
                        vertexIds[surface].begin());
    };
    for (uint32_t v = 0; v < positions.size(); ++v) {
        const Cell c = cellOf(positions[v]);
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == grid.end()) continue;
                    for (uint32_t w : it->second) {
                        const double d = glm::length(positions[w] - positions[v]);
                        if (owner[w] == owner[v] || !(d < cell)) continue;
                        char text[160];
                        std::snprintf(
                            text, sizeof text,
                            " are %.3g apart, closer than TetGen tells points apart (%.3g, 1e-8 of their extent): ", d,
                            cell);
                        throw InputError(names[owner[v]] + " and " + names[owner[w]] + text + "vertex " +
                                         std::to_string(local(owner[v], v)) + " of " + names[owner[v]] +
                                         " and vertex " + std::to_string(local(owner[w], w)) + " of " +
                                         names[owner[w]] + " (media may share vertices exactly, or keep apart)");
                    }
                }
    }
}

}  // namespace

VolumeBoundary singleRegion(const TriangleMesh& surface) {
    VolumeBoundary c;
    c.surface = surface;
    c.sides.assign(surface.triangles.size(), {0, -1});
    for (uint32_t t = 0; t < surface.triangles.size(); ++t) c.source.push_back({0, t});
    c.parent = {-1};
    return c;
}

VolumeBoundary buildVolumeBoundary(const std::vector<TriangleMesh>& surfaces, const std::vector<std::string>& names) {
    const size_t n = surfaces.size();
    VolumeBoundary c;
    // Vertices: exact duplicates across surfaces merged, in order of first appearance.
    std::unordered_map<glm::dvec3, uint32_t, PositionHash> vertexIndex;
    std::vector<std::vector<uint32_t>> vertexIds(n);
    std::vector<uint32_t> owner;  // per vertex: the first surface holding it
    for (size_t i = 0; i < n; ++i)
        for (const glm::dvec3& p : surfaces[i].positions) {
            auto [it, inserted] = vertexIndex.emplace(p, uint32_t(c.surface.positions.size()));
            if (inserted) {
                c.surface.positions.push_back(p);
                owner.push_back(uint32_t(i));
            }
            vertexIds[i].push_back(it->second);
        }
    if (n > 1) refuseNearVertices(c.surface.positions, owner, vertexIds, names);
    // Triangles: one per corner set, remembering every surface holding it and its winding there.
    std::map<std::array<uint32_t, 3>, uint32_t> triangleIndex;
    std::vector<std::vector<Holder>> holders;
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t t = 0; t < surfaces[i].triangles.size(); ++t) {
            const auto& v = surfaces[i].triangles[t];
            const std::array<uint32_t, 3> tri{vertexIds[i][v[0]], vertexIds[i][v[1]], vertexIds[i][v[2]]};
            auto key = tri;
            std::sort(key.begin(), key.end());
            auto [it, inserted] = triangleIndex.emplace(key, uint32_t(c.surface.triangles.size()));
            if (inserted) {
                c.surface.triangles.push_back(tri);
                c.source.push_back({i, t});
                holders.emplace_back();
            }
            holders[it->second].push_back({i, t, !sameWinding(c.surface.triangles[it->second], tri)});
        }
    // Surfaces that meet other than along shared corners and triangles cross. Each alone is free
    // of self-intersections, so the two triangles found have holders on two different surfaces.
    if (const auto hit = findSelfIntersection(c.surface)) {
        for (const Holder& a : holders[hit->first])
            for (const Holder& b : holders[hit->second])
                if (a.surface != b.surface)
                    throw InputError(
                        names[a.surface] + " and " + names[b.surface] + " cross: triangle " +
                        std::to_string(a.triangle) + " of " + names[a.surface] + " meets triangle " +
                        std::to_string(b.triangle) + " of " + names[b.surface] +
                        " (media may nest or share whole triangles, not overlap; an open vessel is one closed, "
                        "cup-shaped mesh, not a solid with a cavity reaching its rim: docs/FORMAT.md, cavities)");
        throw std::logic_error("buildVolumeBoundary: a surface intersects itself after validation");
    }
    c.parent = findNesting(surfaces, vertexIds, names);
    std::vector<int> depth(n, 0);
    for (size_t i = 0; i < n; ++i)
        for (int32_t p = c.parent[i]; p >= 0; p = c.parent[p]) ++depth[i];
    for (size_t t = 0; t < c.surface.triangles.size(); ++t) c.sides.push_back(sidesOf(holders[t], c.parent, depth));

    return c;
}

VolumeBoundary validatedBoundary(std::vector<TriangleMesh> surfaces, const std::vector<std::string>& names,
                                 bool strict) {
    for (size_t i = 0; i < surfaces.size(); ++i) {
        try {
            prepareSurface(surfaces[i], strict);
        } catch (const InputError& e) {
            throw InputError(names[i] + ": " + e.what());
        }
    }
    return buildVolumeBoundary(surfaces, names);
}

void placeInsidePoints(VolumeBoundary& boundary, const std::vector<TriangleMesh>& surfaces,
                       const std::vector<std::string>& names) {
    std::vector<std::vector<const TriangleMesh*>> children(surfaces.size());
    for (size_t i = 0; i < surfaces.size(); ++i)
        if (boundary.parent[i] >= 0) children[boundary.parent[i]].push_back(&surfaces[i]);
    boundary.insidePoints.clear();
    for (size_t i = 0; i < surfaces.size(); ++i)
        boundary.insidePoints.push_back(placeInsidePoint(surfaces[i], children[i], names[i]));
}

}  // namespace tetglow
