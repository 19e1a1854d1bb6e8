#include "tet/WindingGrid.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>

#include "tet/WindingNumber.h"

namespace tetglow {

TriangleMesh windingGridBoundary(const TriangleMesh& soup, int cells) {
    const Bounds3 b = bounds(soup);
    const glm::dvec3 extent = b.hi - b.lo;
    const double h = std::max({extent.x, extent.y, extent.z}) / cells;
    // One cell of margin on every side, so that every inside cell has an outside beyond it.
    const glm::ivec3 n = glm::max(glm::ivec3(glm::ceil(extent / h)), glm::ivec3(1)) + 2;
    const glm::dvec3 origin = b.lo - h;
    const auto index = [&](int i, int j, int k) {
        return (size_t(i) * size_t(n.y) + size_t(j)) * size_t(n.z) + size_t(k);
    };
    const WindingNumber winding(soup);
    std::vector<char> inside(size_t(n.x) * size_t(n.y) * size_t(n.z), 0);
    tbb::parallel_for(tbb::blocked_range<int>(1, n.x - 1), [&](const auto& range) {
        for (int i = range.begin(); i != range.end(); ++i)
            for (int j = 1; j < n.y - 1; ++j)
                for (int k = 1; k < n.z - 1; ++k)
                    inside[index(i, j, k)] = winding.classify(origin + h * (glm::dvec3(i, j, k) + 0.5)) > 0.5;
    });
    if (std::find(inside.begin(), inside.end(), 1) == inside.end())
        throw InputError("mesh encloses no volume: its winding number stays at or below 1/2 at every grid cell");

    // Corners rounded to float one axis at a time: rounding is monotone, so the grid stays a
    // grid of axis-aligned planes and no square can cross another.
    TriangleMesh out;
    std::unordered_map<size_t, uint32_t> corners;
    const auto corner = [&](int i, int j, int k) {
        const size_t key = (size_t(i) * size_t(n.y + 1) + size_t(j)) * size_t(n.z + 1) + size_t(k);
        auto [it, added] = corners.emplace(key, uint32_t(out.positions.size()));
        if (added) {
            const glm::dvec3 p = origin + h * glm::dvec3(i, j, k);
            out.positions.push_back({roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)});
        }
        return it->second;
    };
    for (int i = 1; i < n.x; ++i)
        for (int j = 1; j < n.y; ++j)
            for (int k = 1; k < n.z; ++k)
                for (int axis = 0; axis < 3; ++axis) {
                    // The face between the cell at (i, j, k) and the one before it along `axis`.
                    glm::ivec3 c(i, j, k), before = c;
                    before[axis] -= 1;
                    const bool in = inside[index(c.x, c.y, c.z)],
                               beforeIn = inside[index(before.x, before.y, before.z)];
                    if (in == beforeIn) continue;
                    glm::ivec3 u(0), v(0);
                    u[(axis + 1) % 3] = 1;
                    v[(axis + 2) % 3] = 1;
                    // Counter-clockwise about +axis; outward is +axis where the cell before is inside.
                    std::array<uint32_t, 4> q = {corner(c.x, c.y, c.z), corner(c.x + u.x, c.y + u.y, c.z + u.z),
                                                 corner(c.x + u.x + v.x, c.y + u.y + v.y, c.z + u.z + v.z),
                                                 corner(c.x + v.x, c.y + v.y, c.z + v.z)};
                    if (in) std::swap(q[1], q[3]);
                    out.triangles.push_back({q[0], q[1], q[2]});
                    out.triangles.push_back({q[0], q[2], q[3]});
                }
    return out;
}

}  // namespace tetglow
