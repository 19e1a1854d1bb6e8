#include "StabilityCases.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::test {

TetTraversal tetsOf(const TriangleMesh& mesh) {
    TetOptions o;
    o.useCache = false;
    return TetTraversal(tetrahedralize(mesh, o));
}

void expectTetsRefuse(const TriangleMesh& mesh, const std::string& problem) {
    try {
        TetOptions o;
        o.useCache = false;
        o.strict = true;
        tetrahedralize(mesh, o);
        ADD_FAILURE() << "the tets accepted a mesh that should fail with: " << problem;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    }
}

TriangleMesh tiltedPolyhedron(int subdivisions) {
    TriangleMesh m = icosphere(subdivisions, 0.8, {0.1, -0.2, 0.3});
    // A fixed linear map with no axis-aligned direction preserved (determinant > 0).
    for (auto& p : m.positions) p = {p.x + 0.4 * p.y, 1.6 * p.y - 0.3 * p.z, p.z + 0.2 * p.x};
    return m;
}

TriangleMesh thinPlate(double thickness) {
    TriangleMesh m = box(glm::dvec3(-0.5, -0.5, -thickness / 2), glm::dvec3(0.5, 0.5, thickness / 2));
    // Coefficients with few bits: the products are exact.
    for (auto& p : m.positions) p = {p.x + 0.25 * p.y + 0.5 * p.z, p.y + 0.75 * p.z, 0.5 * p.x + 0.25 * p.y + p.z};
    return m;
}

std::vector<uint32_t> slivers(const TetMesh& mesh, double quality) {
    std::vector<uint32_t> found;
    for (uint32_t t = 0; t < mesh.tets.size(); ++t) {
        double longest = 0, shortest = INFINITY;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const double l = glm::distance(mesh.vertices[mesh.tets[t][i]], mesh.vertices[mesh.tets[t][j]]);
                longest = std::max(longest, l);
                shortest = std::min(shortest, l);
            }
        // A regular tet has volume / longest^3 = 1 / (6 sqrt 2).
        if (mesh.tetVolume(t) / std::pow(longest, 3) * 6 * std::sqrt(2.0) < quality && shortest > longest / 3)
            found.push_back(t);
    }
    return found;
}

std::vector<NamedLine> degenerateLines(const TriangleMesh& convex) {
    const Bounds3 box = bounds(convex);
    const double far = 2 * box.diagonal();
    std::vector<NamedLine> lines;
    auto axisLines = [&](const std::string& kind, const glm::dvec3& p) {
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 d(0);
            d[axis] = 1;
            lines.push_back({kind, Ray{p - d * far, d}});
        }
    };
    for (const auto& v : convex.positions) axisLines("through a vertex", v);
    for (uint32_t t = 0; t < convex.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (convex.triangles[t][k] < convex.triangles[t][(k + 1) % 3])  // each edge once
                axisLines("through an edge", 0.5 * (convex.corner(t, k) + convex.corner(t, (k + 1) % 3)));
    std::vector<glm::dvec3> vertexNormal(convex.positions.size(), glm::dvec3(0));
    for (uint32_t t = 0; t < convex.triangles.size(); ++t) {
        const glm::dvec3 a = convex.corner(t, 0), b = convex.corner(t, 1), c = convex.corner(t, 2);
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a)), centre = (a + b + c) / 3.0;
        for (uint32_t v : convex.triangles[t]) vertexNormal[v] += n;
        // Into the face at a grazing angle, along the direction towards its first corner.
        const glm::dvec3 along = glm::normalize((a - centre) - glm::dot(a - centre, n) * n);
        for (double angle : {1e-2, 1e-4, 1e-6, 1e-8}) {
            const glm::dvec3 d = glm::normalize(std::cos(angle) * along - std::sin(angle) * n);
            char kind[32];
            std::snprintf(kind, sizeof kind, "grazing at %.0e rad", angle);
            lines.push_back({kind, Ray{centre - d * far, d}});
        }
    }
    for (size_t v = 0; v < convex.positions.size(); ++v) {
        // In the plane normal to the mean of the face normals around v: a supporting plane.
        const glm::dvec3 n = glm::normalize(vertexNormal[v]);
        const glm::dvec3 d = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.5, 0.8)));
        lines.push_back({"touching a vertex", Ray{convex.positions[v] - d * far, d}});
    }
    return lines;
}

}  // namespace tetglow::test
