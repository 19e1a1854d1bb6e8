// `tetglow init` on the meshes people have: framed on the vertices the triangles use, at any
// size, turned to the mesh's up axis (said, and --up to change it), and never a scene that
// `render` then refuses.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "JsonFiles.h"
#include "MeshWriters.h"
#include "TestMeshes.h"
#include "scene/SceneLoader.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// boxQuads (0..2, 0..3, 0..4) scaled by `s`, as OBJ text, with `extra` lines after it.
std::string boxObj(double s, const std::string& extra = "") {
    PolygonMesh m = boxQuads();
    for (auto& p : m.positions) p *= s;
    return objText(m) + extra;
}

// A stray vertex no face uses took the frame: the camera looked at a point between it and the box.
TEST(InitCommand, FramesTheUsedVerticesNotAStrayOne) {
    const std::string dir = tempDir(), mesh = writeTemp("stray.obj", boxObj(1, "v 1000 1000 1000\n"));
    const auto r = runTetglow("init " + mesh + " -o " + dir + "/s.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json scene = readJson(dir + "/s.json");
    EXPECT_LT(glm::length(vec(scene["camera"]["look_at"]) - glm::dvec3(1, 1.5, 2)), 1e-3) << scene["camera"].dump();
    EXPECT_LT(glm::length(vec(scene["camera"]["position"]) - glm::dvec3(1, 1.5, 2)), 20) << scene["camera"].dump();
}

// A mesh 1e-12 across was framed as if 1e-9 across: a speck in the middle of the image. Meshes
// far smaller (or larger) than tetglow's ray offsets resolve are moved to the origin and scaled
// to a size near 1 by the shape's transform, and framed there.
TEST(InitCommand, FramesATinyMeshAtItsOwnSize) {
    const std::string dir = tempDir(), mesh = writeTemp("tiny.obj", boxObj(1e-12));
    const auto r = runTetglow("init " + mesh + " -o " + dir + "/s.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("size: 5.39e-12 across, so the scene scales the mesh by 1e+12 and moves it to the origin"),
              std::string::npos)
        << r.out;
    const nlohmann::json scene = readJson(dir + "/s.json");
    EXPECT_EQ(scene["media"][0]["shape"]["transform"][0]["scale"].get<double>(), 1e12);
    const SceneDesc desc = loadScene(dir + "/s.json");
    const Bounds3 box = bounds(desc.media[0].boundary);
    const double radius = box.diagonal() / 2;
    EXPECT_NEAR(radius, glm::length(glm::dvec3(2, 3, 4)) / 2, 1e-3);
    EXPECT_LT(glm::length(desc.camera.lookAt - (box.lo + box.hi) * 0.5), 1e-3 * radius);
    const double distance = glm::length(desc.camera.position - desc.camera.lookAt);
    EXPECT_GT(distance, 2 * radius);
    EXPECT_LT(distance, 5 * radius);
}

// A mesh of radius 3e11 got a camera and a floor beyond the scene's coordinate range, which
// render refused; so does one of 1e12.
TEST(InitCommand, AHugeMeshGetsASceneRenderReads) {
    const std::string dir = tempDir();
    for (const double scale : {1.1e11, 1e12}) {
        SCOPED_TRACE(scale);
        const std::string name = "huge" + std::to_string(int(std::log10(scale)));
        const std::string mesh = writeTemp(name + ".obj", boxObj(scale));
        const auto r = runTetglow("init " + mesh + " -o " + dir + "/" + name + ".json");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NO_THROW(loadScene(dir + "/" + name + ".json"));
    }
}

// A NaN vertex: init wrote a scene, and render then refused the mesh.
TEST(InitCommand, RefusesAMeshRenderRefuses) {
    const std::string dir = tempDir();
    const std::string mesh =
        writeTemp("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    expectOneLineError(runTetglow("init " + mesh + " -o " + dir + "/s.json"), 1,
                       "nan.obj: vertex 3 has a non-finite coordinate");
    EXPECT_FALSE(std::filesystem::exists(dir + "/s.json"));
}

// A Z-up mesh stood on end: --up z turns the camera and the floor, and without it init says what
// it assumed.
TEST(InitCommand, UpAxisTurnsTheCameraAndTheFloor) {
    const std::string dir = tempDir(), mesh = writeTemp("box.ply", plyAscii(boxQuads()));
    const auto assumed = runTetglow("init " + mesh + " -o " + dir + "/y.json");
    ASSERT_EQ(assumed.exitCode, 0) << assumed.err;
    EXPECT_NE(assumed.out.find("up: y assumed (" + mesh + " states no up axis)"), std::string::npos) << assumed.out;
    EXPECT_NE(assumed.out.find("--up z"), std::string::npos) << assumed.out;

    const auto z = runTetglow("init " + mesh + " --up z -o " + dir + "/z.json");
    ASSERT_EQ(z.exitCode, 0) << z.err;
    const nlohmann::json scene = readJson(dir + "/z.json");
    EXPECT_EQ(vec(scene["camera"]["up"]), glm::dvec3(0, 0, 1));
    const nlohmann::json& floor = scene["surfaces"][0]["shape"];
    EXPECT_EQ(vec(floor["edge0"]).z, 0);
    EXPECT_EQ(vec(floor["edge1"]).z, 0);
    EXPECT_LT(vec(floor["corner"]).z, 0);  // under the box's lowest z
    const glm::dvec3 normal = glm::cross(vec(floor["edge0"]), vec(floor["edge1"]));
    EXPECT_GT(normal.z, 0) << "the floor faces up";
    EXPECT_GT(vec(scene["camera"]["position"]).z, 2) << "seen from above";
    EXPECT_NO_THROW(loadScene(dir + "/z.json"));

    const auto down = runTetglow("init " + mesh + " --up=-z -o " + dir + "/down.json");
    ASSERT_EQ(down.exitCode, 0) << down.err;
    EXPECT_EQ(vec(readJson(dir + "/down.json")["camera"]["up"]), glm::dvec3(0, 0, -1));
    expectOneLineError(runTetglow("init " + mesh + " --up -z -o " + dir + "/d.json"), 2,
                       "--up: '-z' reads as an option: write --up=-z");
    expectOneLineError(runTetglow("init " + mesh + " --up w -o " + dir + "/w.json"), 2, "--up");
}

// glTF states Y-up; init says it took it from the file.
TEST(InitCommand, GltfIsYUpByItsOwnConvention) {
    const std::string dir = tempDir();
    const std::string mesh = writeTemp("box.glb", glb(gltf({boxQuads().fanned()}, {{"Box", 0, {}, ""}}, {0}, "")));
    const auto r = runTetglow("init " + mesh + " -o " + dir + "/s.json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("up: y (glTF is Y-up)"), std::string::npos) << r.out;
    EXPECT_EQ(vec(readJson(dir + "/s.json")["camera"]["up"]), glm::dvec3(0, 1, 0));
}

}  // namespace
}  // namespace tetglow::test
