// Photon emission against next-event estimation: for every kind of light, the irradiance that
// photons deposit on a small receiver equals the irradiance sample() predicts there, and the
// mean photon flux equals power().
#include <cmath>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "sampling/Rng.h"
#include "sampling/Sampling.h"
#include "scene/Light.h"

namespace tetglow::test {
namespace {

struct Case {
    const char* name;
    LightDesc desc;
};

std::vector<Case> lights() {
    std::vector<Case> cases;
    LightDesc point;
    point.type = LightType::Point;
    point.position = {0.2, 2, 0.1};
    point.intensity = {1, 2, 3};
    cases.push_back({"point", point});
    LightDesc spot = point;
    spot.type = LightType::Spot;
    spot.lookAt = {0, 0, 0};
    spot.coneAngle = 20;
    spot.coneDelta = 15;
    cases.push_back({"spot", spot});
    LightDesc diskSpot = spot;
    diskSpot.radius = 0.3;
    cases.push_back({"spot with a radius", diskSpot});
    LightDesc quad = quadLight({-0.5, 1.5, -0.5}, {1, 0, 0}, {0, 0.2, 1}, {2, 1, 0.5});
    cases.push_back({"quad (front side down)", quad});
    quad.twoSided = true;
    cases.push_back({"two-sided quad", quad});
    LightDesc distant;
    distant.type = LightType::Distant;
    distant.direction = {0.3, -1, 0.2};
    distant.irradiance = {1, 0.5, 2};
    cases.push_back({"distant", distant});
    LightDesc environment;
    environment.type = LightType::Environment;
    environment.radiance = {0.5, 1, 0.25};
    cases.push_back({"environment", environment});
    return cases;
}

TEST(Light, PhotonsDepositTheIrradianceThatSampleGives) {
    Bounds3 scene;
    scene.extend(glm::dvec3(-1));
    scene.extend(glm::dvec3(1));
    // A small disk at the origin facing up: photons crossing it, against sample() from its centre.
    const glm::dvec3 centre(0), normal(0, 1, 0);
    const double rho = 0.1;
    for (const Case& c : lights()) {
        SCOPED_TRACE(c.name);
        const auto light = makeLight(c.desc, scene);
        Rng rng(5, 1, 0);
        RGB nee(0);
        const int samples = 200000;
        for (int i = 0; i < samples; ++i) {
            const double u0 = rng.uniform(), u1 = rng.uniform();
            const LightSample s = light->sample(centre, {u0, u1});
            if (s.pdf > 0) nee += s.L * (std::max(0.0, glm::dot(s.wi, normal)) / s.pdf);
        }
        nee /= samples;

        const int photons = 4000000;
        RGB deposited(0), emitted(0), emitted2(0);
        for (int i = 0; i < photons; ++i) {
            const double a = rng.uniform(), b = rng.uniform(), u = rng.uniform(), v = rng.uniform();
            const PhotonEmission e = light->emitPhoton({a, b}, {u, v});
            emitted += e.flux;
            emitted2 += e.flux * e.flux;
            const double cosine = -glm::dot(e.ray.d, normal);
            if (cosine <= 0) continue;
            const double t = glm::dot(centre - e.ray.o, normal) / glm::dot(e.ray.d, normal);
            const glm::dvec3 q = e.ray.at(t) - centre;
            if (t > 0 && glm::dot(q, q) < rho * rho) deposited += e.flux;
        }
        deposited /= photons * kPi * rho * rho;
        emitted /= photons;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GT(nee[k], 0);
            EXPECT_NEAR(deposited[k], nee[k], 0.04 * nee[k]);
            const double se = std::sqrt(std::max(0.0, emitted2[k] / photons - emitted[k] * emitted[k]) / photons);
            EXPECT_NEAR(emitted[k], light->power()[k], 4 * se + 1e-9 * light->power()[k]);
        }
    }
}

}  // namespace
}  // namespace tetglow::test
