#include "tet/Nesting.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "tet/Predicates.h"
#include "tet/SelfIntersection.h"

namespace tetglow {
namespace {

int sign(double v) { return (v > 0) - (v < 0); }

// A fixed sequence of directions (splitmix64), so classifications are reproducible.
glm::dvec3 direction(uint64_t& state) {
    auto next = [&] {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return double((z ^ (z >> 31)) >> 11) * 0x1p-53 * 2 - 1;
    };
    for (;;) {
        const glm::dvec3 d(next(), next(), next());
        if (const double l = glm::length(d); l > 0.1 && l <= 1) return d / l;
    }
}

}  // namespace

PointSide classifyPoint(const TriangleMesh& surface, const glm::dvec3& p) {
    const Bounds3 box = bounds(surface);
    if (!box.contains(p)) return PointSide::Outside;
    const double reach = 2 * box.diagonal() + 1;
    uint64_t state = 0x7E76C0DEull;
    for (int attempt = 0; attempt < 1000; ++attempt) {
        const glm::dvec3 q = p + reach * direction(state);  // outside the box
        bool degenerate = false;
        int crossings = 0;
        for (uint32_t t = 0; t < surface.triangles.size() && !degenerate; ++t) {
            const std::array<glm::dvec3, 3> tri{surface.corner(t, 0), surface.corner(t, 1), surface.corner(t, 2)};
            const int sp = sign(orient3d(tri[0], tri[1], tri[2], p)), sq = sign(orient3d(tri[0], tri[1], tri[2], q));
            if (sp * sq > 0) continue;
            if (sp == 0 && segmentMeetsTriangle(p, p, tri)) return PointSide::OnSurface;
            if (sq == 0) {
                degenerate = true;
                continue;
            }
            if (sp == 0) continue;  // the segment leaves p's plane at p, which lies outside the triangle
            const int e0 = sign(orient3d(p, q, tri[0], tri[1])), e1 = sign(orient3d(p, q, tri[1], tri[2])),
                      e2 = sign(orient3d(p, q, tri[2], tri[0]));
            if (e0 == 0 || e1 == 0 || e2 == 0)
                degenerate = true;  // through an edge or a vertex: try another segment
            else
                crossings += e0 == e1 && e1 == e2;
        }
        if (!degenerate) return crossings % 2 ? PointSide::Inside : PointSide::Outside;
    }
    throw std::runtime_error("classifyPoint: no segment from the point avoids the surface's edges");
}

std::vector<int32_t> findNesting(const std::vector<TriangleMesh>& surfaces,
                                 const std::vector<std::vector<uint32_t>>& vertexIds,
                                 const std::vector<std::string>& names) {
    const size_t n = surfaces.size();
    std::vector<Bounds3> boxes(n);
    std::vector<std::unordered_set<uint32_t>> ids(n);
    std::vector<std::set<std::array<uint32_t, 3>>> triangles(n);  // by common vertex ids, sorted
    const auto key = [&](size_t i, uint32_t t) {
        std::array<uint32_t, 3> k;
        for (int c = 0; c < 3; ++c) k[c] = vertexIds[i][surfaces[i].triangles[t][c]];
        std::sort(k.begin(), k.end());
        return k;
    };
    for (size_t i = 0; i < n; ++i) {
        boxes[i] = bounds(surfaces[i]);
        ids[i].insert(vertexIds[i].begin(), vertexIds[i].end());
        for (uint32_t t = 0; t < surfaces[i].triangles.size(); ++t) triangles[i].insert(key(i, t));
    }
    // inside[i][o]: surface i lies inside surface o. Surfaces that do not cross are either nested
    // or apart, so one point of i off o decides: a vertex of i that is not a vertex of o (no
    // other vertex of i can touch o), else the centre of a triangle of i that o does not hold
    // (a shared triangle's centre lies on o, and rounded it falls on either side). When o holds
    // every triangle of i, the two are one surface.
    std::vector<std::vector<char>> inside(n, std::vector<char>(n, 0));
    for (size_t i = 0; i < n; ++i)
        for (size_t o = 0; o < n; ++o) {
            if (o == i || !boxes[o].contains(boxes[i].lo) || !boxes[o].contains(boxes[i].hi)) continue;
            PointSide side = PointSide::OnSurface;
            for (size_t v = 0; v < vertexIds[i].size() && side == PointSide::OnSurface; ++v)
                if (!ids[o].count(vertexIds[i][v])) side = classifyPoint(surfaces[o], surfaces[i].positions[v]);
            for (uint32_t t = 0; t < surfaces[i].triangles.size() && side == PointSide::OnSurface; ++t)
                if (!triangles[o].count(key(i, t)))
                    side = classifyPoint(
                        surfaces[o],
                        (surfaces[i].corner(t, 0) + surfaces[i].corner(t, 1) + surfaces[i].corner(t, 2)) / 3.0);
            if (side == PointSide::OnSurface)
                throw InputError(names[i] + " and " + names[o] + " have the same surface");
            inside[i][o] = side == PointSide::Inside;
        }
    std::vector<int32_t> depth(n, 0), parent(n, -1);
    for (size_t i = 0; i < n; ++i)
        for (size_t o = 0; o < n; ++o) depth[i] += inside[i][o];
    for (size_t i = 0; i < n; ++i)
        for (size_t o = 0; o < n; ++o) {
            if (!inside[i][o]) continue;
            if (inside[o][i]) throw InputError(names[i] + " and " + names[o] + " enclose the same space");
            if (parent[i] < 0 || depth[o] > depth[parent[i]]) parent[i] = int32_t(o);
        }
    // The surfaces around one must themselves be nested, each in the next.
    for (size_t i = 0; i < n; ++i)
        for (size_t o = 0; o < n; ++o)
            if (inside[i][o] && o != size_t(parent[i]) && !inside[parent[i]][o])
                throw InputError(names[i] + " lies inside " + names[o] + " and " + names[parent[i]] +
                                 ", which are not nested");
    return parent;
}

}  // namespace tetglow
