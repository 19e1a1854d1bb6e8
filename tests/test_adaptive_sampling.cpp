// Adaptive sampling to a noise target (render/AdaptiveSampling.h): the samples go to the tiles
// whose noise estimate is high, the image is the same at any thread count and for any split into
// parts (each replays the pilot), and stopping early leaves the image's mean where a fixed-spp
// render has it.
#include <algorithm>
#include <cstring>
#include <regex>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "render/AdaptiveSampling.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"

namespace tetglow::test {
namespace {

// A glowing, scattering sphere in a uniform sky: the sky's pixels are flat (a ray that misses
// sees the same radiance every sample), the sphere's noisy.
RenderOptions adaptive(uint64_t seed, double target = 0.002) {
    RenderOptions options;
    options.spp = 512;
    options.seed = seed;
    options.noiseTarget = target;
    return options;
}

bool sameFilm(const Film& a, const Film& b) {
    if (a.pixelCount() != b.pixelCount()) return false;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        if (a.sum(i) != b.sum(i) || a.count(i) != b.count(i) || a.dropped(i) != b.dropped(i)) return false;
    return true;
}

TEST(AdaptiveSampling, SamplesGoWhereTheErrorIs) {
    const int size = 48;  // 6x6 tiles
    SceneDesc desc = glowingSphereUnderQuad(size);
    desc.camera.position *= 2.5;  // the sphere across the middle third: the corner's tiles see sky alone
    const Scene scene(desc);
    const auto integrator = makeIntegrator(scene, IntegratorDesc{});
    const RenderResult r = render(scene, *integrator, adaptive(3, 0.001));
    const Film& film = r.film;
    const uint32_t sky = film.count(0), sphere = film.count(size_t(size / 2) * size + size / 2);
    // The flat sky takes the pilot only; the sphere's centre the passes its noise needs.
    EXPECT_EQ(sky, uint32_t(kPilotPasses));
    EXPECT_GT(sphere, 2 * sky) << "sky " << sky << ", sphere " << sphere;
    EXPECT_EQ(r.stop, RenderStop::Noise);  // every tile reached the target before the cap
    uint32_t most = 0;
    for (size_t i = 0; i < film.pixelCount(); ++i) most = std::max(most, film.count(i));
    EXPECT_EQ(r.passes, int(most));
    EXPECT_LT(most, 512u);
    // A tile's pixels share their count.
    for (int y = 8; y < 16; ++y)
        for (int x = 8; x < 16; ++x) EXPECT_EQ(film.count(size_t(y) * size + x), film.count(8 * size + 8));
}

TEST(AdaptiveSampling, SameBitsOnAnyThreadCount) {
    const Scene scene(glowingSphereUnderQuad(24));
    const auto integrator = makeIntegrator(scene, IntegratorDesc{});
    RenderOptions options = adaptive(5);
    options.threads = 1;
    const RenderResult one = render(scene, *integrator, options);
    options.threads = 2;
    const RenderResult two = render(scene, *integrator, options);
    EXPECT_GT(one.passes, kPilotPasses);
    EXPECT_EQ(one.passes, two.passes);
    EXPECT_TRUE(sameFilm(one.film, two.film));
    EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(),
                             one.image.pixels.size() * sizeof(one.image.pixels[0])));
}

// Parts that start after the pilot, inside it, and at 0, each from a fresh integrator (a process
// of its own), merged last first: the whole render's film, sums and counts.
TEST(AdaptiveSampling, PartsMergeIntoTheWholeRenderBitForBit) {
    const Scene scene(glowingSphereUnderQuad(24));
    IntegratorDesc integ;
    const RenderResult whole = render(scene, *makeIntegrator(scene, integ), adaptive(7));
    ASSERT_GT(whole.passes, kPilotPasses + 8);
    for (const std::vector<std::pair<int, int>>& split :
         {std::vector<std::pair<int, int>>{{0, 5}, {5, 30}, {30, 512}}, {{0, 20}, {20, 21}, {21, 512}}}) {
        Film merged(24, 24);
        for (auto range = split.rbegin(); range != split.rend(); ++range) {
            RenderOptions options = adaptive(7);
            options.firstPass = range->first;
            options.endPass = range->second;
            const RenderResult part = render(scene, *makeIntegrator(scene, integ), options);
            ASSERT_TRUE(merged.merge(part.film));
        }
        EXPECT_TRUE(sameFilm(merged, whole.film)) << split[0].second << ":" << split[1].second;
    }
}

// Through the commands a farm's tasks run: three parts, with --noise, merge into the file the
// single render writes, byte for byte; and a part to another target is refused.
TEST(AdaptiveSampling, ThreePartCommandsMergeIntoTheRenderedFile) {
    const std::string dir = tempDir(), sphere = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";
    const std::string common = "render " + sphere + " --resolution 48x36 --spp 200 --seed 3 --noise 0.0005";
    const auto single = runTetglow(common + " -o " + dir + "/single.exr");
    ASSERT_EQ(single.exitCode, 0) << single.err;
    // Tiles took different counts, some more than the pilot and than the second part's end.
    std::smatch spp;
    ASSERT_TRUE(
        std::regex_search(single.out, spp, std::regex(R"((\d+) spp \(the most a pixel took; ([0-9.]+) on average)")))
        << single.out;
    EXPECT_GT(std::stoi(spp[1]), 40);
    EXPECT_LT(std::stod(spp[2]), std::stoi(spp[1]));
    std::string parts;
    for (const char* range : {"0:9", "9:40", "40:200"}) {
        const std::string part = dir + "/part-" + std::string(range).substr(0, std::string(range).find(':')) + ".exr";
        const auto r = runTetglow(common + " --threads 2 --pass-range " + range + " -o " + part);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        parts += " " + part;
    }
    const auto m = runTetglow("merge" + parts + " -o " + dir + "/merged.exr");
    ASSERT_EQ(m.exitCode, 0) << m.err;
    EXPECT_TRUE(readFile(dir + "/merged.exr") == readFile(dir + "/single.exr"));
    const auto other =
        runTetglow("render " + sphere + " --resolution 48x36 --spp 200 --seed 3 --noise 0.01 --pass-range 0:9 -o " +
                   dir + "/other.exr");
    ASSERT_EQ(other.exitCode, 0) << other.err;
    const auto refused = runTetglow("merge " + dir + "/other.exr " + dir + "/part-9.exr " + dir + "/part-40.exr -o " +
                                    dir + "/mixed.exr");
    EXPECT_NE(refused.exitCode, 0);
    EXPECT_NE(refused.err.find("different scene or different settings"), std::string::npos) << refused.err;
}

// Where a tile stops depends on its pilot, whose samples stay in the image: a small bias, as in
// Cycles. The mean over seeds of the sphere's pixels agrees with a long fixed-spp render within
// the seeds' standard error.
TEST(AdaptiveSampling, MeanOverSeedsIsTheFixedSppMean) {
    const Scene scene(glowingSphereUnderQuad(16));
    const auto integrator = makeIntegrator(scene, IntegratorDesc{});
    RenderOptions fixed;
    fixed.spp = 4096;
    fixed.seed = 1000;
    const Image reference = render(scene, *integrator, fixed).image;
    auto centre = [](const Image& image) {
        RGB sum(0);
        for (int y = 4; y < 12; ++y)
            for (int x = 4; x < 12; ++x) sum += RGB(image.at(x, y));
        return sum / 64.0;
    };
    uint32_t fewest = UINT32_MAX, most = 0;  // over the centre's tiles and the seeds
    const Estimate e = estimateMean(24, [&](int i) {
        const RenderResult r = render(scene, *integrator, adaptive(i, 0.002));
        for (int y = 4; y < 12; ++y)
            for (int x = 4; x < 12; ++x) {
                fewest = std::min(fewest, r.film.count(size_t(y) * 16 + x));
                most = std::max(most, r.film.count(size_t(y) * 16 + x));
            }
        return centre(r.image);
    });
    EXPECT_GT(most, 2 * uint32_t(kPilotPasses));  // the tiles and seeds stopped at passes of their own
    EXPECT_GT(most, fewest);
    const RGB expected = centre(reference);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(e.mean[c], expected[c], 4 * e.stdError[c] + 1e-3 * expected[c]) << "channel " << c;
        EXPECT_GT(e.stdError[c], 0);
    }
}

}  // namespace
}  // namespace tetglow::test
