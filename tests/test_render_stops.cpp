// Where a render stops: the spp of the scene or of --spp caps a render that runs for a --time or
// to a --noise target, the render says its stops before the first pass and which one ended it,
// and its time left is the time to the nearest stop.
#include <regex>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

// A glowing box, 4x4 pixels: a pass takes a moment.
std::string boxScene(const std::string& integrator) {
    return R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
               "integrator": {)" +
           integrator + R"(},
               "media": [{"shape": {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}, "sigma_s": 1, "emission": 1}]})";
}

// The passes of the image written, from "OUT.exr and OUT.png: 4x4, N spp".
int passesWritten(const CommandResult& r) {
    std::smatch m;
    if (!std::regex_search(r.out, m, std::regex(R"(: \d+x\d+, (\d+) spp)"))) return -1;
    return std::stoi(m[1]);
}

// As a new user met it: init writes spp 64, and --noise ran on towards 1048576 passes.
TEST(RenderStops, NoiseStopsAtTheScenesSppAndSaysSo) {
    const std::string mesh = writeTemp("box.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\n"
                                       "f 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n");
    const std::string dir = tempDir();
    ASSERT_EQ(runTetglow("init " + mesh + " -o " + dir + "/s.json").exitCode, 0);
    // A target no 64 passes reach; --time only keeps the unfixed render from running for hours.
    const auto r =
        runTetglow("render " + dir + "/s.json --noise 1e-12 --time 20 --resolution 4x4 -o " + dir + "/s.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(passesWritten(r), 64) << r.out;
    EXPECT_NE(r.err.find("render: stops at noise 1e-12 (estimated relative MSE), after 20 s, or after 64 passes (the "
                         "scene's spp), whichever comes first"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("render: warning: by the estimate after pass 2, the noise target 1e-12 needs more than "
                         "1048576 passes (the most a render takes), more than the cap of 64 (the scene's spp)"),
              std::string::npos)
        << "said at the start: " << r.err;
    EXPECT_NE(r.err.find("render: stopped at the cap of 64 passes (the scene's spp), before the noise target 1e-12"),
              std::string::npos)
        << r.err;
    // The time left is to the cap, not to 1048576 passes.
    EXPECT_NE(r.err.find("render: pass 1 of at most 64,"), std::string::npos) << r.err;
}

TEST(RenderStops, NoiseTargetReachedBeforeTheCapIsSaid) {
    const std::string scene = writeTemp("box.json", boxScene(R"("spp": 1000)"));
    const auto r = runTetglow("render " + scene + " --noise 0.5 -o " + tempDir() + "/box.exr", 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_LT(passesWritten(r), 1000) << r.out;
    EXPECT_NE(r.err.find("render: reached the noise target 0.5 after"), std::string::npos) << r.err;
}

// FORMAT.md's "spp still caps them": --time 150 on a scene of spp 16 rendered 620 passes.
TEST(RenderStops, TimeStopsAtTheScenesSpp) {
    const std::string scene = writeTemp("box.json", boxScene(R"("spp": 6)"));
    const auto r = runTetglow("render " + scene + " --time 3 -o " + tempDir() + "/box.exr", 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(passesWritten(r), 6) << r.out;
    EXPECT_NE(r.err.find("render: stopped at the cap of 6 passes (the scene's spp), before the time limit of 3 s"),
              std::string::npos)
        << r.err;
    // --spp and --passes cap it the same way, and say so.
    const auto passes = runTetglow("render " + scene + " --time 3 --passes 3 -o " + tempDir() + "/box.exr", 60);
    ASSERT_EQ(passes.exitCode, 0) << passes.err;
    EXPECT_EQ(passesWritten(passes), 3) << passes.out;
    EXPECT_NE(passes.err.find("stopped at the cap of 3 passes (--spp)"), std::string::npos) << passes.err;
}

// A scene that gives no spp leaves a render for a time to the clock.
TEST(RenderStops, TimeWithoutAnySppRunsForTheTime) {
    const std::string scene = writeTemp("box.json", boxScene(R"("seed": 1)"));
    const auto r = runTetglow("render " + scene + " --time 0.5 -o " + tempDir() + "/box.exr", 60);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("render: stopped by the time limit of 0.5 s after"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("neither the scene nor --spp gives a spp"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tetglow::test
