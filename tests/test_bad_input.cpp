// Broken meshes, generated here: each gets a one-line error naming the file and the problem,
// exit code 1, and no output file (with --strict for the meshes the tets otherwise repair, see
// test_interior_repair.cpp). Valid oddities (two shells, inward winding) are accepted.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

std::string objText(const TriangleMesh& m) {
    std::string s;
    for (const auto& p : m.positions)
        s += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& t : m.triangles)
        s += "f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + "\n";
    return s;
}

// Runs `tetglow tetrahedralize` on the text and checks the failure.
void expectRejected(const std::string& contents, const std::string& expected, const std::string& fileName = "mesh.obj",
                    const std::string& options = "") {
    const std::string path = test::writeTemp(fileName, contents);
    const std::string out = test::tempDir() + "/out.tet";
    test::expectOneLineError(test::runTetglow("tetrahedralize " + path + " -o " + out + options), 1, expected);
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(BadInput, MeshWithHole) {
    TriangleMesh m = box();
    m.triangles.pop_back();
    expectRejected(objText(m), "not closed: edge", "mesh.obj", " --strict");
}

TEST(BadInput, SelfIntersectingMesh) {
    expectRejected(objText(merge(box(), box(glm::dvec3(0.5), glm::dvec3(1.5)))), "intersects itself: triangle",
                   "mesh.obj", " --strict");
}

TEST(BadInput, NonManifoldEdge) {
    // Two cubes sharing only an edge: that edge has four triangles.
    expectRejected(objText(merge(box(), box({1, 1, 0}, {2, 2, 1}))), "non-manifold edge", "mesh.obj", " --strict");
}

TEST(BadInput, DuplicateFaces) {
    TriangleMesh m = box();
    m.triangles.push_back({m.triangles[3][1], m.triangles[3][2], m.triangles[3][0]});
    expectRejected(objText(m), "duplicate faces: triangle 3 and triangle 12", "mesh.obj", " --strict");
}

TEST(BadInput, DegenerateTriangles) {
    TriangleMesh m = box();
    m.triangles.push_back({0, 0, 1});
    expectRejected(objText(m), "degenerate triangle 12: a vertex is repeated", "mesh.obj", " --strict");
    TriangleMesh c = box();
    c.positions.push_back({0.5, 0, 0});  // on the edge from vertex 0 to vertex 1
    c.triangles.push_back({0, 1, 8});
    expectRejected(objText(c), "degenerate triangle 12: zero area", "mesh.obj", " --strict");
}

TEST(BadInput, NanCoordinates) {
    std::string text = objText(box());
    text.replace(text.find("v ") + 2, 8, "nan");
    expectRejected(text, "vertex 0 has a non-finite coordinate");
}

TEST(BadInput, EmptyFile) { expectRejected("", "no triangles"); }

TEST(BadInput, MissingFile) {
    const auto r = test::runTetglow("tetrahedralize /nonexistent/fish.obj");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("/nonexistent/fish.obj: no such file"), std::string::npos) << r.err;
}

TEST(BadInput, NotAMesh) {
    expectRejected("Dear diary,\ntoday I saw a fish.\n", "not an OBJ line");
    expectRejected(std::string("\x89PNG\r\n\x1a\n\0\0\0", 12), "binary file", "image.obj");
    expectRejected("OFF\n3 1 0\n0 0 0\n1 0 0\n", "OFF file ends early", "mesh.off");
}

TEST(BadInput, BadFaceIndex) {
    expectRejected("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n", "mesh.obj:4: face index 7 out of range");
}

TEST(BadInput, BadArgumentsAreUsageErrors) {
    const std::string path = test::writeTemp("box.obj", objText(box()));
    for (const char* arg : {"--max-volume nan", "--max-volume -1", "--quality inf", "--frobnicate"}) {
        const auto r = test::runTetglow("tetrahedralize " + path + " " + arg);
        EXPECT_EQ(r.exitCode, 2) << arg << ": " << r.err;
    }
}

TEST(ValidInput, TwoSeparateShellsBothBecomeMedium) {
    const TriangleMesh m = merge(box(), icosphere(2, 0.5, {3, 0.5, 0.5}));
    TetStats stats;
    ValidationReport report;
    TetOptions o;
    o.useCache = false;
    const TetMesh tets = tetrahedralize(m, o, &stats, &report);
    EXPECT_EQ(report.components, 2u);
    TriangleMesh sphere = icosphere(2, 0.5, {3, 0.5, 0.5});
    const double expected = 1.0 + validateAndRepair(sphere).volume;  // float-snapped, as the tets see it
    EXPECT_NEAR(tets.volume(), expected, 1e-9 * expected);
}

TEST(ValidInput, InwardWindingIsFixed) {
    TriangleMesh m = box();
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    m.triangles[4] = {m.triangles[4][0], m.triangles[4][2], m.triangles[4][1]};  // and one inconsistent
    const ValidationReport report = validateAndRepair(m);
    EXPECT_NEAR(report.volume, 1.0, 1e-12);
    EXPECT_GT(report.flippedTriangles, 0u);
    EXPECT_EQ(validateAndRepair(m).flippedTriangles, 0u);  // now consistent and outward
}

TriangleMesh inward(TriangleMesh m) {
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    return m;
}

TEST(ValidInput, CavityIsNotMedium) {
    // A box with a spherical hole inside, wound inward as a cavity's surface is: the tets fill
    // only the space between them. The whole mesh wound the other way round is the same solid.
    const TriangleMesh cavity = icosphere(2, 0.3, glm::dvec3(0.5));
    TriangleMesh snapped = cavity;
    const double expected = 1.0 - validateAndRepair(snapped).volume;  // float-snapped, as the tets see it
    TetOptions o;
    o.useCache = false;
    for (const TriangleMesh& m : {merge(box(), inward(cavity)), inward(merge(box(), inward(cavity)))}) {
        TriangleMesh checked = m;
        EXPECT_EQ(validateAndRepair(checked).droppedShells, 0u);
        EXPECT_NEAR(tetrahedralize(m, o).volume(), expected, 1e-9);
    }
}

TEST(ValidInput, NestedShellsWoundAlikeStaySolid) {
    // Inside a box, a sphere wound as the box is: winding number 2 within it, inside by the rule
    // (above 1/2), so the sphere bounds nothing and the whole box is medium. It was a cavity,
    // losing the sphere's volume.
    TriangleMesh m = merge(box(), icosphere(2, 0.3, glm::dvec3(0.5)));
    const ValidationReport report = validateAndRepair(m);
    EXPECT_EQ(report.droppedShells, 1u);
    EXPECT_EQ(report.flippedTriangles, 0u);
    EXPECT_NEAR(report.volume, 1.0, 1e-12);
    EXPECT_EQ(m.triangles.size(), box().triangles.size());
    EXPECT_EQ(m.positions.size(), 8u);
    TetOptions o;
    o.useCache = false;
    EXPECT_NEAR(tetrahedralize(merge(box(), icosphere(2, 0.3, glm::dvec3(0.5))), o).volume(), 1.0, 1e-12);
}

TEST(ValidInput, ManyShellsNestAsTheirWindingSays) {
    // 1000 boxes on a grid, each holding a smaller box: wound inward in the even ones (cavities),
    // outward in the odd ones (inside on both sides, dropped); the whole wound inward in every
    // third (the same solid). Volume and notes follow from each pair's own winding.
    TriangleMesh m;
    double expected = 0;
    size_t dropped = 0;
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 lo(2.0 * (i % 10), 2.0 * (i / 10 % 10), 2.0 * (i / 100));
        TriangleMesh inner = box(lo + 0.25, lo + 0.75);
        TriangleMesh pair = merge(box(lo, lo + 1.0), i % 2 ? inner : inward(inner));
        m = merge(m, i % 3 ? pair : inward(pair));
        expected += i % 2 ? 1.0 : 1.0 - 0.125;
        dropped += i % 2;
    }
    const ValidationReport report = validateAndRepair(m);
    EXPECT_EQ(report.components, 2000u);
    EXPECT_EQ(report.droppedShells, dropped);
    EXPECT_NEAR(report.volume, expected, 1e-9);
}

// TetGen itself, without tetglow's validation: its three failure modes become errors.
TEST(TetGenFailures, OpenMeshGivesAnErrorNotAnEmptyMesh) {
    TriangleMesh m = box();
    m.triangles.pop_back();
    EXPECT_THROW(tetrahedralizeUnchecked(m, "pYnQz"), InputError);
}

TEST(TetGenFailures, SelfIntersectionGivesAnErrorNotACrash) {
    const TriangleMesh m = merge(box(), box(glm::dvec3(0.5), glm::dvec3(1.5)));
    try {
        tetrahedralizeUnchecked(m, "pYnQz");
        ADD_FAILURE() << "TetGen accepted a self-intersecting mesh";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("TetGen"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace tetglow

namespace tetglow {
namespace {

TEST(ValidInput, PositionsAreSnappedToFloat) {
    // Embree stores floats: the tets must see the very same vertices.
    TriangleMesh m = icosphere(1, 0.1, {0.1, 0.2, 0.3});
    validateAndRepair(m);
    for (const auto& p : m.positions)
        for (int k = 0; k < 3; ++k) ASSERT_EQ(p[k], roundToFloat(p[k])) << p.x << ' ' << p.y << ' ' << p.z;
}

}  // namespace
}  // namespace tetglow
