// The procedural cumulus cloud: valid TetGen input for every seed and resolution, and the
// committed scenes/meshes/cloud.obj is exactly what the generator makes by default.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "TestMeshes.h"
#include "scene/CloudGenerator.h"
#include "scene/MeshFile.h"
#include "tet/MeshValidation.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

CloudParams withSeed(uint32_t seed) {
    CloudParams p;
    p.seed = seed;
    return p;
}

// Why it cannot self-intersect: star-shaped about the origin, every triangle faces away from it
// (positive orientation seen from the origin), so the triangles' cones tile space without overlap.
void expectStarShaped(const TriangleMesh& m) {
    size_t facingIn = 0;
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        facingIn += glm::dot(m.corner(t, 0), glm::cross(m.corner(t, 1), m.corner(t, 2))) <= 0;
    EXPECT_EQ(facingIn, 0u) << "triangles not facing away from the origin";
    // Bounded slope of the radius keeps the triangles well shaped.
    EXPECT_GT(test::minAngleDegrees(m), 10.0) << "sliver triangles";
}

// Closed, manifold, outward, no self-intersection, rounded to float: nothing to repair.
void expectValidAsIs(const TriangleMesh& m) {
    TriangleMesh copy = m;
    const ValidationReport report = validateAndRepair(copy);
    EXPECT_EQ(report.weldedVertices, 0u);
    EXPECT_EQ(report.unusedVertices, 0u);
    EXPECT_EQ(report.flippedTriangles, 0u);
    EXPECT_EQ(report.components, 1u);
    EXPECT_TRUE(report.notes.empty()) << report.notes.front();
    // Validation renumbers the vertices, but every corner must keep its position (already float).
    ASSERT_EQ(copy.triangles.size(), m.triangles.size());
    size_t moved = 0;
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) moved += copy.corner(t, k) != m.corner(t, k);
    EXPECT_EQ(moved, 0u) << "corners not rounded to float";
}

// 2 wide, 1.2 tall, no deeper than wide, the origin inside about a quarter of the way up.
void expectSize(const TriangleMesh& m) {
    const Bounds3 b = bounds(m);
    EXPECT_NEAR(b.hi.x - b.lo.x, 2.0, 1e-6);
    EXPECT_NEAR(b.hi.y - b.lo.y, 1.2, 1e-6);
    EXPECT_LE(b.hi.z - b.lo.z, 2.0);
    EXPECT_GT(b.hi.z - b.lo.z, 1.0);
    EXPECT_NEAR(-b.lo.y / 1.2, 0.25, 0.05);
}

TEST(CloudGenerator, DefaultIsAValidMedium) {
    const TriangleMesh m = makeCloud();
    EXPECT_EQ(m.triangles.size(), 20480u);
    expectValidAsIs(m);
    expectStarShaped(m);
    expectSize(m);
}

// Flat-ish bottom: the lowest tenth of the vertices lies within 1% of the height of the lowest.
TEST(CloudGenerator, BottomIsFlat) {
    const TriangleMesh m = makeCloud();
    std::vector<double> ys;
    for (const auto& p : m.positions) ys.push_back(p.y);
    std::sort(ys.begin(), ys.end());
    EXPECT_LT(ys[ys.size() / 10] - ys.front(), 0.012);
}

TEST(CloudGenerator, TetrahedralizesWithoutSteinerPoints) {
    TetOptions o;
    o.useCache = false;
    const TriangleMesh surface = makeCloud();
    const TetMesh tets = tetrahedralize(surface, o);
    EXPECT_EQ(tets.vertices.size(), surface.positions.size()) << "Steiner points";
    EXPECT_EQ(tets.surface.size(), surface.triangles.size());
    const double volume = signedVolume(surface);
    EXPECT_NEAR(tets.volume(), volume, 1e-9 * volume);
    EXPECT_NEAR(tets.surfaceVolume(), volume, 1e-9 * volume);
}

TEST(CloudGenerator, EverySeedAndResolutionIsValid) {
    for (uint32_t seed : {0u, 2u, 3u, 18u, 77u, 4294967295u}) {  // 18 comes out deeper than wide and is turned
        SCOPED_TRACE("seed " + std::to_string(seed));
        const TriangleMesh m = makeCloud(withSeed(seed));
        expectValidAsIs(m);
        expectStarShaped(m);
        expectSize(m);
    }
    for (int subdivisions : {1, 2, 3, 4, 6}) {
        SCOPED_TRACE("subdivisions " + std::to_string(subdivisions));
        CloudParams p;
        p.subdivisions = subdivisions;
        const TriangleMesh m = makeCloud(p);
        EXPECT_EQ(m.triangles.size(), 20u << (2 * subdivisions));
        expectValidAsIs(m);
    }
}

TEST(CloudGenerator, ShapeKnobsAtTheirLimitsStayValid) {
    for (int bumps : {1, 2, 16})
        for (double roughness : {0.0, 0.15}) {
            SCOPED_TRACE(std::to_string(bumps) + " bumps, roughness " + std::to_string(roughness));
            CloudParams p;
            p.bumps = bumps;
            p.roughness = roughness;
            const TriangleMesh m = makeCloud(p);
            expectValidAsIs(m);
            expectStarShaped(m);
        }
}

TEST(CloudGenerator, DeterministicForASeed) {
    const TriangleMesh a = makeCloud(withSeed(5)), b = makeCloud(withSeed(5)), c = makeCloud(withSeed(6));
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_NE(a.positions, c.positions);
    EXPECT_GT(std::abs(signedVolume(a) - signedVolume(c)), 1e-3);
}

TEST(CloudGenerator, RejectsParametersOutOfRange) {
    auto make = [](int subdivisions, int bumps, double roughness) {
        CloudParams p;
        p.subdivisions = subdivisions;
        p.bumps = bumps;
        p.roughness = roughness;
        return makeCloud(p);
    };
    EXPECT_THROW(make(0, 7, 0.03), InputError);
    EXPECT_THROW(make(9, 7, 0.03), InputError);
    EXPECT_THROW(make(5, 0, 0.03), InputError);
    EXPECT_THROW(make(5, 17, 0.03), InputError);
    EXPECT_THROW(make(5, 7, -0.01), InputError);
    EXPECT_THROW(make(5, 7, 0.2), InputError);
    EXPECT_THROW(make(5, 7, std::nan("")), InputError);
}

TEST(CloudGenerator, CommandWritesTheCloud) {
    const std::string path = test::tempDir() + "/cloud.obj";
    const auto r = test::runTetglow("generate cloud --seed 9 --subdivisions 3 -o " + path);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const TriangleMesh written = readMesh(path), expected = makeCloud({3, 9});
    ASSERT_EQ(written.positions.size(), expected.positions.size());
    EXPECT_EQ(written.triangles, expected.triangles);
    // Nine digits bring float positions back exactly once snapped to float, as validation does.
    for (size_t v = 0; v < expected.positions.size(); ++v) {
        const glm::dvec3& p = written.positions[v];
        ASSERT_EQ(glm::dvec3(roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)), expected.positions[v]);
    }

    const auto bad = test::runTetglow("generate cloud --bumps 40 -o " + path);
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.err.find("bumps must be 1 to 16"), std::string::npos) << bad.err;
}

TEST(CloudGenerator, CommittedObjIsTheDefaultCloud) {
    const TriangleMesh expected = makeCloud();
    const TriangleMesh committed = readMesh(TETGLOW_SOURCE_DIR "/scenes/meshes/cloud.obj");
    ASSERT_EQ(committed.positions.size(), expected.positions.size())
        << "regenerate: tetglow generate cloud -o scenes/meshes/cloud.obj";
    for (size_t v = 0; v < expected.positions.size(); ++v) {
        const glm::dvec3& c = committed.positions[v];
        ASSERT_EQ(glm::dvec3(roundToFloat(c.x), roundToFloat(c.y), roundToFloat(c.z)), expected.positions[v])
            << "vertex " << v;
    }
    EXPECT_EQ(committed.triangles, expected.triangles);
}

}  // namespace
}  // namespace tetglow
