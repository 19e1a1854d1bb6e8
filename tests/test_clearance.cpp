// A point's distance to the medium's boundary bounded from below by a coarse grid (ClearanceGrid),
// against the closed form inside a convex mesh; and the shadow roulette's tests that this bound
// makes certain, decided before any walk (sureDepth), keep the transmittance.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/PathStep.h"
#include "media/ShadowRay.h"
#include "scene/Scene.h"
#include "tet/ClearanceGrid.h"
#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

// Inside a convex polyhedron the distance to its boundary is the least distance to a face's plane.
double convexDistance(const TriangleMesh& convex, const glm::dvec3& p) {
    double d = INFINITY;
    for (const auto& f : convex.triangles) {
        const glm::dvec3 a = convex.positions[f[0]];
        const glm::dvec3 n = glm::normalize(glm::cross(convex.positions[f[1]] - a, convex.positions[f[2]] - a));
        d = std::min(d, std::abs(glm::dot(p - a, n)));
    }
    return d;
}

TEST(ClearanceGrid, BoundsTheDistanceToTheBoundaryFromBelowWithinACell) {
    const TriangleMesh sphere = icosphere(3);
    const TetMesh mesh = tetrahedralize(sphere, test::noCache());
    const ClearanceGrid grid(mesh, 32);
    const double cell = 2.0 / 32;  // the box's longest side over 32, within the float rounding
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int inside = 0;
    double slack = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        if (glm::length(p) > 0.9) continue;  // inside the inscribed ball of icosphere(3)
        ++inside;
        const double exact = convexDistance(sphere, p), bound = grid.lowerBound(p);
        ASSERT_LE(bound, exact + 1e-12) << p.x << " " << p.y << " " << p.z;
        // d(c) >= d(p) - |p - c| for the nearest corner c: at most 2 |p - c| short, 1.74 cells.
        ASSERT_GE(bound, exact - 1.74 * cell - 1e-9) << p.x << " " << p.y << " " << p.z;
        slack = std::max(slack, exact - bound);
    }
    EXPECT_GT(inside, 5000);
    EXPECT_GT(slack, 0.2 * cell);  // the bound is not the distance itself
    EXPECT_NEAR(grid.largest(), convexDistance(sphere, glm::dvec3(0)), 0.87 * cell);  // a corner near the centre
    // Outside its box, and for NaN, no bound.
    EXPECT_EQ(grid.lowerBound({0, 0, 3}), 0.0);
    EXPECT_EQ(grid.lowerBound(glm::dvec3(std::numeric_limits<double>::quiet_NaN())), 0.0);
    EXPECT_TRUE(ClearanceGrid().empty());
    EXPECT_EQ(ClearanceGrid().lowerBound(glm::dvec3(0)), 0.0);
}

// From the centre of a dense sphere (optical depth 10 to its boundary) a shadow ray's first
// roulette tests are certain: decided before the walk, they keep the transmittance's mean, and
// three in four rays end at each.
TEST(ClearanceGrid, ShadowRouletteDecidedInTheClearBallKeepsTheTransmittance) {
    const Scene scene(test::sceneWith(test::sphereMedium(RGB(10, 10.5, 11), RGB(0)), 8));
    const Ray ray{{0.02, -0.01, 0.03}, glm::normalize(glm::dvec3(0.3, 0.5, 0.8))};
    const VolumeState centre = scene.volumeAt(ray.o);
    ASSERT_TRUE(centre.inside());
    const Volume& volume = *scene.volumes()[0].volume;
    // The sure depth: the smallest extinction over the bound on the distance to the boundary.
    const double sure = sureDepth(volume, centre.start, ray.o, INFINITY);
    EXPECT_GT(sure, 10 * (0.95 - 0.11));
    EXPECT_LE(sure, 10 * 1.0);
    EXPECT_EQ(sureDepth(volume, centre.start, ray.o, 0.2), 10 * 0.2);  // a ray that ends inside the ball
    // Tests at ln 20 + k ln 4 below it.
    const int tests = int(std::floor((sure - std::log(20.0)) / std::log(4.0))) + 1;
    ASSERT_GE(tests, 3);
    const RGB exact = transmittance(scene, ray, 10, centre);
    const int n = 400000;
    const test::Estimate e = test::estimateMean(n, [&](int i) {
        Rng rng(9, uint64_t(i));
        return transmittance(scene, ray, 10, centre, &rng);
    });
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], exact[c], 5 * e.stdError[c]) << c;
    // At least the certain tests, each survived with probability 1/4.
    EXPECT_LE(double(n - e.black) / n, 1.2 * std::pow(0.25, tests));
}

}  // namespace
}  // namespace tetglow
