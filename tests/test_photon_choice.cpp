// The photon integrator's choice, per photon domain, between its photons and the eye path's walk:
// from the errors the pilot measures (PhotonChoice), the same at any thread count.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "TestScenes.h"
#include "photon/PhotonChoice.h"
#include "photon/PhotonIntegrator.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

IntegratorDesc photonDesc() {
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 20000;
    desc.seed = 5;
    return desc;
}

DomainChoice chosen(const Scene& scene, const IntegratorDesc& desc) {
    PhotonIntegrator photon(scene, desc);
    photon.choose();
    EXPECT_EQ(photon.choices().size(), 1u);
    const DomainChoice c = photon.choices().at(0);
    std::printf(
        "%s, %llu passes: photon variance %.3g, bias^2 %.3g, walk variance %.3g over %d probes: "
        "photons %.3g, walks %.3g, walks pay from %llu\n",
        c.walked ? "walked" : "photons", (unsigned long long)c.passes, c.errors.photonVariance, c.errors.photonBias2,
        c.errors.walkVariance, c.probes, c.photonMse, c.walkMse, (unsigned long long)c.walksPayFrom);
    return c;
}

// A unit sphere whose mean free path is a tenth of its diagonal (blub's), under a point light:
// the kernel blurs the light that changes within a mean free path of its boundary, a bias that
// falls slowly, so the photons pay for a few passes and the walk for many (the same
// measurement: the pilot does not depend on the pass count). Thin and glowing, the photons' error
// is the lower one at any pass count.
TEST(PhotonChoice, ADenseMediumIsWalkedAndAThinGlowingOneReadsPhotons) {
    const double diagonal = 2 * std::sqrt(3.0);
    SceneDesc dense = sceneWith(sphereMedium(RGB(0.1 * 10 / diagonal), RGB(0.9 * 10 / diagonal)), 32);
    dense.lights.push_back(pointLight({2, 3, 2}, RGB(20)));
    IntegratorDesc desc = photonDesc();
    desc.spp = 256;
    const DomainChoice many = chosen(Scene(dense), desc);
    EXPECT_TRUE(many.measured);
    EXPECT_GT(many.probes, 100);
    EXPECT_GT(many.errors.photonBias2, 0);
    EXPECT_TRUE(many.walked);
    EXPECT_GT(many.walksPayFrom, 1u);
    EXPECT_LT(many.walksPayFrom, 256u);
    desc.spp = 2;
    const DomainChoice few = chosen(Scene(dense), desc);
    EXPECT_EQ(few.errors.photonBias2, many.errors.photonBias2);
    EXPECT_FALSE(few.walked);

    SceneDesc thin = sceneWith(sphereMedium(RGB(0.05), RGB(0.15)), 32);
    thin.media[0].emission = RGB(0.5, 1, 2);
    thin.lights.push_back(pointLight({2, 3, 2}, RGB(20)));
    const DomainChoice t = chosen(Scene(thin), photonDesc());
    EXPECT_TRUE(t.measured);
    EXPECT_GT(t.probes, 100);
    EXPECT_FALSE(t.walked);
    EXPECT_LT(t.photonMse, t.walkMse);
    EXPECT_EQ(t.walksPayFrom, 0u);
}

// The choice follows the pass count the render will reach: a biased photon estimate with little
// variance pays for a few passes, the walk for many (the measured crossover).
TEST(PhotonChoice, PhotonsPayForFewPassesAndWalksForMany) {
    const EstimateErrors e{0.001, 0.002, 0.05};
    const KernelShrink beam{2.0 / 3, 2};
    const uint64_t from = walksPayFrom(e, beam, 1 << 16);
    ASSERT_GT(from, 1u);
    EXPECT_LT(predictedPhotonMse(e, beam, from - 1), predictedWalkMse(e, from - 1));
    EXPECT_GT(predictedPhotonMse(e, beam, from), predictedWalkMse(e, from));
    EXPECT_GT(predictedPhotonMse(e, beam, 4 * from), predictedWalkMse(e, 4 * from));
    EXPECT_EQ(walksPayFrom({0.001, 0, 0.05}, beam, 1 << 16), 0u);  // no bias: photons all the way
    // One pass: the photon estimate's variance and bias as measured.
    EXPECT_DOUBLE_EQ(predictedPhotonMse(e, beam, 1), 0.003);
    EXPECT_DOUBLE_EQ(predictedWalkMse(e, 10), 0.005);
}

// The pilot's photons and eye paths depend on the seed alone and its sums run in probe order:
// the same measurement, to the last bit, and the same choice at 1, 2 and 3 threads.
TEST(PhotonChoice, TheChoiceIsTheSameAtAnyThreadCount) {
    SceneDesc s = glowingSphereUnderQuad(24);
    MediumDesc aside = sphereMedium(RGB(0.5), RGB(6));
    for (auto& p : aside.boundary.positions) p = p * 0.3 + glm::dvec3(0, 0, 2);
    aside.name = "aside";
    s.media.push_back(aside);
    const Scene scene(s);
    IntegratorDesc desc = photonDesc();
    desc.photons = 5000;
    // Workers beyond the cores, so that 3 threads run as 3 on a 2-core machine too.
    const tbb::global_control workers(tbb::global_control::max_allowed_parallelism, 3);
    auto choices = [&](int threads) {
        std::vector<DomainChoice> c;
        tbb::task_arena(threads).execute([&] {
            PhotonIntegrator photon(scene, desc);
            photon.choose();
            c = photon.choices();
        });
        return c;
    };
    const std::vector<DomainChoice> one = choices(1);
    ASSERT_EQ(one.size(), 2u);
    for (const DomainChoice& c : one) EXPECT_GT(c.probes, 20);
    for (int threads : {2, 3}) {
        const std::vector<DomainChoice> other = choices(threads);
        ASSERT_EQ(other.size(), one.size());
        for (size_t d = 0; d < one.size(); ++d) {
            EXPECT_EQ(other[d].walked, one[d].walked) << threads << " threads, domain " << d;
            EXPECT_EQ(other[d].probes, one[d].probes);
            EXPECT_EQ(other[d].errors.photonVariance, one[d].errors.photonVariance);
            EXPECT_EQ(other[d].errors.photonBias2, one[d].errors.photonBias2);
            EXPECT_EQ(other[d].errors.walkVariance, one[d].errors.walkVariance);
        }
    }
}

}  // namespace
}  // namespace tetglow::test
