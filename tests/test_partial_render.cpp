// Renders split into parts (render --pass-range) and merged (merge) are the single render, bit
// for bit, for any split; merge refuses parts that do not make up one render.
#include <sys/stat.h>

#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>

#include "Sanitizers.h"
#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "render/PartialRender.h"
#include "render/Renderer.h"

namespace tetglow::test {
namespace {

const std::string kSphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof a.pixels[0]) == 0;
}

using Split = std::vector<std::pair<int, int>>;
const std::vector<Split> kSplits = {
    {{0, 16}},
    {{0, 2}, {2, 11}, {11, 16}},
    {{0, 1},
     {1, 2},
     {2, 3},
     {3, 4},
     {4, 5},
     {5, 6},
     {6, 7},
     {7, 8},
     {8, 9},
     {9, 10},
     {10, 11},
     {11, 12},
     {12, 13},
     {13, 14},
     {14, 15},
     {15, 16}},
};

// The renderer itself: the films of the parts, merged in any order, are the single render's.
TEST(PartialRender, MergedFilmsAreTheSingleRenderBitForBit) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.3), RGB(1.5, 2, 2.5), 0.4), 12);
    desc.lights.push_back(environment(0.5));
    LightDesc point;
    point.position = {2, 3, 2};
    point.intensity = RGB(20);
    desc.lights.push_back(point);
    const Scene scene(desc);
    for (IntegratorType type : {IntegratorType::VolPath, IntegratorType::Photon}) {
        desc.integrator.type = type;
        desc.integrator.photons = 2000;
        RenderOptions options;
        options.spp = 16;
        options.seed = 5;
        auto integrator = makeIntegrator(scene, desc.integrator);
        const RenderResult single = render(scene, *integrator, options);
        ASSERT_EQ(single.passes, 16);
        for (const Split& split : kSplits) {
            Film merged(12, 12);
            // Merged last part first: the order must not matter either.
            for (auto range = split.rbegin(); range != split.rend(); ++range) {
                auto partIntegrator = makeIntegrator(scene, desc.integrator);  // a fresh process's
                options.firstPass = range->first;
                options.endPass = range->second;
                const RenderResult part = render(scene, *partIntegrator, options);
                EXPECT_EQ(part.passes, range->second - range->first);
                if (split.size() > 1) {
                    EXPECT_FALSE(sameBits(part.image, single.image));  // a part alone is not the image
                }
                ASSERT_TRUE(merged.merge(part.film));
            }
            EXPECT_TRUE(sameBits(merged.image(), single.image))
                << nameOf(kIntegratorNames, type) << ", " << split.size() << " parts";
            for (size_t i = 0; i < merged.pixelCount(); ++i) ASSERT_EQ(merged.sum(i), single.film.sum(i)) << i;
        }
        float brightest = 0;
        for (const auto& p : single.image.pixels) brightest = std::max(brightest, p.x);
        EXPECT_GT(brightest, 0.01f);  // an image, not a black frame that any sum matches
    }
}

// The same through the commands: byte-identical EXR files, photon and volpath.
TEST(PartialRender, MergeOfAnySplitIsTheRenderedFile) {
    const std::string dir = tempDir();
    for (const char* integrator : {"volpath", "photon"}) {
        const std::string common =
            "render " + kSphere + " --resolution 16x12 --spp 16 --seed 3 --photons 3000 --integrator " + integrator;
        const auto single = runTetglow(common + " -o " + dir + "/single.exr");
        ASSERT_EQ(single.exitCode, 0) << single.err;
        for (const Split& split : kSplits) {
            std::string parts;
            for (const auto& [a, b] : split) {
                const std::string part = dir + "/part-" + std::to_string(a) + ".exr";
                const auto r = runTetglow(common + " --threads 2 --pass-range " + std::to_string(a) + ":" +
                                          std::to_string(b) + " -o " + part);
                ASSERT_EQ(r.exitCode, 0) << r.err;
                parts += " " + part;
            }
            const auto m = runTetglow("merge" + parts + " -o " + dir + "/merged.exr");
            ASSERT_EQ(m.exitCode, 0) << m.err;
            EXPECT_EQ(readFile(dir + "/merged.exr"), readFile(dir + "/single.exr"))
                << integrator << ", " << split.size() << " parts";
            EXPECT_TRUE(std::filesystem::exists(dir + "/merged.png"));
        }
    }
}

TEST(PartialRender, MergeRefusesPartsThatAreNotOneRender) {
    const std::string dir = tempDir();
    const std::string common = "render " + kSphere + " --resolution 8x6";
    auto part = [&](const std::string& name, const std::string& range, const std::string& extra = " --spp 6") {
        const std::string path = dir + "/" + name + ".exr";
        const auto r = runTetglow(common + extra + " --pass-range " + range + " -o " + path);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return path;
    };
    const std::string a = part("a", "0:3"), b = part("b", "3:6"), overlap = part("overlap", "2:5"),
                      tail = part("tail", "5:6");
    const std::string seed = part("seed", "3:6", " --spp 6 --seed 7"), spp = part("spp", "3:6", " --spp 7");
    ASSERT_EQ(runTetglow(common + " --spp 6 -o " + dir + "/whole.exr").exitCode, 0);
    struct Case {
        std::string parts, file, message;
    };
    const std::vector<Case> cases = {
        {a + " " + seed, seed, "a different scene or different settings"},
        {a + " " + spp, spp, "a different scene or different settings"},
        {a + " " + overlap + " " + b, overlap, "passes 2:5 overlap passes 0:3"},
        {a + " " + tail, tail, "passes 3:5 before its 5:6 are in no part"},
        {b, b, "passes 0:3 before its 3:6 are in no part"},
        {a, a, "passes 3:6 after its 0:3 are in no part"},
        {a + " " + b + " " + b, b, "overlap"},
        {a + " " + dir + "/whole.exr", dir + "/whole.exr", "not a partial render"},
        {a + " " + dir + "/none.exr", dir + "/none.exr", "no such file"},
    };
    for (const Case& c : cases) {
        const auto r = runTetglow("merge " + c.parts + " -o " + dir + "/out.exr");
        EXPECT_EQ(r.exitCode, 1) << c.parts;
        EXPECT_NE(r.err.find(c.file + ": "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir + "/out.exr")) << c.parts;
    }
    // A part is read like every input: a FIFO in its place blocked merge for ever.
    const std::string fifo = dir + "/fifo.exr";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto r = runTetglow("merge " + a + " " + fifo + " -o " + dir + "/out.exr", 60);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(fifo + ": is a FIFO"), std::string::npos) << r.err;
    EXPECT_EQ(runTetglow("merge " + a + " " + b + " -o " + dir + "/out.exr").exitCode, 0);
}

TEST(PartialRender, RefusesTimeLimitsAndBadRanges) {
    const std::string dir = tempDir(), common = "render " + kSphere + " --resolution 8x6 --spp 6 -o " + dir + "/p.exr";
    for (const char* bad : {" --pass-range 0:3 --time 1", " --pass-range 3:3", " --pass-range 0:7", " --pass-range 2",
                            " --pass-range -1:2"}) {
        const auto r = runTetglow(common + bad);
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find("--"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir + "/p.exr")) << bad;
    }
}

// Another build may sample a pass differently (one sampler constant changed): its parts would
// merge into an image that matches neither build, so the build that made a part is recorded and
// must agree.
TEST(PartialRender, MergeRefusesPartsOfAnotherBuild) {
    const std::string dir = tempDir(), common = "render " + kSphere + " --resolution 8x6 --spp 4";
    const std::string a = dir + "/a.exr", b = dir + "/b.exr", other = dir + "/other.exr";
    ASSERT_EQ(runTetglow(common + " --pass-range 0:2 -o " + a).exitCode, 0);
    ASSERT_EQ(runTetglow(common + " --pass-range 2:4 -o " + b).exitCode, 0);
    PartialRender part = readPartial(b);
    EXPECT_EQ(part.info.build.size(), 40u) << "a SHA-1 build id in hex: " << part.info.build;
    EXPECT_EQ(part.info.build, readPartial(a).info.build);
    part.info.build = std::string(40, '0');
    writePartial(other, part);
    expectOneLineError(runTetglow("merge " + a + " " + other + " -o " + dir + "/out.exr"), 1,
                       other + ": made by another tetglow build than " + a +
                           " (build 0000000000000000000000000000000000000000 vs " + readPartial(a).info.build +
                           "): render every part with one binary");
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.exr"));
    EXPECT_EQ(runTetglow("merge " + a + " " + b + " -o " + dir + "/out.exr").exitCode, 0);
}

// Peak memory of `tetglow merge` (KiB, the binary runTetglow runs), from the kernel's account of the child.
long mergePeakKiB(const std::string& args) {
    const std::string dir = tempDir(), report = dir + "/peak";
    const char* binary = std::getenv("TETGLOW_TEST_BINARY") ? std::getenv("TETGLOW_TEST_BINARY") : TETGLOW_BINARY;
    const std::string command =
        "python3 -c 'import resource, subprocess, sys; subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, "
        "check=True); "
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)' " +
        std::string(binary) + " merge " + args + " > " + report;
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    const std::string peak = readFile(report);
    return peak.empty() ? 0 : std::stol(peak);
}

// 16 parts of a 256x256 frame (about 4 MB of film each): merge holds one film and one part at a
// time, so its memory is that of merging one part, not 16 times as much.
TEST(PartialRender, MergeMemoryDoesNotGrowWithTheParts) {
    if (test::kAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer keeps freed films resident: the Release suite checks this bound";
    const std::string dir = tempDir(),
                      common = "render " + kSphere + " --resolution 256x256 --integrator single --step 0.2";
    std::string parts;
    for (int p = 0; p < 16; ++p) {
        const std::string part = dir + "/p" + std::to_string(p) + ".exr";
        ASSERT_EQ(runTetglow(common + " --spp 16 --pass-range " + std::to_string(p) + ":" + std::to_string(p + 1) +
                             " -o " + part)
                      .exitCode,
                  0);
        parts += " " + part;
    }
    ASSERT_EQ(runTetglow(common + " --spp 1 --pass-range 0:1 -o " + dir + "/one.exr").exitCode, 0);
    const long one = mergePeakKiB(dir + "/one.exr -o " + dir + "/one-merged.exr");
    const long sixteen = mergePeakKiB(parts + " -o " + dir + "/merged.exr");
    const long film = 256 * 256 * long(kFilmBytesPerPixel) / 1024;
    EXPECT_LT(sixteen, one + 3 * film) << "merging 16 parts took " << sixteen << " KiB, one part " << one
                                       << " KiB; a film is " << film << " KiB";
}

// A turntable: frames differ, frame 0 is the still, and each frame splits and merges alike.
TEST(PartialRender, TurntableFramesSplitAndMerge) {
    std::string scene = readFile(kSphere);
    const std::string camera = "\"camera\":";
    scene.insert(scene.find(camera), "\"turntable\": {\"frames\": 4, \"axis\": [0, 1, 0]},\n  ");
    const std::string path = writeTemp("turntable.json", scene), dir = tempDir();
    const std::string common = " --resolution 12x10 --spp 4";
    ASSERT_EQ(runTetglow("render " + kSphere + common + " -o " + dir + "/still.exr").exitCode, 0);
    ASSERT_EQ(runTetglow("render " + path + common + " -o " + dir + "/f0.exr").exitCode, 0);
    ASSERT_EQ(runTetglow("render " + path + common + " --frame 1 -o " + dir + "/f1.exr").exitCode, 0);
    EXPECT_EQ(readFile(dir + "/f0.exr"), readFile(dir + "/still.exr"));
    EXPECT_NE(readFile(dir + "/f1.exr"), readFile(dir + "/f0.exr"));
    for (const char* range : {"0:1", "1:4"})
        ASSERT_EQ(runTetglow("render " + path + common + " --frame 1 --pass-range " + range + " -o " + dir + "/p" +
                             range[0] + ".exr")
                      .exitCode,
                  0);
    ASSERT_EQ(runTetglow("render " + path + common + " --frame 2 --pass-range 1:4 -o " + dir + "/other.exr").exitCode,
              0);
    ASSERT_EQ(runTetglow("merge " + dir + "/p0.exr " + dir + "/p1.exr -o " + dir + "/m1.exr").exitCode, 0);
    EXPECT_EQ(readFile(dir + "/m1.exr"), readFile(dir + "/f1.exr"));
    const auto mixed = runTetglow("merge " + dir + "/p0.exr " + dir + "/other.exr -o " + dir + "/bad.exr");
    EXPECT_EQ(mixed.exitCode, 1);
    EXPECT_NE(mixed.err.find(dir + "/other.exr: frame 2, but"), std::string::npos) << mixed.err;
    const auto past = runTetglow("render " + path + common + " --frame 4 -o " + dir + "/f4.exr");
    EXPECT_EQ(past.exitCode, 1);
    EXPECT_NE(past.err.find("--frame 4 is past the scene's frames 0..3"), std::string::npos) << past.err;
}

}  // namespace
}  // namespace tetglow::test
