// Scenes with several media: media that cross are refused (naming both and a triangle pair);
// nested or touching media, which the integrators do not render yet, are refused too, rather
// than rendered wrong (a path leaving the inner one used to count as outside every medium).
#include <filesystem>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

std::string sceneWithMedia(const std::string& a, const std::string& b) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "resolution": [8, 8]},
  "integrator": {"spp": 1},
  "lights": [{"type": "environment", "radiance": 1}],
  "media": [{"shape": )" + a + R"(, "sigma_s": 1}, {"shape": )" + b + R"(, "sigma_s": 2}]})";
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
    expectRefused("overlap", sceneWithMedia(kBig, R"({"type": "sphere", "center": [1.2, 0, 0], "radius": 0.5, "subdivisions": 2})"),
                  "/media/0 and /media/1 cross: triangle ");
}

TEST(SceneRegions, AMediumCrossingItsContainerIsRefused) {
    expectRefused("poke", sceneWithMedia(kBig, R"({"type": "sphere", "center": [0.8, 0, 0], "radius": 0.3, "subdivisions": 1})"),
                  "/media/0 and /media/1 cross");
}

TEST(SceneRegions, NestedMediaAreRefusedUntilTheyRender) {
    expectRefused("nested", sceneWithMedia(kBig, R"({"type": "sphere", "center": [0.1, 0, 0], "radius": 0.4, "subdivisions": 1})"),
                  "/media/1 lies inside /media/0: nested media are not rendered yet");
}

TEST(SceneRegions, TouchingMediaAreRefusedUntilTheyRender) {
    expectRefused("touching",
                  sceneWithMedia(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]})",
                                 R"({"type": "box", "min": [1, 0, 0], "max": [2, 1, 1]})"),
                  "/media/0 and /media/1 share triangles: touching media are not rendered yet");
}

TEST(SceneRegions, MediaApartStillRender) {
    const std::string path = writeTemp("apart.json", sceneWithMedia(kBig, R"({"type": "sphere", "center": [3, 0, 0], "radius": 0.5})"));
    const auto r = runTetglow("render " + path + " -o " + tempDir() + "/apart.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace tetglow::test
