#include "scene/MeshFile.h"
#include "tet/SelfIntersection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "TestMeshes.h"

using namespace tetglow;

namespace {

using Pair = std::optional<std::pair<uint32_t, uint32_t>>;

void append(TriangleMesh& to, const TriangleMesh& from) {
    const auto offset = static_cast<uint32_t>(to.positions.size());
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    for (auto t : from.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

TriangleMesh transformed(TriangleMesh mesh, const glm::dmat3& m, const glm::dvec3& offset) {
    for (auto& p : mesh.positions) p = m * p + offset;
    return mesh;
}

glm::dmat3 rotation(double yaw, double pitch) {
    const double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
    return glm::dmat3(cy, sy, 0, -sy, cy, 0, 0, 0, 1) * glm::dmat3(1, 0, 0, 0, cp, sp, 0, -sp, cp);
}

// [-1, 1]^3, outward winding; vertex k has coordinate bits x = k & 1, y = k & 2, z = k & 4.
TriangleMesh cube() {
    TriangleMesh m;
    for (int k = 0; k < 8; ++k) m.positions.push_back({k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1});
    const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

TriangleMesh tetrahedron() {
    return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

TriangleMesh octahedron() {
    return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
            {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

// Unit UV sphere with 2 * slices * (stacks - 1) triangles; vertex 0 is the north pole.
TriangleMesh uvSphere(uint32_t slices, uint32_t stacks) {
    TriangleMesh m;
    const double pi = std::numbers::pi;
    m.positions.push_back({0, 0, 1});
    for (uint32_t i = 1; i < stacks; ++i)
        for (uint32_t j = 0; j < slices; ++j) {
            const double theta = pi * i / stacks, phi = 2 * pi * j / slices;
            m.positions.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    const auto south = static_cast<uint32_t>(m.positions.size());
    m.positions.push_back({0, 0, -1});
    const auto ring = [&](uint32_t i, uint32_t j) { return 1 + (i - 1) * slices + j % slices; };
    for (uint32_t j = 0; j < slices; ++j) {
        m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        for (uint32_t i = 1; i + 1 < stacks; ++i) {
            m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
        m.triangles.push_back({ring(stacks - 1, j), south, ring(stacks - 1, j + 1)});
    }
    return m;
}

// An n x n square grid of unit cells in the plane z = height, two triangles each.
TriangleMesh sheet(uint32_t n, double height) {
    TriangleMesh m;
    for (uint32_t y = 0; y <= n; ++y)
        for (uint32_t x = 0; x <= n; ++x) m.positions.push_back({x, y, height});
    const auto at = [&](uint32_t x, uint32_t y) { return y * (n + 1) + x; };
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            m.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
            m.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    return m;
}

// The two triangles alone, with shared corners still welded.
TriangleMesh pairMesh(const TriangleMesh& mesh, uint32_t i, uint32_t j) {
    TriangleMesh out;
    std::map<uint32_t, uint32_t> index;
    for (uint32_t t : {i, j}) {
        std::array<uint32_t, 3> tri;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.triangles[t][k];
            const auto [it, added] = index.try_emplace(v, static_cast<uint32_t>(out.positions.size()));
            if (added) out.positions.push_back(mesh.positions[v]);
            tri[k] = it->second;
        }
        out.triangles.push_back(tri);
    }
    return out;
}

Pair bruteForce(const TriangleMesh& mesh) {
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t j = i + 1; j < mesh.triangles.size(); ++j)
            if (findSelfIntersection(pairMesh(mesh, i, j))) return std::pair{i, j};
    return std::nullopt;
}

// Independent floating-point check for generic configurations: does segment pq cross the
// interior of triangle t (Moeller-Trumbore)?
bool pierces(const glm::dvec3& p, const glm::dvec3& q, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 d = q - p, e1 = t[1] - t[0], e2 = t[2] - t[0], h = glm::cross(d, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-12) return false;
    const glm::dvec3 s = p - t[0], r = glm::cross(s, e1);
    const double u = glm::dot(s, h) / det, v = glm::dot(d, r) / det, along = glm::dot(e2, r) / det;
    return u > 0 && v > 0 && u + v < 1 && along > 0 && along < 1;
}

bool edgePierces(const TriangleMesh& m, uint32_t a, uint32_t b) {
    const auto corners = [&](uint32_t t) { return std::array{m.corner(t, 0), m.corner(t, 1), m.corner(t, 2)}; };
    for (int k = 0; k < 3; ++k)
        if (pierces(m.corner(a, k), m.corner(a, (k + 1) % 3), corners(b)) ||
            pierces(m.corner(b, k), m.corner(b, (k + 1) % 3), corners(a)))
            return true;
    return false;
}

}  // namespace

TEST(SelfIntersection, ClosedConvexMeshesHaveNone) {
    EXPECT_FALSE(findSelfIntersection(tetrahedron()));
    EXPECT_FALSE(findSelfIntersection(octahedron()));
    EXPECT_FALSE(findSelfIntersection(cube()));
    EXPECT_FALSE(findSelfIntersection(TriangleMesh{}));
}

TEST(SelfIntersection, DisjointCubesHaveNone) {
    TriangleMesh m = cube();
    append(m, transformed(cube(), rotation(0.3, 0.2), {3.5, 0.1, 0}));
    EXPECT_FALSE(findSelfIntersection(m));
}

TEST(SelfIntersection, InterpenetratingCubesGiveAPairFromBoth) {
    TriangleMesh m = cube();
    append(m, transformed(cube(), rotation(0.3, 0.2), {1.3, 0.4, -0.2}));
    const Pair hit = findSelfIntersection(m);
    ASSERT_TRUE(hit);
    EXPECT_LT(hit->first, 12u);
    EXPECT_GE(hit->second, 12u);
    EXPECT_TRUE(edgePierces(m, hit->first, hit->second));
}

TEST(SelfIntersection, VertexPushedThroughOppositeFace) {
    TriangleMesh m = cube();
    m.positions[7] = {-1.5, 0.25, 0.125};
    EXPECT_TRUE(findSelfIntersection(m));
}

TEST(SelfIntersection, SharedEdgeOnlyFoldOverIntersects) {
    const TriangleMesh fold{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 2, 0}}, {{0, 1, 2}, {1, 0, 3}}};
    EXPECT_EQ(findSelfIntersection(fold), Pair(std::pair{0u, 1u}));
    const TriangleMesh flat{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, -2, 0}}, {{0, 1, 2}, {1, 0, 3}}};
    EXPECT_FALSE(findSelfIntersection(flat));
    const TriangleMesh bent{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 2, 1e-30}}, {{0, 1, 2}, {1, 0, 3}}};
    EXPECT_FALSE(findSelfIntersection(bent));
}

TEST(SelfIntersection, SharedVertexIntersectsOnlyBeyondIt) {
    const auto withSecond = [](glm::dvec3 b1, glm::dvec3 b2) {
        return findSelfIntersection(TriangleMesh{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, b1, b2}, {{0, 1, 2}, {0, 3, 4}}});
    };
    EXPECT_TRUE(withSecond({0.5, 0.5, 1}, {0.5, 0.5, -1}));     // opposite edge pierces the face
    EXPECT_TRUE(withSecond({0.5, 0.5, 0}, {0.5, 0.5, 1}));      // opposite edge starts on the face
    EXPECT_TRUE(withSecond({1, -1, 0}, {1, 1, 0}));             // coplanar, wedges overlap
    EXPECT_TRUE(withSecond({4, 0, 0}, {1, -1, 0}));             // coplanar, along a common edge line
    EXPECT_FALSE(withSecond({-1, 0, 1}, {-1, 0, -1}));          // crosses the plane only at the vertex
    EXPECT_FALSE(withSecond({-1, 1, 0}, {-1, -1, 0}));          // coplanar, wedges apart
    EXPECT_FALSE(withSecond({-1, -1, 1}, {-1, -1, -1}));        // meets the plane on the far side
    EXPECT_FALSE(withSecond({0.5, 0.5, 1}, {1.5, 0.5, 1e-9}));  // passes just above the face
}

TEST(SelfIntersection, TouchingCountsNearMissDoesNot) {
    const auto withApex = [](double height) {
        return findSelfIntersection(TriangleMesh{
            {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, height}, {1, 1, 1}, {2, 1, 1}}, {{0, 1, 2}, {3, 4, 5}}});
    };
    EXPECT_EQ(withApex(0), Pair(std::pair{0u, 1u}));  // vertex on the face interior
    EXPECT_FALSE(withApex(1e-9));
    EXPECT_TRUE(withApex(-1e-9));
    // Coplanar triangles that share no vertex but touch at an edge point.
    const TriangleMesh edgeTouch{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {2, 2, 0}, {3, 3, 0}, {4, 2, 0}},
                                 {{0, 1, 2}, {3, 4, 5}}};
    EXPECT_TRUE(findSelfIntersection(edgeTouch));
}

TEST(SelfIntersection, FirstPairMatchesBruteForce) {
    for (double dx : {0.5, 1.2, 1.9, 2.5}) {
        TriangleMesh m = uvSphere(12, 8);
        append(m, transformed(uvSphere(10, 7), rotation(0.4, 0.7), {dx, 0.2, 0.1}));
        append(m, transformed(cube(), rotation(1.0, 0.3) * 0.6, {dx / 2, -0.9, 0.3}));
        EXPECT_EQ(findSelfIntersection(m), bruteForce(m)) << "offset " << dx;
    }
}

// Flat, axis-aligned triangles have no extent along one axis, which the broad phase must survive.
TEST(SelfIntersection, FlatSheets) {
    TriangleMesh m = sheet(40, 0);
    EXPECT_FALSE(findSelfIntersection(m));
    append(m, sheet(40, 1));
    EXPECT_FALSE(findSelfIntersection(m));
    // A triangle lying in the lower sheet, across many of its cells.
    append(m, TriangleMesh{{{2.5, 3.25, 0}, {30.5, 3.75, 0}, {10.25, 20.5, 0}}, {{0, 1, 2}}});
    const auto last = static_cast<uint32_t>(m.triangles.size() - 1);
    uint32_t first = 0;
    while (!findSelfIntersection(pairMesh(m, first, last))) ++first;
    EXPECT_EQ(findSelfIntersection(m), Pair(std::pair{first, last}));
}

TEST(SelfIntersection, LargeSphere) {
    TriangleMesh m = uvSphere(250, 101);
    ASSERT_EQ(m.triangles.size(), 50000u);
    EXPECT_FALSE(findSelfIntersection(m));

    const uint32_t moved = 1 + 50 * 250;  // on the ring next to the equator, at +x
    m.positions[moved] = {-1.1, 0.001, 0.002};
    const Pair hit = findSelfIntersection(m);
    ASSERT_TRUE(hit);
    const auto uses = [&](uint32_t t) { return std::ranges::count(m.triangles[t], moved) > 0; };
    EXPECT_TRUE(uses(hit->first) || uses(hit->second));
}

TEST(SelfIntersection, SharedMeshesHaveNone) {
    for (const char* name : {"blub", "spot", "bob"})
        if (test::sharedMesh(name).empty()) GTEST_SKIP() << name << ".obj not tested: ../shared/meshes not found";
    for (const char* name : {"blub", "spot", "bob"})
        EXPECT_FALSE(findSelfIntersection(readMesh(test::sharedMesh(name)))) << name;
}
