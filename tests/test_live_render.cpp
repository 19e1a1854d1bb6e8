// The preview's render follows a change at once, also in the middle of a long photon pass.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "cli/LiveRender.h"

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

}  // namespace
}  // namespace tetglow::test
