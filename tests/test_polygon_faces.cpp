// Polygons of more than three corners in OBJ, OFF and PLY: a convex one is its fan, a concave
// one is clipped into ears that neither overlap nor leave gaps (as Assimp triangulates Collada's),
// and one whose outline crosses itself is an error naming file and line.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "MeshWriters.h"
#include "TestMeshes.h"
#include "scene/MeshFile.h"
#include "tet/PolygonTriangulation.h"

namespace tetglow {
namespace {

// The L (0,0) (4,0) (4,1) (1,1) (1,3) (0,3) of area 6, counter-clockwise seen from +z, listed
// from (4,0): the fan from there crosses the L's inner corner.
std::vector<glm::dvec3> lOutline(double z) {
    return {{4, 0, z}, {4, 1, z}, {1, 1, z}, {1, 3, z}, {0, 3, z}, {0, 0, z}};
}

// The L extruded from z = 0 to z = 2 (volume 12), its caps as hexagons.
test::PolygonMesh lPrism() {
    test::PolygonMesh m;
    for (double z : {0.0, 2.0})
        for (const auto& p : lOutline(z)) m.positions.push_back(p);
    m.faces = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};  // bottom seen from -z, top from +z
    for (uint32_t i = 0; i < 6; ++i) m.faces.push_back({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
    return m;
}

// The L alone: a flat sheet, no inside.
test::PolygonMesh lSheet() {
    test::PolygonMesh m;
    m.positions = lOutline(0);
    m.faces = {{0, 1, 2, 3, 4, 5}};
    return m;
}

double triangleArea(const TriangleMesh& m, uint32_t t) {
    return glm::length(glm::cross(m.corner(t, 1) - m.corner(t, 0), m.corner(t, 2) - m.corner(t, 0))) / 2;
}

// The concave caps are cut into triangles of total area 6 each: unsigned areas, so that a fan's
// overlapping triangles (of area 6 only when their signs are counted) show.
TEST(PolygonFaces, AConcavePolygonIsClippedIntoEarsThatCoverItOnce) {
    const std::string path = test::writeTemp("l-prism.obj", test::objText(lPrism()));
    const TriangleMesh mesh = readMesh(path);
    double caps = 0;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
        if (mesh.corner(t, 0).z == mesh.corner(t, 1).z && mesh.corner(t, 1).z == mesh.corner(t, 2).z)
            caps += triangleArea(mesh, t);
    EXPECT_EQ(caps, 12);
    EXPECT_EQ(signedVolume(mesh), 12);
}

// The prism as the user runs it: with the fan, its caps crossed their own sides and the repair
// never came back.
TEST(PolygonFaces, APrismWithConcaveCapsTetrahedralizesToItsVolume) {
    const std::string path = test::writeTemp("l-prism-cli.obj", test::objText(lPrism()));
    const test::CommandResult r = test::runTetglow("tetrahedralize --no-cache --json '" + path + "'", 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"tet_volume\": 12.0,"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"repairs\": []"), std::string::npos) << r.out;
}

// The same flat concave polygon in OBJ and in Collada (which Assimp clips into ears) is refused
// alike: a sheet with no inside.
TEST(PolygonFaces, AFlatConcavePolygonIsRefusedInObjAsInCollada) {
    const std::string obj = test::writeTemp("flat/l.obj", test::objText(lSheet()));
    const std::string dae = test::writeTemp("flat/l.dae", test::collada(lSheet(), "Y_UP"));
    std::string errors[2];
    for (int i = 0; i < 2; ++i) {
        const std::string path = i ? dae : obj;
        const test::CommandResult r = test::runTetglow("tetrahedralize --no-cache '" + path + "'", 60);
        test::expectOneLineError(r, 1, path + ": mesh encloses no volume");
        errors[i] = r.err.substr(r.err.find(path) + path.size());
    }
    EXPECT_EQ(errors[0], errors[1]);
}

// Convex polygons keep their fan, so that meshes read before read the same.
TEST(PolygonFaces, AConvexPolygonIsItsFan) {
    const test::PolygonMesh box = test::boxQuads();
    const TriangleMesh mesh = readMesh(test::writeTemp("box.obj", test::objText(box)));
    std::vector<std::array<uint32_t, 3>> fan;
    for (const auto& f : box.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k) fan.push_back({f[0], f[k], f[k + 1]});
    EXPECT_EQ(mesh.triangles, fan);
}

// A bow tie crosses itself: no triangulation covers it without overlap.
TEST(PolygonFaces, AnOutlineThatCrossesItselfIsAnErrorNamingFileAndLine) {
    const std::string obj = "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nv 1 3 0\nf 1 2 3 4 5\n";
    const std::string path = test::writeTemp("bow-tie.obj", obj);
    try {
        readMesh(path);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path +
                                             ":6: the polygon's outline crosses or touches itself (its edges 2 and "
                                             "5), so it has no triangulation without overlap");
    }
}

// Clipping stays within its bound: a comb of many teeth (every other corner reflex).
TEST(PolygonFaces, AConcavePolygonOfManyCornersIsClipped) {
    std::vector<glm::dvec3> positions;
    const int teeth = 2000;
    for (int i = 0; i < teeth; ++i) {
        positions.emplace_back(2 * i, 0, 0);
        positions.emplace_back(2 * i + 1, 10, 0);
    }
    positions.emplace_back(2 * teeth, 0, 0);
    positions.emplace_back(2 * teeth, -1, 0);
    positions.emplace_back(0, -1, 0);
    std::vector<uint32_t> polygon;
    for (uint32_t i = uint32_t(positions.size()); i-- > 0;) polygon.push_back(i);  // counter-clockwise
    std::vector<std::array<uint32_t, 3>> triangles;
    triangulatePolygon(positions, polygon, triangles, "comb: ");
    EXPECT_EQ(triangles.size(), polygon.size() - 2);
    TriangleMesh mesh{positions, triangles};
    double area = 0;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) area += triangleArea(mesh, t);
    EXPECT_EQ(area, teeth * 10.0 + 2 * teeth);  // the teeth, 2 x 10 / 2 each, and the base strip
}

// The triangles of a polygon in the plane z = 0, each counter-clockwise with area, summed; a
// triangle of no area or turned over fails.
double clippedArea(const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles) {
    double area = 0;
    for (const auto& t : triangles) {
        const glm::dvec3 n = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        EXPECT_GT(n.z, 0);
        area += n.z / 2;
    }
    return area;
}

// Random star-shaped polygons (simple, with many reflex corners), and an L with corners in the
// middle of its edges: covered once, by triangles that all have area.
TEST(PolygonFaces, EarsCoverSimplePolygonsOnce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> radius(0.2, 1);
    for (int trial = 0; trial < 200; ++trial) {
        const size_t n = 4 + trial % 40;
        std::vector<glm::dvec3> positions;
        for (size_t i = 0; i < n; ++i) {
            const double a = 2 * M_PI * double(i) / double(n), r = radius(rng);
            positions.emplace_back(r * std::cos(a), r * std::sin(a), 0);
        }
        std::vector<uint32_t> polygon(n);
        double shoelace = 0;
        for (uint32_t i = 0; i < n; ++i) {
            polygon[i] = i;
            const glm::dvec3 &p = positions[i], &q = positions[(i + 1) % n];
            shoelace += (p.x * q.y - q.x * p.y) / 2;
        }
        std::vector<std::array<uint32_t, 3>> triangles;
        triangulatePolygon(positions, polygon, triangles, "star: ");
        EXPECT_EQ(triangles.size(), n - 2) << trial;
        EXPECT_NEAR(clippedArea(positions, triangles), shoelace, 1e-12) << trial;
    }
    const std::vector<glm::dvec3> l = {{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {4, 1, 0}, {2, 1, 0},
                                       {1, 1, 0}, {1, 2, 0}, {1, 3, 0}, {0, 3, 0}, {0, 1, 0}};
    std::vector<std::array<uint32_t, 3>> triangles;
    triangulatePolygon(l, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, triangles, "l: ");
    EXPECT_EQ(clippedArea(l, triangles), 6);
}

}  // namespace
}  // namespace tetglow
