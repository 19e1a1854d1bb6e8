// The preview's render follows a change at once, also in the middle of a long photon pass, and
// samples to a noise target by the rule `render --noise` follows.
#include <chrono>
#include <cstring>
#include <thread>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "cli/LiveRender.h"
#include "render/AdaptiveSampling.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"

namespace tetglow::test {
namespace {

TEST(LiveRender, AChangeInterruptsAPhotonPass) {
    // Photons that mostly cross the sphere unscattered: cheap to store, but 5e7 paths on one
    // thread take a minute or more.
    SceneDesc slow = sceneWith(sphereMedium(RGB(0.5), RGB(0.001)), 8);
    slow.lights.push_back(environment(1));
    slow.integrator.type = IntegratorType::Photon;
    slow.integrator.photons = 50'000'000;
    slow.integrator.maxDepth = 1;
    slow.integrator.spp = 1;
    SceneDesc quick = slow;
    quick.integrator.photons = 1000;

    LiveRender live(std::make_unique<Scene>(slow), 1);
    live.restart(slow);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // well into the first photon pass
    const uint64_t generation = live.restart(quick);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(20 * testTimeScale());
    while (std::chrono::steady_clock::now() < deadline && !(live.latest() && live.latest()->generation == generation))
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_TRUE(live.latest() && live.latest()->generation == generation)
        << "the change waited for the photon pass to finish";
    EXPECT_EQ(live.error(), "");
}

// Its passes end where the render's do, on the render's image bit for bit: without the rule the
// image of that pass would have every pixel sampled, and the passes would go on to the spp.
TEST(LiveRender, NoiseTargetSamplesAsRenderDoes) {
    SceneDesc desc = glowingSphereUnderQuad(16);
    desc.integrator.spp = 256;
    desc.integrator.seed = 4;
    const Scene scene(desc);
    RenderOptions options;
    options.spp = 256;
    options.seed = 4;
    options.noiseTarget = 0.002;
    const RenderResult expected = render(scene, *makeIntegrator(scene, desc.integrator), options);
    ASSERT_GT(expected.passes, kPilotPasses);
    ASSERT_LT(expected.passes, 256);

    LiveRender live(std::make_unique<Scene>(desc), 1, options.noiseTarget);
    live.restart(desc);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(60 * testTimeScale());
    while (std::chrono::steady_clock::now() < deadline && !(live.latest() && live.latest()->passes >= expected.passes))
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // a pass after the last would be published by now
    const auto last = live.latest();
    ASSERT_TRUE(last);
    EXPECT_EQ(last->passes, expected.passes);
    ASSERT_EQ(last->image.pixels.size(), expected.image.pixels.size());
    EXPECT_EQ(0, std::memcmp(last->image.pixels.data(), expected.image.pixels.data(),
                             expected.image.pixels.size() * sizeof(expected.image.pixels[0])));
    EXPECT_EQ(live.error(), "");
}

}  // namespace
}  // namespace tetglow::test
