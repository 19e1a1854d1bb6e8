// Next-event estimation against closed forms: the choice of a light by importance, and
// volpath's direct light on a floor under a rectangle light and the sky.
#include <cmath>

#include <gtest/gtest.h>

#include "photon/Rng.h"
#include "photon/Sampling.h"
#include "render/Integrator.h"
#include "render/LightSelection.h"
#include "render/Scene.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// The form factor of the rectangle [0, a] x [0, b] in the plane z = h, seen from the origin
// facing +z; it is odd in a and in b, so any rectangle in that plane is a sum of four with signs.
double cornerFormFactor(double a, double b, double h) {
    const double A = a / h, B = b / h, sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi);
}
template <class Corner>
double overRectangle(Corner&& f, double x0, double x1, double y0, double y1, double h) {
    return f(x1, y1, h) - f(x0, y1, h) - f(x1, y0, h) + f(x0, y0, h);
}

// chooseLight picks each light as often as choicePmf says, never one that cannot reach the point.
TEST(LightSelection, ChoicesFollowTheirPmf) {
    Bounds3 bounds;
    bounds.extend(glm::dvec3(-1)), bounds.extend(glm::dvec3(1));
    std::vector<std::unique_ptr<Light>> lights;
    LightDesc d;
    d.type = LightType::Point, d.position = {0, 2, 0}, d.intensity = RGB(1);
    lights.push_back(makeLight(d, bounds));
    d.type = LightType::Spot, d.lookAt = {0, 5, 0}, d.coneAngle = 20, d.coneDelta = 5;  // points away
    lights.push_back(makeLight(d, bounds));
    d.type = LightType::Quad, d.corner = {-0.5, 1, -0.3}, d.edge0 = {1, 0, 0}, d.edge1 = {0, 0, 0.6}, d.radiance = RGB(0.3);
    lights.push_back(makeLight(d, bounds));
    d.type = LightType::Environment, d.radiance = RGB(0.02);
    lights.push_back(makeLight(d, bounds));
    const glm::dvec3 p(0.2, 0, 0.1);
    double total = 0;
    for (const auto& l : lights) total += choicePmf(lights, *l, p);
    EXPECT_NEAR(total, 1, 1e-12);
    EXPECT_EQ(choicePmf(lights, *lights[1], p), 0);
    std::vector<int> count(lights.size(), 0);
    Rng rng(2, 3);
    const int samples = 100000;
    for (int i = 0; i < samples; ++i) {
        const LightChoice c = chooseLight(lights, p, rng.uniform());
        ASSERT_NE(c.light, nullptr);
        for (size_t k = 0; k < lights.size(); ++k)
            if (c.light == lights[k].get()) {
                ++count[k];
                EXPECT_EQ(c.pmf, choicePmf(lights, *lights[k], p));
            }
    }
    EXPECT_EQ(count[1], 0);
    for (size_t k : {0, 2, 3}) {
        const double pmf = choicePmf(lights, *lights[k], p);
        EXPECT_NEAR(count[k], samples * pmf, 5 * std::sqrt(samples * pmf * (1 - pmf))) << k;
    }
}

// volpath with one surface event (max_depth 2): a diffuse floor under a rectangle light facing
// down, in a sky it hides, sends rho (Lq F + Lsky (1 - F)) at every point (F its form factor):
// light sampling, BSDF sampling and their MIS weights (light choice and solid-angle pdfs) agree.
TEST(LightSelection, VolpathDirectLightOnAFloorMatchesClosedForm) {
    SceneDesc desc;
    desc.camera.position = {0, 3, 3}, desc.camera.lookAt = {0, 0, 0};
    LightDesc quadLight;
    quadLight.type = LightType::Quad, quadLight.corner = {-0.5, 1, -0.3}, quadLight.edge0 = {1, 0, 0}, quadLight.edge1 = {0, 0, 0.6};
    quadLight.radiance = {3, 2, 1};
    LightDesc sky;
    sky.type = LightType::Environment, sky.radiance = {0.2, 0.3, 0.4};
    desc.lights = {quadLight, sky};
    SurfaceDesc floor;
    floor.name = "floor";
    floor.mesh = quad({-20, 0, -20}, {0, 0, 40}, {40, 0, 0});
    floor.material.reflectance = RGB(0.5);
    desc.surfaces.push_back(floor);
    const Scene scene(desc);
    IntegratorDesc integ;
    integ.maxDepth = 2;
    const auto integrator = makeIntegrator(scene, integ);
    integrator->beginPass(0);
    for (const glm::dvec3& p : {glm::dvec3(0, 0, 0), glm::dvec3(0.4, 0, 0.2), glm::dvec3(-1.5, 0, 0.8)}) {
        const Ray ray{desc.camera.position, glm::normalize(p - desc.camera.position)};
        const int samples = 40000;
        RGB sum(0), sum2(0);
        for (int i = 0; i < samples; ++i) {
            Rng rng(6, 1, uint64_t(i));
            const RGB L = integrator->radiance(ray, rng);
            sum += L, sum2 += L * L;
        }
        const double F = overRectangle(cornerFormFactor, -0.5 - p.x, 0.5 - p.x, -0.3 - p.z, 0.3 - p.z, 1.0);
        for (int c = 0; c < 3; ++c) {
            const double mean = sum[c] / samples, se = std::sqrt(std::max(0.0, sum2[c] / samples - mean * mean) / samples);
            const double exact = 0.5 * (quadLight.radiance[c] * F + sky.radiance[c] * (1 - F));
            EXPECT_NEAR(mean, exact, 4 * se) << p.x << " " << p.z << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace tetglow::test
