// The winding number's tree over many disjoint closed shells: a cluster of whole closed shells
// adds exactly 0 outside its bounding sphere, so a point costs only the shells near it. The
// repair of 20,000 disjoint tetrahedra spent most of its time in the tree's dipoles and
// triangles of shells that add nothing.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "tet/WindingNumber.h"

namespace tetglow {
namespace {

// n^3 small tetrahedra, wound outward, at irregular spacing so that no sum cancels by chance.
TriangleMesh tetrahedra(int n) {
    TriangleMesh m;
    for (int i = 0; i < n * n * n; ++i) {
        const glm::dvec3 o(0.731 * (i % n) + 0.0137 * i, 0.693 * (i / n % n), 0.717 * (i / n / n));
        const auto base = uint32_t(m.positions.size());
        for (const glm::dvec3& c :
             {glm::dvec3(0), glm::dvec3(0.31, 0, 0), glm::dvec3(0, 0.29, 0), glm::dvec3(0, 0, 0.33)})
            m.positions.push_back(o + c);
        for (const auto& f : {std::array<uint32_t, 3>{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}})
            m.triangles.push_back({base + f[0], base + f[1], base + f[2]});
    }
    return m;
}

TEST(WindingShells, DisjointClosedShellsAddExactlyNothingOutside) {
    const int n = 8;
    const TriangleMesh m = tetrahedra(n);
    const WindingNumber winding(m);
    for (int i = 0; i < n * n * n; i += 37) {
        const glm::dvec3 a = m.positions[4 * i], b = m.positions[4 * i + 1], c = m.positions[4 * i + 2],
                         d = m.positions[4 * i + 3];
        EXPECT_NEAR(winding.approximate((a + b + c + d) / 4.0), 1.0, 1e-12) << i;
    }
    // Outside the sphere around all of them, but nearer than the tree's far ratio: the tree
    // descended into clusters and summed solid angles and dipoles to a residue of rounding.
    const Bounds3 box = bounds(m);
    const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
    const double reach = glm::length(box.hi - box.lo);
    for (const glm::dvec3& direction : {glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0.6, 0.48, -0.64)}) {
        const glm::dvec3 p = centre + reach * direction;
        EXPECT_EQ(winding.approximate(p), 0.0) << p.x << " " << p.y << " " << p.z;
    }
}

}  // namespace
}  // namespace tetglow
