// Numbers at the edges of their types and requests that cannot finish: each is a one-line
// input error naming the value and its range, never an abort in Embree, +Inf pixels, a wrapped
// integer, a loop that never ends or std::bad_alloc.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// A box of glowing, scattering medium seen from z = 4: 4x4 pixels, one sample.
Json scene() {
    return Json::parse(R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
                           "integrator": {"spp": 1},
                           "media": [{"shape": {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}, "sigma_s": 1, "emission": 1}]})");
}

// Renders the scene (killed after a minute: a hang fails the test instead of hanging it).
CommandResult renderScene(const Json& s, const std::string& options = "") {
    const std::string path = writeTemp("scene.json", s.dump());
    return runTetglow("render " + path + " -o " + tempDir() + "/out.exr " + options, 60);
}

void expectRefused(const CommandResult& r, int code, const std::string& expected) {
    expectOneLineError(r, code, expected);
    EXPECT_FALSE(fs::exists(tempDir() + "/out.exr"));
}

// Embree aborts on a ray whose origin or direction its ray.valid() refuses.
TEST(SceneLimits, FarCameraIsAnErrorNotAnEmbreeAbort) {
    Json s = scene();
    s["camera"]["position"] = {1e30, 0, 4};
    expectRefused(renderScene(s), 1,
                  "/camera/position: expected an array of 3 numbers in [-1e12, 1e12], got [1e+30,0,4]");
}

TEST(SceneLimits, DirectionsThatCannotBeNormalisedAreErrors) {
    Json s = scene();
    s["lights"] = Json::parse(R"([{"type": "distant", "direction": [1e300, 1e300, 0], "irradiance": 1}])");
    expectRefused(renderScene(s), 1, "/lights/0/direction: expected an array of 3 numbers in [-1e12, 1e12]");
    s["lights"][0]["direction"] = {1e-300, 0, 0};  // its square underflows: normalising divides by 0
    expectRefused(renderScene(s), 1, "/lights/0/direction: expected a vector of length >= 1e-12, got [1e-300,0,0]");
    s["lights"] =
        Json::parse(R"([{"type": "spot", "position": [0, 3, 0], "look_at": [0, 3, 1e-300], "intensity": 1}])");
    expectRefused(renderScene(s), 1, "/lights/0/look_at: expected a point at least 1e-12 from \"position\"");
}

TEST(SceneLimits, MeshPlacedBeyondTheBoundIsAnError) {
    Json s = scene();
    s["media"][0]["shape"]["transform"] = Json::parse(R"([{"scale": 1e7}, {"scale": 1e7}])");  // each in range
    expectRefused(renderScene(s), 1, "/media/0/shape: vertex 0 has a coordinate outside [-1e12, 1e12] once placed");
}

// The image stores 32-bit floats: a finite double beyond their range gave +Inf pixels and exit 0;
// the film's exact sums hold samples up to 2^32, and one beyond is an error, never dropped unsaid.
TEST(SceneLimits, ColoursBeyondFloatAreErrors) {
    Json s = scene();
    s["media"][0]["emission"] = 1e39;
    expectRefused(renderScene(s), 1,
                  "/media/0/emission: expected an array of 3 numbers in [0, 3.40282e38] (or one for all 3), got 1e+39");
    s["media"][0]["emission"] = 3e38;  // in range, but times a chord of 2 it is not
    s["media"][0]["sigma_s"] = 0;
    expectRefused(renderScene(s), 1, "beyond the film's range (at most 4.29497e9 per sample)");
}

TEST(SceneLimits, PbrtNumbersAndCountsDoNotWrap) {
    const std::string head =
        "LookAt 0 0 4  0 0 0  0 1 0\nCamera \"perspective\"\n"
        "Film \"image\" \"integer xresolution\" 4 \"integer yresolution\" 4\n";
    const std::string world = "WorldBegin\nLightSource \"point\" \"point from\" [0 2 0]\nWorldEnd\n";
    const std::pair<std::string, std::string> cases[] = {
        // max_depth = maxdepth + 1 wrapped to INT_MIN: every path ended at once and the image was black.
        {"Integrator \"volpath\" \"integer maxdepth\" 2147483647\n",
         "parameter \"integer maxdepth\": must be in 0..1048575"},
        // 65536 x 65537 samples wrapped to 65536.
        {"Sampler \"stratified\" \"integer xsamples\" 65536 \"integer ysamples\" 65537\n",
         "samples per pixel must be in 1..1048576"},
        {"Sampler \"halton\" \"integer seed\" -3\n", "parameter \"integer seed\": must not be negative"},
        // pbrt-v3 reads floats: 1e39 is not one.
        {"Camera \"perspective\" \"float fov\" 1e39\n",
         "expected a finite number of float range (|x| <= 3.40282e38), got '1e39'"},
    };
    for (const auto& [line, expected] : cases) {
        SCOPED_TRACE(line);
        const std::string path = writeTemp("scene.pbrt", head + line + world);
        expectRefused(runTetglow("render " + path + " -o " + tempDir() + "/out.exr", 60), 1, expected);
    }
    const std::string far =
        writeTemp("far.pbrt", head + "WorldBegin\nTranslate 1e30 0 0\nLightSource \"point\"\nWorldEnd\n");
    expectRefused(runTetglow("render " + far + " -o " + tempDir() + "/out.exr", 60), 1,
                  "light 0 position (1e+30, 0, 0) is out of range");
}

// A step so small that t + step == t looped for ever; one a little larger, for hours.
TEST(Loops, TooSmallMarchStepIsAnError) {
    for (const char* options : {"--integrator single --step 1e-300", "--integrator single --step 1e-9",
                                "--integrator photon --estimate knn-march --step 1e-300"})
        expectRefused(renderScene(scene(), options), 1, "step (/integrator/step or --step) ");
    const std::string mesh = writeTemp("box.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\n"
                                       "f 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n");
    expectOneLineError(runTetglow("compare-boundary " + mesh + " --points 1 --rays 1 --steps 1e-300", 60), 1,
                       "--steps 1e-300 is too small for this scene: at least 1.73205e-06");
}

// TetGen refined for ever under a tiny volume bound: a bound that asks for more tets than the
// machine holds is refused before TetGen starts.
TEST(Loops, TetGenVolumeBoundTooSmallIsAnError) {
    Json s = scene();
    s["media"][0]["tetgen"] = {{"max_volume", 1e-30}};
    expectRefused(renderScene(s), 1,
                  "/media/0: max volume 1e-30 (TetGen -a) would make at least 8e+30 tets of this mesh (volume 8), more "
                  "than 10000000: use a max volume >= 8e-07");
}

// A documented maximum (2^40 photon paths per pass) allocated far beyond the machine and died as
// std::bad_alloc: it is checked against the machine's memory first.
TEST(Memory, PhotonsBeyondTheMachineAreAnErrorNotBadAlloc) {
    const auto r = renderScene(scene(), "--integrator photon --photons 1099511627776");
    expectRefused(r, 1, "1099511627776 photon paths per pass (a 32-byte photon each) needs about");
    EXPECT_NE(r.err.find("more than this machine's"), std::string::npos) << r.err;
}

// An error echoing a 100 kB key stays a short line.
TEST(Messages, LongKeysAreShortened) {
    Json s = scene();
    s["camera"][std::string(100000, 'k')] = 1;
    const auto r = renderScene(s);
    expectRefused(r, 1, "unknown key; allowed here: position, look_at, up, fov, resolution, handedness");
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
}

}  // namespace
}  // namespace tetglow::test
