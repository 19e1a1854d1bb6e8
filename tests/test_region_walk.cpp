// Walking region to region: the tet walk crosses interfaces itself (no Embree), and optical
// depths along lines through nested media equal the closed form from the meshes' chords.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "tet/Nesting.h"
#include "tet/TetTraversal.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

TriangleMesh validated(TriangleMesh m) {
    validateAndRepair(m);
    return m;
}

// Three levels of absorbing spheres and an empty cavity (sigma 0) in the innermost.
struct NestedSpheres {
    std::vector<TriangleMesh> meshes{validated(icosphere(3, 1.0)), validated(icosphere(3, 0.6, {0.1, 0, 0})),
                                     validated(icosphere(2, 0.3, {0.2, 0.05, 0})),
                                     validated(icosphere(2, 0.12, {0.22, 0.05, 0.03}))};
    std::vector<double> sigma{0.7, 2.0, 5.0, 0.0};
    TetTraversal volume{[&] {
        TetOptions o;
        o.useCache = false;
        return tetrahedralize(meshes, {"body", "organ", "core", "cavity"}, o);
    }()};

    // The closed form: each region's length is its mesh's chord minus its children's.
    double exactDepth(const Ray& ray) const {
        const auto& m = volume.mesh();
        double tau = 0;
        for (size_t r = 0; r < meshes.size(); ++r) {
            double length = test::convexChord(meshes[r], ray);
            for (size_t c = 0; c < meshes.size(); ++c)
                if (m.regionParent[c] == int32_t(r)) length -= test::convexChord(meshes[c], ray);
            tau += sigma[r] * length;
        }
        return tau * glm::length(ray.d);
    }
    // The walk's: every segment in its tet's region; counts the interfaces crossed.
    double walkDepth(const Ray& ray, double tmax, int64_t start, size_t& interfaces) const {
        double tau = 0;
        int32_t last = -1;
        const bool ok = volume.traverse(
            ray, 0.0, tmax,
            [&](const WalkSegment& s) {
                const int32_t r = volume.mesh().region(s.tet);
                interfaces += last >= 0 && r != last;
                last = r;
                tau += sigma[r] * (s.tOut - s.tIn);
                return true;
            },
            start);
        EXPECT_TRUE(ok);
        return tau * glm::length(ray.d);
    }
};

TEST(RegionWalk, TransmittanceThroughNestedSpheresIsTheClosedForm) {
    const NestedSpheres scene;
    std::mt19937_64 rng(14);
    constexpr int kLines = 100000;
    size_t interfaces = 0, through = 0;
    double worst = 0;
    const uint64_t queriesBefore = surfaceQueries();
    for (int i = 0; i < kLines; ++i) {
        const glm::dvec3 a = test::onSphere(rng, 1.3), b = test::onSphere(rng, 1.3);
        const Ray ray{a, b - a};
        const double exact = scene.exactDepth(ray);
        const double walked = scene.walkDepth(ray, 1.0, TetTraversal::kOutside, interfaces);
        through += exact > 0;
        // Relative error of exp(-tau): exp(exact - walked) - 1.
        worst = std::max(worst, std::abs(std::expm1(exact - walked)));
    }
    EXPECT_LE(worst, 1e-9);
    EXPECT_GT(through, size_t(kLines) / 2);
    EXPECT_GT(interfaces, size_t(kLines) / 2);
    // At most one Embree query per line, for the entry into the outer sphere (none for a line
    // that misses its box); none at the interfaces.
    EXPECT_LE(surfaceQueries() - queriesBefore, uint64_t(kLines));
    std::printf("worst relative transmittance error %.2e over %d lines, %zu interfaces crossed\n", worst, kLines,
                interfaces);
}

TEST(RegionWalk, RaysThroughVerticesAndEdgesOfTheInterfaces) {
    const NestedSpheres scene;
    const TetMesh& m = scene.volume.mesh();
    std::mt19937_64 rng(5);
    size_t interfaces = 0, rays = 0;
    double worst = 0;
    // Through every vertex of the inner three meshes (exactly: a vertex is an interface vertex,
    // and a ray through it meets several faces at one point) and near the middle of an edge.
    for (uint32_t s = 0; s < m.surface.size(); ++s) {
        if (m.surfaceRegions[s][1] < 0) continue;  // the outer sphere: no interface
        const glm::dvec3 a = m.vertices[m.surface[s][0]], b = m.vertices[m.surface[s][1]];
        for (const glm::dvec3& target : {a, a + 0.5 * (b - a)}) {
            const glm::dvec3 from = test::onSphere(rng, 1.3);
            const Ray ray{from, 2.0 * (target - from)};
            // The whole line beyond `from` (the closed form counts every t >= 0).
            const double err =
                std::abs(scene.walkDepth(ray, INFINITY, TetTraversal::kOutside, interfaces) - scene.exactDepth(ray));
            worst = std::max(worst, err);
            ++rays;
        }
    }
    // Some of these rays meet a face at a small angle, where the crossing's t is known less well
    // (see GrazingTheInterfaceBetweenTouchingBoxes); a ray that took a wrong tet would be off by
    // a chord, 1e-3 or more.
    EXPECT_LE(worst, 1e-10);
    EXPECT_GT(interfaces, rays);
    std::printf("%zu rays through interface vertices and edges: worst optical depth error %.2e\n", rays, worst);
}

TEST(RegionWalk, PointsAreLocatedInTheirRegionAcrossInterfaces) {
    const NestedSpheres scene;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const uint64_t queriesBefore = surfaceQueries();
    int perRegion[4] = {};
    for (int i = 0; i < 20000; ++i) {
        // Half the points near the inner spheres, where the regions are small.
        const glm::dvec3 p = i % 2 ? glm::dvec3(u(rng), u(rng), u(rng))
                                   : glm::dvec3(0.2, 0.05, 0) + 0.35 * glm::dvec3(u(rng), u(rng), u(rng));
        int32_t expected = -1, depth = -1;
        for (int32_t m = 0; m < 4; ++m) {
            const PointSide side = classifyPoint(scene.meshes[m], p);
            ASSERT_NE(side, PointSide::OnSurface);
            if (side == PointSide::Inside && m > depth) {  // listed outermost first
                expected = m;
                depth = m;
            }
        }
        const int64_t t = scene.volume.locate(p);
        ASSERT_EQ(t < 0 ? -1 : scene.volume.mesh().region(uint32_t(t)), expected) << "point " << i;
        if (t >= 0) {
            EXPECT_TRUE(scene.volume.contains(uint32_t(t), p));
            ++perRegion[expected];
        }
    }
    for (int r = 0; r < 4; ++r) EXPECT_GT(perRegion[r], 50) << "region " << r;
    // Points outside the outer sphere but inside its box need the line walk (and Embree); those
    // inside never cross an interface with it, so the count stays below the points outside.
    std::printf("Embree queries for 20000 locations: %llu\n", (unsigned long long)(surfaceQueries() - queriesBefore));
}

TEST(RegionWalk, AWalkThatStaysInsideAsksEmbreeNothing) {
    const NestedSpheres scene;
    std::mt19937_64 rng(3);
    size_t interfaces = 0;
    double worst = 0;
    const uint64_t queriesBefore = surfaceQueries();
    for (int i = 0; i < 2000; ++i) {
        // From inside the core to a point inside the outer sphere's inscribed ball: the ray never
        // leaves the regions.
        const glm::dvec3 a = glm::dvec3(0.2, 0.05, 0) + test::onSphere(rng, 0.2), b = test::onSphere(rng, 0.95);
        const Ray ray{a, b - a};
        const int64_t start = scene.volume.locate(a);
        ASSERT_GE(start, 0);
        const double walked = scene.walkDepth(ray, 1.0, start, interfaces);
        // The closed form from a, up to b: the chords from a minus those from b onward.
        const Ray beyond{b, b - a};
        worst = std::max(worst, std::abs(walked - (scene.exactDepth(ray) - scene.exactDepth(beyond))));
    }
    EXPECT_LE(worst, 1e-12);
    EXPECT_GT(interfaces, 2000u);
    EXPECT_EQ(surfaceQueries(), queriesBefore) << "neither location nor the walk needed Embree";
}

TEST(RegionWalk, TouchingBoxesThroughAnEdgeOfTheirInterface) {
    TetOptions o;
    o.useCache = false;
    const TetTraversal volume(tetrahedralize({box(), box({1, 0, 0}, {2, 1, 1})}, {"left", "right"}, o));
    const double sigma[2] = {1.0, 3.0};
    // Through (1, 0.5, 0.5) and (1, 0.25, 0.25), on the diagonal that splits the shared face
    // (an edge of the interface), and off it by a tilt of 1e-9.
    for (const Ray& ray :
         {Ray{{-1, 0.5, 0.5}, {4, 0, 0}}, Ray{{-1, 0.25, 0.25}, {4, 0, 0}}, Ray{{-1, 0.5, 0.5}, {4, 1e-9, -1e-9}}}) {
        double tau = 0;
        ASSERT_TRUE(volume.traverse(ray, 0.0, 1.0, [&](const WalkSegment& s) {
            tau += sigma[volume.mesh().region(s.tet)] * (s.tOut - s.tIn) * glm::length(ray.d);
            return true;
        }));
        EXPECT_NEAR(tau, 4.0, 1e-12) << ray.o.y << " " << ray.o.z;
    }
}

TEST(RegionWalk, GrazingTheInterfaceBetweenTouchingBoxes) {
    TetOptions o;
    o.useCache = false;
    const TetTraversal volume(tetrahedralize({box(), box({1, 0, 0}, {2, 1, 1})}, {"left", "right"}, o));
    const double sigma[2] = {1.0, 3.0};
    // Through (1, 0.3, 0.5) on the shared face, at angle theta to it: from the floor of the left
    // box (y = 0) to the ceiling of the right one (y = 1), 0.3 / cos(theta) in the left box and
    // 0.7 / cos(theta) in the right.
    for (double theta : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
        const glm::dvec3 d(std::sin(theta), std::cos(theta), 0), p(1, 0.3, 0.5);
        const Ray ray{p - 0.5 * d, d};
        double tau = 0;
        ASSERT_TRUE(volume.traverse(ray, 0.0, 1.5, [&](const WalkSegment& s) {
            tau += sigma[volume.mesh().region(s.tet)] * (s.tOut - s.tIn);
            return true;
        }));
        const double exact = (0.3 * sigma[0] + 0.7 * sigma[1]) / std::cos(theta);
        std::printf("theta %.0e: optical depth error %.2e\n", theta, tau - exact);
        // Where the ray crosses a plane it grazes is only known to about 1e-16 / theta in double
        // precision (the projected face is that thin); the walk stays within that, never a tet off.
        EXPECT_NEAR(tau, exact, 1e-15 / theta) << "theta " << theta;
    }
}

}  // namespace
}  // namespace tetglow
