// Emitters against closed forms where the integrators once went wrong: a glowing medium that
// neither absorbs nor scatters (emission x chord), and several environment lights (their sum).
#include <cmath>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "tet/SurfaceBVH.h"

namespace tetglow::test {
namespace {

// The length of the camera ray inside the unit sphere, from Embree's hits on its boundary.
double chord(const Scene& scene, const Ray& ray) {
    const auto hits = scene.volumes()[0].volume->traversal().bvh().allHits(ray);
    double length = 0;
    for (size_t i = 0; i + 1 < hits.size(); i += 2) length += hits[i + 1].t - hits[i].t;
    return length;
}

// FORMAT.md: emission is radiance per unit length. Without extinction no flight collides, so
// volpath must collect it along the whole chord (it once rendered such a medium black).
TEST(Emitters, EmissionWithoutExtinctionIsEmissionTimesChord) {
    const RGB emission(0.2, 0.5, 1.5);
    MediumDesc m = sphereMedium(RGB(0), RGB(0));
    m.emission = emission;
    const SceneDesc desc = sceneWith(m, 16);
    const Scene scene(desc);
    for (IntegratorType type : {IntegratorType::VolPath, IntegratorType::Photon}) {  // single: a march, not exact
        IntegratorDesc integ;
        integ.type = type;
        integ.photons = 1000;
        const auto integrator = makeIntegrator(scene, integ);
        integrator->beginPass(0);
        int inside = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const Ray ray = scene.camera().generateRay(x + 0.5, y + 0.5);
                const double length = chord(scene, ray);
                inside += length > 0;
                Rng rng(3, uint64_t(y) * 16 + x);
                const RGB L = integrator->radiance(ray, rng);
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(L[c], emission[c] * length, 1e-9 + 1e-6 * emission[c] * length)
                        << "pixel " << x << "," << y << " channel " << c << " integrator " << int(type);
            }
        EXPECT_GT(inside, 16 * 16 / 4);
    }
}

// Two environment lights are one of their summed radiance: escaping rays see the sum (they once
// saw only the last), through an absorbing sphere exactly the sum times the transmittance.
TEST(Emitters, TwoEnvironmentLightsSeenAsTheirSum) {
    const RGB sigmaA(0.4, 1.1, 2.3);
    SceneDesc desc = sceneWith(sphereMedium(sigmaA, RGB(0)), 16);
    desc.lights.push_back(environment(0.1));
    desc.lights.push_back(environment(0.05));
    const Scene scene(desc);
    for (IntegratorType type : {IntegratorType::VolPath, IntegratorType::Single}) {
        IntegratorDesc integ;
        integ.type = type;
        const auto integrator = makeIntegrator(scene, integ);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const Ray ray = scene.camera().generateRay(x + 0.5, y + 0.5);
                Rng rng(5, uint64_t(y) * 16 + x);
                const RGB L = integrator->radiance(ray, rng);
                for (int c = 0; c < 3; ++c) {
                    const double expected = 0.15 * std::exp(-sigmaA[c] * chord(scene, ray));
                    ASSERT_NEAR(L[c], expected, 1e-4 * expected) << "pixel " << x << "," << y << " channel " << c;
                }
            }
    }
}

// ... and light sampling sees the same sum: a white furnace lit by two environments of 0.1 and
// 0.05 is 0.15 everywhere (escaping rays and next-event estimation must agree for that).
TEST(Emitters, TwoEnvironmentLightsFurnaceIsTheSum) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0), RGB(1, 2, 4), 0.5, 2), 6);
    desc.lights.push_back(environment(0.1));
    desc.lights.push_back(environment(0.05));
    const Scene scene(desc);
    IntegratorDesc integ;
    integ.maxDepth = 1 << 20;  // a furnace is only white without truncation
    const auto integrator = makeIntegrator(scene, integ);
    RGB sum(0), sum2(0);
    int n = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x)
            for (int i = 0; i < 200; ++i, ++n) {
                Rng rng(9, uint64_t(y) * 6 + x, uint64_t(i));
                const RGB L = integrator->radiance(scene.camera().generateRay(x + 0.5, y + 0.5), rng);
                sum += L;
                sum2 += L * L;
            }
    const RGB mean = sum / double(n);
    const RGB se = glm::sqrt(glm::max(RGB(0), sum2 / double(n) - mean * mean) / double(n - 1));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 0.15, 4 * se[c] + 1e-12) << "channel " << c;
}

}  // namespace
}  // namespace tetglow::test
