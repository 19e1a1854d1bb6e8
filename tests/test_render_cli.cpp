// `tetglow render` and `tetglow diff` as a user runs them: files written, determinism across
// thread counts, Ctrl-C, and clear errors for broken scenes.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow::test {
namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

const std::string kSphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

TEST(RenderCommand, WritesExrAndPngAndReportsTimes) {
    const std::string out = tempDir() + "/sub/dir/sphere.exr";
    const auto r = runTetglow("render " + kSphere + " --resolution 24x20 --spp 2 -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::file_size(out) > 0);
    EXPECT_TRUE(std::filesystem::file_size(tempDir() + "/sub/dir/sphere.png") > 0);
    EXPECT_NE(r.out.find("tetrahedralization"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rendering"), std::string::npos) << r.out;
}

// (d) through the command: the same seed gives byte-identical EXR files on 1 and 2 threads.
TEST(RenderCommand, SameSeedSameFileAnyThreadCount) {
    const std::string dir = tempDir();
    for (const char* integrator : {"volpath", "single"}) {
        const std::string common =
            "render " + kSphere + " --resolution 20x16 --spp 2 --seed 9 --integrator " + integrator;
        ASSERT_EQ(runTetglow(common + " --threads 1 -o " + dir + "/one.exr").exitCode, 0);
        ASSERT_EQ(runTetglow(common + " --threads 2 -o " + dir + "/two.exr").exitCode, 0);
        EXPECT_EQ(slurp(dir + "/one.exr"), slurp(dir + "/two.exr")) << integrator;
        const auto d = runTetglow("diff " + dir + "/one.exr " + dir + "/two.exr --json");
        ASSERT_EQ(d.exitCode, 0) << d.err;
        EXPECT_NE(d.out.find("\"rmse\": 0.0"), std::string::npos) << d.out;
    }
}

TEST(RenderCommand, CtrlCStillWritesTheImage) {
    const std::string dir = tempDir(), out = dir + "/partial.exr";
    // A render far too long to finish; SIGINT after a second must stop it and write the image.
    const std::string cmd = "( " + std::string(TETGLOW_BINARY) + " render " + kSphere +
                            " --spp 100000 --resolution 64x64 -o " + out + " >" + dir +
                            "/log 2>&1 & pid=$!; sleep 2; kill -INT $pid; wait $pid; echo $? >" + dir + "/code )";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(slurp(dir + "/code"), "130\n") << slurp(dir + "/log");
    EXPECT_NE(slurp(dir + "/log").find("interrupted"), std::string::npos) << slurp(dir + "/log");
    EXPECT_GT(std::filesystem::file_size(out), 0u);
    EXPECT_GT(std::filesystem::file_size(dir + "/partial.png"), 0u);
}

// (e) Broken scenes: one line naming the file and what is wrong, exit code 1, no image.
// A scattering sphere in glass under point, spot and distant lights: volpath and single cannot
// carry their light through the glass and say so, naming the integrator that can.
TEST(RenderCommand, DeltaLightsBehindGlassAreReported) {
    const std::string lights[] = {R"({"type": "point", "position": [2, 3, 2], "intensity": 20})",
                                  R"({"type": "spot", "position": [0, 3, 0], "look_at": [0, 0, 0], "intensity": 20})",
                                  R"({"type": "distant", "direction": [0, -1, 0], "irradiance": 2})"};
    for (const std::string& light : lights) {
        const std::string scene =
            writeTemp("glass.json", R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
            "integrator": {"spp": 1}, "lights": [)" +
                                        light + R"(],
            "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_s": 2, "boundary": {"type": "dielectric", "ior": 1.5}}]})");
        for (const char* integrator : {"volpath", "single", "photon"}) {
            const auto r = runTetglow("render " + scene + " --photons 100 --integrator " + integrator + " -o " +
                                      tempDir() + "/glass.exr");
            ASSERT_EQ(r.exitCode, 0) << r.err;
            const bool warned =
                r.err.find("warning: /media/0 lies inside a dielectric boundary, through which " +
                           std::string(integrator) + " cannot carry light from a point, spot or distant light") !=
                std::string::npos;
            EXPECT_EQ(warned, std::string(integrator) != "photon") << light << integrator << ": " << r.err;
            if (warned) {
                EXPECT_NE(r.err.find("--integrator photon renders it\n"), std::string::npos) << r.err;
            }
        }
    }
    // Under a sky alone (no delta light) nothing is missing.
    const std::string sky =
        writeTemp("sky.json", R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [4, 4]},
        "integrator": {"spp": 1}, "lights": [{"type": "environment", "radiance": 1}],
        "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_s": 2, "boundary": {"type": "dielectric", "ior": 1.5}}]})");
    const auto r = runTetglow("render " + sky + " -o " + tempDir() + "/sky.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// A dense glowing sphere in glass (photons are traced: the glass makes caustics) takes all 64
// events of each path: 10 million paths would take minutes. Under --time the pass stops
// starting blocks of paths when the time is up.
TEST(RenderCommand, APhotonPassEndsWithItsTimeLimit) {
    const std::string scene =
        writeTemp("dense.json", R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "resolution": [1, 1]},
        "integrator": {"type": "photon", "spp": 1, "photons": 10000000},
        "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1}, "sigma_s": 1000, "emission": 1,
                     "boundary": {"type": "dielectric", "ior": 1.3}}]})");
    const auto r = runTetglow("render " + scene + " --time 0.001 -o " + tempDir() + "/dense.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const size_t at = r.out.find("photons: ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_LT(std::stoull(r.out.substr(at + 9)), 10000000ull) << r.out;
}

TEST(RenderCommand, BrokenScenesGetClearErrors) {
    const std::string sphere = slurp(kSphere);
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = sphere;
        const size_t at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return s.replace(at, from.size(), to);
    };
    struct Case {
        std::string name, text, expected;
    };
    const std::vector<Case> cases = {
        {"syntax", "{\"camera\": ", "syntax.json"},
        {"missing-mesh",
         replaced("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"subdivisions\": 4}",
                  "{\"type\": \"mesh\", \"file\": \"no/such/mesh.obj\"}"),
         "no/such/mesh.obj"},
        {"bad-sigma", replaced("\"sigma_a\": [0.3, 0.3, 0.3]", "\"sigma_a\": [0.3, \"x\", 0.3]"), "/media/0/sigma_a"},
        {"nan-g", replaced("\"g\": 0.0", "\"g\": 1e999"), "/media/0/g"},
    };
    for (const auto& c : cases) {
        const std::string path = writeTemp(c.name + ".json", c.text), out = tempDir() + "/" + c.name + ".exr";
        const auto r = runTetglow("render " + path + " -o " + out);
        EXPECT_EQ(r.exitCode, 1) << c.name << ": " << r.err;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.name << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
    }
    EXPECT_EQ(runTetglow("render /no/such/scene.json").exitCode, 2);  // a usage error: CLI11 checks the file exists
    EXPECT_EQ(runTetglow("render " + kSphere + " --integrator magic").exitCode, 2);
    EXPECT_EQ(runTetglow("render " + kSphere + " --resolution 10by10").exitCode, 2);
}

TEST(RenderCommand, NoiseGivesTheSameFileOnOneAndTwoThreads) {
    const std::string dir = tempDir(), common = "render " + kSphere + " --resolution 20x16 --seed 3 --noise 0.02";
    const auto one = runTetglow(common + " --threads 1 -o " + dir + "/one.exr");
    ASSERT_EQ(one.exitCode, 0) << one.err;
    ASSERT_EQ(runTetglow(common + " --threads 2 -o " + dir + "/two.exr").exitCode, 0);
    EXPECT_EQ(slurp(dir + "/one.exr"), slurp(dir + "/two.exr"));
    EXPECT_NE(one.err.find("noise"), std::string::npos) << one.err;
    EXPECT_NE(one.out.find("estimated relative MSE"), std::string::npos) << one.out;
}

// A CSV beside the image: a header and one row per pass, whose last error is what `diff` says.
TEST(RenderCommand, ReferenceWritesTheErrorPerPass) {
    const std::string dir = tempDir(), common = "render " + kSphere + " --resolution 20x16 ";
    ASSERT_EQ(runTetglow(common + "--spp 64 --seed 1 -o " + dir + "/ref.exr").exitCode, 0);
    const auto r = runTetglow(common + "--spp 5 --seed 2 --reference " + dir + "/ref.exr -o " + dir + "/test.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream csv(slurp(dir + "/test.csv"));
    std::string line, last;
    std::getline(csv, line);
    EXPECT_EQ(line, "pass,seconds,noise_estimate,rel_mse_vs_reference");
    int rows = 0;
    while (std::getline(csv, line)) {
        ++rows;
        last = line;
    }
    EXPECT_EQ(rows, 5);
    EXPECT_EQ(last.rfind("5,", 0), 0u) << last;
    const auto d = runTetglow("diff " + dir + "/test.exr " + dir + "/ref.exr --json");
    ASSERT_EQ(d.exitCode, 0) << d.err;
    const double csvError = std::stod(last.substr(last.rfind(',') + 1));
    const auto at = d.out.find("\"rel_mse\": ");
    ASSERT_NE(at, std::string::npos) << d.out;
    EXPECT_NEAR(std::stod(d.out.substr(at + 11)), csvError, 1e-6 * csvError + 1e-12);
    // A reference of another size: one line naming it.
    expectOneLineError(runTetglow("render " + kSphere + " --resolution 8x8 --spp 1 --reference " + dir +
                                  "/ref.exr -o " + dir + "/x.exr"),
                       1, "ref.exr: the reference is 20x16");
}

}  // namespace
}  // namespace tetglow::test
