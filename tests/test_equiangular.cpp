// Single scattering near a small light: equiangular sampling along the ray (Kulla and Fajardo
// 2012), restricted to the cone a spot light lights, in photon mapping's direct light.
#include <cmath>

#include <gtest/gtest.h>

#include "PhotonAgainstVolpath.h"
#include "TestScenes.h"
#include "sampling/Equiangular.h"
#include "sampling/Rng.h"
#include "scene/Light.h"
#include "scene/Scene.h"

namespace tetglow::test {
namespace {

// The pdf integrates to 1 over the segment and sample() inverts its distribution function.
TEST(Equiangular, SamplesFollowTheirPdf) {
    const glm::dvec3 o(0.1, -0.2, 0.3), d = glm::normalize(glm::dvec3(1, 0.5, -0.25));
    for (const glm::dvec3 centre :
         {glm::dvec3(1, 1, 0), glm::dvec3(0.5, 0.2, 0.2), o + 0.7 * d + glm::dvec3(0, 1e-3, 0)}) {
        const double a = 0.2, b = 2.5;
        const Equiangular eq(o, d, centre, a, b);
        const int n = 200000;
        double integral = 0;
        std::vector<double> cdf(n + 1, 0);
        for (int i = 0; i < n; ++i) {
            const double h = (b - a) / n, t = a + (i + 0.5) * h;
            integral += eq.pdf(t) * h;
            cdf[i + 1] = integral;
        }
        EXPECT_NEAR(integral, 1, 1e-6) << "centre " << centre.x;
        for (double u : {0.05, 0.3, 0.5, 0.77, 0.99}) {
            const double t = eq.sample(u);
            EXPECT_NEAR(cdf[size_t((t - a) / (b - a) * n)], u, 2e-3) << "centre " << centre.x << " u " << u;
        }
        EXPECT_EQ(eq.pdf(a - 0.01), 0);
        EXPECT_EQ(eq.pdf(b + 0.01), 0);
    }
    // An empty segment through the centre: nothing to draw, and nothing that is not a number.
    const Equiangular empty(o, d, o + 0.5 * d, 0.5, 0.5);
    EXPECT_EQ(empty.sample(0.3), 0.5);
    EXPECT_EQ(empty.pdf(0.5), 0);
}

// The clipped interval holds exactly the points inside the cone, and a spot light with a radius
// lights no point outside its cone.
TEST(LightCone, ClipKeepsExactlyThePointsInsideTheCone) {
    const LightDesc spot = spotLight({0.2, 2, 0.1}, {0, 0, 0}, RGB(1), 20, 5, 0.3);
    const auto light = makeLight(spot, Bounds3{});
    const auto focus = light->focus();
    ASSERT_TRUE(focus && focus->cone);
    const LightCone& cone = *focus->cone;
    Rng rng(7, 1);
    int inside = 0, lit = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 o = glm::dvec3(rng.uniform(), rng.uniform(), rng.uniform()) * 6.0 - 3.0;
        const glm::dvec3 d = sampleUniformSphere({rng.uniform(), rng.uniform()});
        const Ray ray{o, d};
        const auto span = cone.clip(ray, 0, 6);
        for (int j = 0; j <= 60; ++j) {
            const double t = 0.1 * j;
            const glm::dvec3 p = ray.at(t);
            const bool in = span && t >= span->first - 1e-9 && t <= span->second + 1e-9;
            if (std::abs(glm::length(p - cone.apex) * cone.cosAngle - glm::dot(p - cone.apex, cone.axis)) > 1e-9)
                EXPECT_EQ(in, cone.contains(p)) << "ray " << i << " t " << t;
            inside += in;
            const LightSample s = light->sample(p, {rng.uniform(), rng.uniform()});
            if (s.pdf > 0 && !isBlack(s.L)) {
                ++lit;
                EXPECT_TRUE(cone.contains(p)) << "lit outside the cone: ray " << i << " t " << t;
            }
        }
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(lit, 500);
}

// A thin medium crossed by a narrow spot light's beam: eye rays cross the beam in a sliver of
// their length, where a distance drawn by transmittance rarely lands. Drawn in the cone towards
// the light, photon mapping's single scattering keeps volpath's mean with a fraction of its noise.
TEST(Equiangular, ANarrowSpotBeamKeepsItsMeanWithLessNoise) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.02), RGB(0.15)), 24);
    desc.lights.push_back(spotLight({0, 3, 0}, {0, 0, 0}, RGB(400), 5, 1));
    const Scene scene(std::move(desc));
    const PhotonAgainstVolpath c = photonAgainstVolpath(scene, 4096, 16, 4000);
    ASSERT_GT(c.reference, 0.01);
    // The photons' kernel adds a bias of its own; single scattering, most of the light, has none.
    EXPECT_NEAR(c.photonMean, c.reference, 4 * c.sigma + 0.02 * c.reference);
    // Drawn by transmittance alone, the photons' spread is volpath's (measured: 0.84 of it).
    EXPECT_LT(c.photonSpread, c.volpathSpread / 3);
}

}  // namespace
}  // namespace tetglow::test
