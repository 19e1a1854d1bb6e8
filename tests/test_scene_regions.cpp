// Scenes with several media: media that cross are refused (naming both and a triangle pair), so
// is an open inner mesh (naming it) and a cavity in no medium; nested and touching media render
// as regions of one tet mesh, found from the meshes.
#include <filesystem>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "scene/MediaNesting.h"
#include "scene/VolumePartition.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

std::string sceneWithMedia(const std::string& a, const std::string& b) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "resolution": [8, 8]},
  "integrator": {"spp": 1},
  "lights": [{"type": "environment", "radiance": 1}],
  "media": [{"shape": )" +
           a + R"(, "sigma_s": 1}, {"shape": )" + b + R"(, "sigma_s": 2}]})";
}

void expectRefused(const std::string& name, const std::string& scene, const std::string& expected) {
    const std::string path = writeTemp(name + ".json", scene), out = tempDir() + "/" + name + ".exr";
    const auto r = runTetglow("render " + path + " -o " + out);
    EXPECT_EQ(r.exitCode, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << name;
}

const std::string kBig = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "subdivisions": 2})";

TEST(SceneRegions, OverlappingMediaAreRefusedNamingBoth) {
    expectRefused(
        "overlap",
        sceneWithMedia(kBig, R"({"type": "sphere", "center": [1.2, 0, 0], "radius": 0.5, "subdivisions": 2})"),
        "/media/0 and /media/1 cross: triangle ");
}

// The same sphere twice, at every subdivision: one space cannot hold two media.
TEST(SceneRegions, CoincidentMediaAreRefused) {
    for (int subdivisions = 1; subdivisions <= 4; ++subdivisions) {
        const std::string sphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "subdivisions": )" +
                                   std::to_string(subdivisions) + "}";
        expectRefused("same" + std::to_string(subdivisions), sceneWithMedia(sphere, sphere),
                      "/media/0 and /media/1 have the same surface");
    }
}

TEST(SceneRegions, AMediumCrossingItsContainerIsRefused) {
    expectRefused(
        "poke", sceneWithMedia(kBig, R"({"type": "sphere", "center": [0.8, 0, 0], "radius": 0.3, "subdivisions": 1})"),
        "/media/0 and /media/1 cross");
}

void expectRenders(const std::string& name, const std::string& scene, const std::string& expected) {
    const std::string path = writeTemp(name + ".json", scene), out = tempDir() + "/" + name + ".exr";
    const auto r = runTetglow("render " + path + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << name << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(out)) << name;
}

TEST(SceneRegions, NestedMediaRenderAsOneTetMesh) {
    expectRenders(
        "nested",
        sceneWithMedia(kBig, R"({"type": "sphere", "center": [0.1, 0, 0], "radius": 0.4, "subdivisions": 1})"),
        "medium /media/0 + /media/1: ");
}

TEST(SceneRegions, TouchingMediaRenderAsOneTetMesh) {
    expectRenders("touching",
                  sceneWithMedia(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]})",
                                 R"({"type": "box", "min": [1, 0, 0], "max": [2, 1, 1]})"),
                  "medium /media/0 + /media/1: ");
}

TEST(SceneRegions, ACavityRendersInsideItsMedium) {
    std::string scene = sceneWithMedia(kBig, R"({"type": "sphere", "center": [3, 0, 0], "radius": 0.5})");
    scene.insert(
        scene.rfind('}'),
        R"(, "cavities": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 0.5}, "boundary": {"type": "dielectric", "ior": 1}}])");
    expectRenders("cavity", scene, "medium /media/0 + /cavities/0: ");
}

TEST(SceneRegions, ACavityInNoMediumIsRefused) {
    std::string scene = sceneWithMedia(kBig, R"({"type": "sphere", "center": [3, 0, 0], "radius": 0.5})");
    scene.insert(scene.rfind('}'),
                 R"(, "cavities": [{"shape": {"type": "sphere", "center": [0, 3, 0], "radius": 0.5}}])");
    expectRefused("stray-cavity", scene, "/cavities/0: a cavity must lie inside a medium");
}

TEST(SceneRegions, AnOpenInnerMeshIsRepairedOrWhenStrictRefusedNamingIt) {
    // A box without its top face inside the sphere.
    const std::string obj = writeTemp("open-box.obj",
                                      "v -0.2 -0.2 -0.2\nv 0.2 -0.2 -0.2\nv 0.2 0.2 -0.2\nv -0.2 0.2 -0.2\n"
                                      "v -0.2 -0.2 0.2\nv 0.2 -0.2 0.2\nv 0.2 0.2 0.2\nv -0.2 0.2 0.2\n"
                                      "f 1 3 2\nf 1 4 3\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
                                      "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
    const std::string scene = sceneWithMedia(kBig, R"({"type": "mesh", "file": ")" + obj + R"("})");
    const std::string path = writeTemp("open-inner.json", scene);
    const auto r = runTetglow("render " + path + " -o " + tempDir() + "/open-inner.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::string strict = scene;
    strict.replace(strict.rfind("\"sigma_s\": 2"), 12, R"("sigma_s": 2, "tetgen": {"strict": true})");
    expectRefused("open-inner-strict", strict, "/media/1 (");
}

// A reader that found the nesting for its own checks (pbrt's MediumInterface) hands it on, and
// the scene groups its media by that nesting instead of finding it again.
TEST(SceneRegions, MediaAreGroupedByTheNestingAReaderFound) {
    std::vector<MediumDesc> media(2);
    media[0].boundary = icosphere(2, 1.0);
    media[1].boundary = icosphere(1, 0.4);
    media[0].name = "/media/0";
    media[1].name = "/media/1";
    const MediaNesting nesting = nestMedia(media);
    EXPECT_EQ(nesting.parent, (std::vector<int32_t>{-1, 0}));
    EXPECT_EQ(findVolumes(media), (std::vector<std::vector<int>>{{0, 1}}));
    const MediaNesting apart{{-1, -1}, {}};
    EXPECT_EQ(findVolumes(media, &apart), (std::vector<std::vector<int>>{{0}, {1}}));
}

TEST(SceneRegions, MediaApartStillRender) {
    const std::string path =
        writeTemp("apart.json", sceneWithMedia(kBig, R"({"type": "sphere", "center": [3, 0, 0], "radius": 0.5})"));
    const auto r = runTetglow("render " + path + " -o " + tempDir() + "/apart.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace tetglow::test
