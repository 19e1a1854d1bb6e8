// Regions: several closed meshes, nested or touching along shared triangles, in one TetGen run.
// Volumes are exact (boxes) or against the float-snapped meshes' own volumes; every tet's region
// is checked against the exact nesting of its centroid; crossing meshes are refused.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestMeshes.h"
#include "tet/Nesting.h"
#include "tet/Predicates.h"
#include "tet/Tetrahedralizer.h"
#include "tet/VolumeBoundary.h"

namespace tetglow {
namespace {

TriangleMesh validated(TriangleMesh m) {
    validateAndRepair(m);
    return m;
}

// The 2 x 1 x 1 box [0, 2] x [0, 1] x [0, 1] whose faces are triangulated as the unit boxes at
// x = 0 and x = 1 triangulate theirs: the unit box at the origin touches it from inside along 10
// shared triangles.
TriangleMesh doubleBox() {
    const TriangleMesh a = box(), b = box({1, 0, 0}, {2, 1, 1});
    TriangleMesh m = merge(a, b);
    std::erase_if(m.triangles, [&](const std::array<uint32_t, 3>& t) {
        return m.positions[t[0]].x == 1 && m.positions[t[1]].x == 1 && m.positions[t[2]].x == 1;
    });
    return m;
}

// The region whose space holds p, from the meshes alone: the innermost mesh around p.
int32_t regionByNesting(const std::vector<TriangleMesh>& meshes, const std::vector<int32_t>& parent,
                        const glm::dvec3& p) {
    int32_t best = -1, bestDepth = -1;
    for (int32_t i = 0; i < int32_t(meshes.size()); ++i) {
        const PointSide side = classifyPoint(meshes[i], p);
        EXPECT_NE(side, PointSide::OnSurface);
        if (side != PointSide::Inside) continue;
        int depth = 0;
        for (int32_t q = parent[i]; q >= 0; q = parent[q]) ++depth;
        if (depth > bestDepth) {
            best = i;
            bestDepth = depth;
        }
    }
    return best;
}

// What every region mesh must satisfy: each tet in the region its centroid lies in; region
// volumes equal to the enclosed volumes; every triangle two tet faces (one where its front is
// outside every region) with its corners, on the sides its regions say.
void expectConsistent(const TetMesh& m, const std::vector<TriangleMesh>& meshes) {
    ASSERT_EQ(m.regionCount(), meshes.size());
    for (uint32_t t = 0; t < m.tets.size(); ++t)
        ASSERT_EQ(m.region(t), regionByNesting(meshes, m.regionParent, m.centroid(t))) << "tet " << t;
    for (int32_t r = 0; r < int32_t(m.regionCount()); ++r) {
        double enclosed = signedVolume(meshes[r]);
        for (size_t c = 0; c < meshes.size(); ++c)
            if (m.regionParent[c] == r) enclosed -= signedVolume(meshes[c]);
        EXPECT_NEAR(m.regionVolume(r), enclosed, 1e-12 * std::abs(enclosed) + 1e-15) << "region " << r;
        EXPECT_NEAR(m.regionSurfaceVolume(r), enclosed, 1e-12 * std::abs(enclosed) + 1e-15) << "region " << r;
        EXPECT_GT(m.regionTets[r + 1], m.regionTets[r]) << "region " << r << " has no tets";
    }
    for (uint32_t s = 0; s < m.surface.size(); ++s) {
        // The input triangle it comes from, corner for corner in its winding.
        const auto [mesh, index] = m.surfaceSource[s];
        ASSERT_LT(mesh, meshes.size());
        ASSERT_LT(index, meshes[mesh].triangles.size());
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(m.vertices[m.surface[s][k]], meshes[mesh].corner(index, k)) << "triangle " << s;
        auto tri = m.surface[s];
        std::sort(tri.begin(), tri.end());
        for (int side = 0; side < 2; ++side) {
            const uint32_t f = side == 0 ? m.surfaceFace[s] : m.surfaceFaceFront[s];
            if (m.surfaceRegions[s][side] < 0) {
                EXPECT_EQ(f, UINT32_MAX) << "triangle " << s;
                continue;
            }
            ASSERT_NE(f, UINT32_MAX) << "triangle " << s << " side " << side;
            const uint32_t t = f >> 2;
            const int j = int(f & 3);
            EXPECT_EQ(m.adjacency[t][j], ~int32_t(s));
            EXPECT_EQ(m.region(t), m.surfaceRegions[s][side]) << "triangle " << s << " side " << side;
            std::array<uint32_t, 3> face;
            for (int i = 0; i < 3; ++i) face[i] = m.tets[t][kInwardFace[j][i]];
            std::sort(face.begin(), face.end());
            EXPECT_EQ(face, tri) << "triangle " << s;
            // Behind: the tet's fourth vertex is behind the triangle (orient3d > 0), in front: ahead.
            const auto& v = m.surface[s];
            const double o = orient3d(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], m.vertices[m.tets[t][j]]);
            EXPECT_EQ(o > 0, side == 0) << "triangle " << s;
        }
    }
}

TEST(Regions, NestedBoxesHaveExactVolumes) {
    const std::vector<TriangleMesh> meshes{validated(box({0, 0, 0}, {4, 4, 4})), validated(box({1, 1, 1}, {3, 3, 3})),
                                           validated(box({1.5, 1.5, 1.5}, {2.5, 2.5, 2.5}))};
    const TetMesh m = tetrahedralize(meshes, {"outer", "middle", "inner"}, test::noCache());
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, 0, 1}));
    EXPECT_NEAR(m.regionVolume(0), 56.0, 1e-13);
    EXPECT_NEAR(m.regionVolume(1), 7.0, 1e-13);
    EXPECT_NEAR(m.regionVolume(2), 1.0, 1e-13);
    EXPECT_EQ(m.surface.size(), 36u);
    EXPECT_EQ(m.vertices.size(), 24u) << "no Steiner points";
    expectConsistent(m, meshes);
}

TEST(Regions, SteinerPointsStayOffTheInterfaces) {
    // A quality bound adds interior points (heterogeneous media need them); every triangle must
    // still be tet faces as it is, and every tet in its region.
    const std::vector<TriangleMesh> meshes{validated(icosphere(2, 1.0)), validated(icosphere(2, 0.5, {0.2, 0, 0})),
                                           validated(icosphere(1, 0.2, {0.3, 0.1, 0}))};
    TetOptions o = test::noCache();
    o.radiusEdgeRatio = 1.4;
    const TetMesh m = tetrahedralize(meshes, {"outer", "middle", "inner"}, o);
    EXPECT_GT(m.vertices.size(), m.surfaceVertexCount + 100);
    expectConsistent(m, meshes);
}

TEST(Regions, NestedSpheresThreeLevels) {
    const std::vector<TriangleMesh> meshes{validated(icosphere(2, 1.0)), validated(icosphere(2, 0.6, {0.1, 0, 0})),
                                           validated(icosphere(2, 0.25, {0.2, 0.05, 0}))};
    TetStats stats;
    const TetMesh m = tetrahedralize(meshes, {"a", "b", "c"}, test::noCache(), &stats);
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, 0, 1}));
    expectConsistent(m, meshes);
}

TEST(Regions, SiblingsInsideOneContainer) {
    const std::vector<TriangleMesh> meshes{validated(icosphere(2, 1.0)), validated(icosphere(1, 0.3, {0.5, 0, 0})),
                                           validated(icosphere(1, 0.3, {-0.5, 0, 0}))};
    const TetMesh m = tetrahedralize(meshes, {"body", "left", "right"}, test::noCache());
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, 0, 0}));
    expectConsistent(m, meshes);
}

TEST(Regions, InputOrderDoesNotMatterToTheNesting) {
    const std::vector<TriangleMesh> meshes{validated(icosphere(1, 0.3)), validated(icosphere(2, 1.0))};
    const TetMesh m = tetrahedralize(meshes, {"inner", "outer"}, test::noCache());
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{1, -1}));
    expectConsistent(m, meshes);
}

TEST(Regions, TouchingBoxesShareTheirFace) {
    const std::vector<TriangleMesh> meshes{validated(box()), validated(box({1, 0, 0}, {2, 1, 1}))};
    const TetMesh m = tetrahedralize(meshes, {"left", "right"}, test::noCache());
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, -1}));
    EXPECT_EQ(m.surface.size(), 22u) << "the two shared triangles once";
    EXPECT_EQ(m.vertices.size(), 12u);
    size_t interfaces = 0;
    for (const auto& sides : m.surfaceRegions) interfaces += sides[1] >= 0;
    EXPECT_EQ(interfaces, 2u);
    for (uint32_t s = 0; s < m.surface.size(); ++s) {
        if (m.surfaceRegions[s][1] >= 0) {
            EXPECT_EQ(m.surfaceRegions[s], (std::array<int32_t, 2>{0, 1}));
        }
    }
    EXPECT_NEAR(m.regionVolume(0), 1.0, 1e-15);
    EXPECT_NEAR(m.regionVolume(1), 1.0, 1e-15);
    expectConsistent(m, meshes);
}

// Meshes that meet only at a vertex or along an edge are two regions that share no triangle:
// accepted (the documentation once said refused), each region exactly its box.
TEST(Regions, BoxesMeetingAtAnEdgeOrAVertexAreTwoRegions) {
    for (const glm::dvec3 corner : {glm::dvec3(1, 1, 0), glm::dvec3(1, 1, 1)}) {
        const std::vector<TriangleMesh> meshes{validated(box()), validated(box(corner, corner + glm::dvec3(1)))};
        const TetMesh m = tetrahedralize(meshes, {"a", "b"}, test::noCache());
        EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, -1}));
        EXPECT_EQ(m.surface.size(), 24u) << "no triangle shared";
        EXPECT_NEAR(m.regionVolume(0), 1.0, 1e-15);
        EXPECT_NEAR(m.regionVolume(1), 1.0, 1e-15);
        expectConsistent(m, meshes);
    }
}

TEST(Regions, InnerMeshTouchingItsContainerFromInside) {
    const std::vector<TriangleMesh> meshes{validated(doubleBox()), validated(box())};
    const TetMesh m = tetrahedralize(meshes, {"outer", "inner"}, test::noCache());
    EXPECT_EQ(m.regionParent, (std::vector<int32_t>{-1, 0}));
    EXPECT_EQ(m.surface.size(), 22u) << "10 triangles shared, the inner box's face at x = 1 inside";
    size_t innerOutside = 0;
    for (const auto& sides : m.surfaceRegions) innerOutside += sides == std::array<int32_t, 2>{1, -1};
    EXPECT_EQ(innerOutside, 10u);
    EXPECT_NEAR(m.regionVolume(0), 1.0, 1e-15);
    EXPECT_NEAR(m.regionVolume(1), 1.0, 1e-15);
    expectConsistent(m, meshes);
}

TEST(Regions, OneMeshIsOneRegion) {
    const TetMesh m = tetrahedralize(box(), test::noCache());
    EXPECT_EQ(m.regionCount(), 1u);
    EXPECT_EQ(m.regionTets, (std::vector<uint32_t>{0, uint32_t(m.tets.size())}));
    for (const auto& sides : m.surfaceRegions) EXPECT_EQ(sides, (std::array<int32_t, 2>{0, -1}));
}

TEST(Regions, CacheKeysOnTheWholeSet) {
    TetOptions o;
    o.cacheDir = test::tempDir() + "/cache";
    const std::vector<TriangleMesh> pair{box({0, 0, 0}, {4, 4, 4}), box({1, 1, 1}, {3, 3, 3})};
    TetStats first, second, other;
    const TetMesh a = tetrahedralize(pair, {"a", "b"}, o, &first);
    const TetMesh b = tetrahedralize(pair, {"a", "b"}, o, &second);
    EXPECT_FALSE(first.fromCache);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(a.tets, b.tets);
    EXPECT_EQ(a.regionTets, b.regionTets);
    EXPECT_EQ(a.surfaceRegions, b.surfaceRegions);
    EXPECT_EQ(a.surfaceFaceFront, b.surfaceFaceFront);
    // The outer box alone is another input; so is the same pair with a different inner box.
    tetrahedralize({pair[0]}, {"a"}, o, &other);
    EXPECT_FALSE(other.fromCache);
    tetrahedralize({pair[0], box({1, 1, 1}, {2, 3, 3})}, {"a", "b"}, o, &other);
    EXPECT_FALSE(other.fromCache);
}

// ---- Refused input -----------------------------------------------------------------------------

std::string errorOf(const std::vector<TriangleMesh>& meshes, const std::vector<std::string>& names) {
    try {
        tetrahedralize(meshes, names, test::noCache());
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(Regions, OverlappingMeshesAreRefused) {
    const std::string e = errorOf({box(), box(glm::dvec3(0.5), glm::dvec3(1.5))}, {"A.obj", "B.obj"});
    EXPECT_NE(e.find("A.obj and B.obj cross: triangle "), std::string::npos) << e;
    EXPECT_NE(e.find(" of A.obj meets triangle "), std::string::npos) << e;
    EXPECT_NE(e.find(" of B.obj"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST(Regions, MediumCrossingItsContainerIsRefused) {
    const std::string e = errorOf({icosphere(2, 1.0), icosphere(1, 0.3, {0.9, 0, 0})}, {"body", "eye"});
    EXPECT_NE(e.find("body and eye cross"), std::string::npos) << e;
}

TEST(Regions, TouchingAlongPartsOfTrianglesIsRefused) {
    // The small box lies on the big one's floor, inside it, but its bottom face is not made of the
    // big box's triangles: the two surfaces overlap on a patch of a plane.
    const std::string e = errorOf({box({0, 0, 0}, {4, 4, 4}), box({1, 0, 1}, {2, 1, 2})}, {"tank", "stone"});
    EXPECT_NE(e.find("tank and stone cross"), std::string::npos) << e;
}

TEST(Regions, OpenInnerMeshIsRepairedInItsRegion) {
    const TriangleMesh body = icosphere(2, 1.0), organ = icosphere(1, 0.3);
    TriangleMesh open = organ;
    open.triangles.pop_back();  // a planar hole: the tet face across it is the missing triangle
    const TetMesh mesh = tetrahedralize({body, open}, {"body", "organ"}, test::noCache());
    TriangleMesh body32 = body, organ32 = organ;  // float-snapped, as the tets see them
    const double inner = validateAndRepair(organ32).volume, outer = validateAndRepair(body32).volume;
    EXPECT_NEAR(mesh.regionVolume(1), inner, 1e-12);
    EXPECT_NEAR(mesh.regionVolume(0), outer - inner, 1e-12);
    TetOptions strict = test::noCache();
    strict.strict = true;
    try {
        tetrahedralize({body, open}, {"body", "organ"}, strict);
        ADD_FAILURE() << "strict accepted an open mesh";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("organ: mesh is not closed", 0), 0u) << e.what();
    }
}

TEST(Regions, InnerSheetIsRefusedByName) {
    const std::string e = errorOf({icosphere(2, 1.0), disk(glm::dvec3(0), {0, 0, 1}, 0.3, 16)}, {"body", "organ"});
    EXPECT_EQ(e.rfind("organ: mesh encloses no volume", 0), 0u) << e;
}

TEST(Regions, TheSameMeshTwiceIsRefused) {
    const std::string e = errorOf({box(), box()}, {"one", "two"});
    EXPECT_NE(e.find("one"), std::string::npos) << e;
    EXPECT_NE(e.find("two"), std::string::npos) << e;
    EXPECT_NE(e, "(accepted)");
}

TEST(Regions, TheSameSphereTwiceIsRefusedAtEverySubdivision) {
    for (int subdivisions = 1; subdivisions <= 4; ++subdivisions)
        EXPECT_EQ(errorOf({icosphere(subdivisions, 1.0), icosphere(subdivisions, 1.0)}, {"one", "two"}),
                  "one and two have the same surface")
            << subdivisions;
}

// A box 1e-12 inside another: nested exactly, but closer than TetGen tells points apart.
TEST(Regions, SurfacesCloserThanTetGenResolvesAreRefusedNamingBoth) {
    const std::string e = errorOf({box(), box(glm::dvec3(1e-12), glm::dvec3(1 - 1e-12))}, {"outer.obj", "inner.obj"});
    EXPECT_EQ(e.rfind("outer.obj and inner.obj are ", 0), 0u) << e;
    EXPECT_NE(e.find("closer than TetGen tells points apart"), std::string::npos) << e;
    EXPECT_NE(e.find("vertex 0 of outer.obj and vertex 0 of inner.obj"), std::string::npos) << e;
    // 1e-6 apart is resolved: two regions.
    EXPECT_EQ(errorOf({box(), box(glm::dvec3(1e-6), glm::dvec3(1 - 1e-6))}, {"outer.obj", "inner.obj"}), "(accepted)");
}

// ---- The command --------------------------------------------------------------------------------

std::string writeMesh(const std::string& name, const TriangleMesh& m) {
    const std::string path = test::tempDir() + "/" + name;
    writeObj(m, path);
    return path;
}

TEST(RegionsCommand, ReportsEachRegion) {
    const std::string outer = writeMesh("outer.obj", box({0, 0, 0}, {4, 4, 4}));
    const std::string inner = writeMesh("inner.obj", box({1, 1, 1}, {3, 3, 3}));
    const auto r = test::runTetglow("tetrahedralize --no-cache --json " + outer + " " + inner);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["regions"].size(), 2u);
    EXPECT_EQ(j["regions"][0]["inside"], nullptr);
    EXPECT_EQ(j["regions"][1]["inside"], outer);
    EXPECT_NEAR(j["regions"][0]["enclosed_volume"].get<double>(), 56.0, 1e-13);
    EXPECT_NEAR(j["regions"][0]["tet_volume"].get<double>(), 56.0, 1e-13);
    EXPECT_NEAR(j["regions"][1]["enclosed_volume"].get<double>(), 8.0, 1e-13);
    EXPECT_EQ(j["regions"][0]["boundary_faces"], 24);
    EXPECT_EQ(j["regions"][1]["boundary_faces"], 12);
    EXPECT_NEAR(j["mesh_volume"].get<double>(), 64.0, 1e-13);
    const auto text = test::runTetglow("tetrahedralize --no-cache " + outer + " " + inner);
    EXPECT_NE(text.out.find(inner + " inside " + outer), std::string::npos) << text.out;
}

TEST(RegionsCommand, GeneratedSpheresNest) {
    const std::string dir = test::tempDir();
    ASSERT_EQ(test::runTetglow("generate sphere --radius 1 --subdivisions 2 -o " + dir + "/big.obj").exitCode, 0);
    ASSERT_EQ(
        test::runTetglow("generate sphere --radius 0.3 --x 0.4 --subdivisions 1 -o " + dir + "/small.obj").exitCode, 0);
    const auto r = test::runTetglow("tetrahedralize --no-cache --json " + dir + "/small.obj " + dir + "/big.obj");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["regions"][0]["inside"], dir + "/big.obj");
    TriangleMesh big = icosphere(2, 1.0), small = icosphere(1, 0.3, {0.4, 0, 0});
    const double vb = validateAndRepair(big).volume, vs = validateAndRepair(small).volume;
    EXPECT_NEAR(j["regions"][0]["tet_volume"].get<double>(), vs, 1e-12 * vs);
    EXPECT_NEAR(j["regions"][1]["tet_volume"].get<double>(), vb - vs, 1e-12 * vb);
    EXPECT_EQ(test::runTetglow("generate sphere --radius 0 -o " + dir + "/bad.obj").exitCode, 1);
}

TEST(RegionsCommand, CrossingMeshesExitWithOneLine) {
    const std::string a = writeMesh("a.obj", box()), b = writeMesh("b.obj", box(glm::dvec3(0.5), glm::dvec3(1.5)));
    const std::string out = test::tempDir() + "/out.vtk";
    const auto r = test::runTetglow("tetrahedralize --no-cache " + a + " " + b + " -o " + out);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find(a + " and " + b + " cross: triangle "), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// ---- Exact point classification ----------------------------------------------------------------

TEST(Nesting, PointsOnVerticesEdgesAndFacesAreOnTheSurface) {
    const TriangleMesh b = validated(box());
    EXPECT_EQ(classifyPoint(b, {0, 0, 0}), PointSide::OnSurface);
    EXPECT_EQ(classifyPoint(b, {0.5, 0, 0}), PointSide::OnSurface);
    EXPECT_EQ(classifyPoint(b, {0.5, 0.5, 0}), PointSide::OnSurface);
    EXPECT_EQ(classifyPoint(b, {0.25, 0.75, 1}), PointSide::OnSurface);
    EXPECT_EQ(classifyPoint(b, {0.5, 0.5, 0.5}), PointSide::Inside);
    EXPECT_EQ(classifyPoint(b, {1e-300, 0.5, 0.5}), PointSide::Inside);
    EXPECT_EQ(classifyPoint(b, {-1e-300, 0.5, 0.5}), PointSide::Outside);
    EXPECT_EQ(classifyPoint(b, {0.5, 0.5, std::nextafter(1.0, 2.0)}), PointSide::Outside);
    EXPECT_EQ(classifyPoint(b, {0.5, 0.5, std::nextafter(1.0, 0.0)}), PointSide::Inside);
}

}  // namespace
}  // namespace tetglow
