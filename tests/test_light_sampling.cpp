// Next-event estimation's samplers against closed forms: the spherical rectangle's solid angle
// and its density, a rectangle light's irradiance, the choice of a light by importance, and
// volpath's direct light on a floor under a rectangle light and the sky.
#include <cmath>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "sampling/Rng.h"
#include "sampling/Sampling.h"
#include "scene/LightSelection.h"
#include "scene/Scene.h"
#include "scene/SphericalRectangle.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// Solid angle and form factor of the rectangle [0, a] x [0, b] in the plane z = h, seen from
// the origin facing +z; both are odd in a and in b, so any rectangle in that plane is a sum
// of four of them with signs.
double cornerSolidAngle(double a, double b, double h) {
    return std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h)));
}
double cornerFormFactor(double a, double b, double h) {
    const double A = a / h, B = b / h, sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi);
}
template <class Corner>
double overRectangle(Corner&& f, double x0, double x1, double y0, double y1, double h) {
    return f(x1, y1, h) - f(x0, y1, h) - f(x1, y0, h) + f(x0, y0, h);
}

// Receivers below the rectangle [-0.5, 0.5] x [-0.3, 0.3] at height h: (x, y, h).
// The last is so far that the light samples by area.
const glm::dvec3 kReceivers[] = {{0, 0, 1},        {0.5, 0.3, 0.4},  {2, -1, 0.7}, {0.1, 0.05, 0.05},
                                 {0.2, 0.1, 1e-3}, {0.2, 0.1, 1e-8}, {30, 20, 1},  {100, 60, 1}};

TEST(SphericalRectangle, SolidAngleMatchesClosedForm) {
    for (const glm::dvec3& r : kReceivers) {
        // The rectangle lies at z = 0, the point at z = -h below it (and once above it).
        for (double side : {-1.0, 1.0}) {
            const glm::dvec3 o(r.x, r.y, side * r.z);
            const SphericalRectangle s(o, {-0.5, -0.3, 0}, {1, 0, 0}, {0, 0.6, 0});
            const double exact = overRectangle(cornerSolidAngle, -0.5 - r.x, 0.5 - r.x, -0.3 - r.y, 0.3 - r.y, r.z);
            EXPECT_NEAR(s.solidAngle(), exact, 1e-6 * exact) << o.x << " " << o.y << " " << o.z;
        }
    }
}

// Directions uniform in solid angle: on an 8x8 grid of cells of the rectangle, the counts
// follow each cell's own solid angle (chi-square, 63 degrees of freedom).
TEST(SphericalRectangle, SamplesAreUniformInSolidAngle) {
    const glm::dvec3 corner(-0.5, -0.3, 0), ex(1, 0, 0), ey(0, 0.6, 0);
    for (const glm::dvec3& o : {glm::dvec3(0, 0, -1), glm::dvec3(0.9, 0.6, 0.3), glm::dvec3(0.1, 0.05, -0.05)}) {
        const SphericalRectangle s(o, corner, ex, ey);
        const int n = 8, samples = 200000;
        std::vector<int> count(n * n, 0);
        Rng rng(11, 2);
        for (int i = 0; i < samples; ++i) {
            const double u0 = rng.uniform(), u1 = rng.uniform();
            const glm::dvec3 q = s.sample({u0, u1});
            EXPECT_NEAR(q.z, 0, 1e-12);
            const int a = std::min(n - 1, int((q.x + 0.5) * n)), b = std::min(n - 1, int((q.y + 0.3) / 0.6 * n));
            ASSERT_TRUE(a >= 0 && b >= 0) << q.x << " " << q.y;
            ++count[b * n + a];
        }
        double chi2 = 0;
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
                const SphericalRectangle cell(o, corner + ex * (double(a) / n) + ey * (double(b) / n), ex / double(n),
                                              ey / double(n));
                const double expected = samples * cell.solidAngle() / s.solidAngle();
                chi2 += (count[b * n + a] - expected) * (count[b * n + a] - expected) / expected;
            }
        EXPECT_LT(chi2, 63 + 5 * std::sqrt(2 * 63.0)) << o.x << " " << o.y << " " << o.z;
    }
}

// The rectangle light [-0.5, 0.5] x [-0.3, 0.3] at y = 1 facing down, of the tests below.
LightDesc rectangleAbove(const RGB& radiance) { return quadLight({-0.5, 1, -0.3}, {1, 0, 0}, {0, 0, 0.6}, radiance); }

// A rectangle light facing down at y = 1: the irradiance next-event estimation gives on a
// parallel receiver equals L pi F, sampled by solid angle, even 1e-8 below the light, or by
// area (far away, where the solid angle is a sliver); pdf() agrees with sample().
TEST(SphericalRectangle, RectangleLightIrradianceMatchesClosedForm) {
    const LightDesc desc = rectangleAbove({2, 1, 0.5});
    Bounds3 bounds;
    bounds.extend(glm::dvec3(-1));
    bounds.extend(glm::dvec3(1));
    const auto light = makeLight(desc, bounds);
    for (const glm::dvec3& r : kReceivers) {
        const glm::dvec3 p(r.x, 1 - r.z, r.y), up(0, 1, 0);
        Rng rng(4, 9);
        const int samples = 40000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < samples; ++i) {
            const double u0 = rng.uniform(), u1 = rng.uniform();
            const LightSample s = light->sample(p, {u0, u1});
            ASSERT_GT(s.pdf, 0);
            const glm::dvec3 q = p + s.wi * s.distance;
            EXPECT_NEAR(light->pdf(p, s.wi, q, 0), s.pdf, 1e-9 * s.pdf);
            const double e = s.L.x * glm::dot(s.wi, up) / s.pdf;
            sum += e;
            sum2 += e * e;
        }
        const double mean = sum / samples, se = std::sqrt(std::max(0.0, sum2 / samples - mean * mean) / samples);
        const double exact =
            desc.radiance.x * kPi * overRectangle(cornerFormFactor, -0.3 - r.y, 0.3 - r.y, -0.5 - r.x, 0.5 - r.x, r.z);
        EXPECT_NEAR(mean, exact, 4 * se + 1e-12) << r.x << " " << r.y << " " << r.z;
    }
}

// chooseLight picks each light as often as choicePmf says, never one that cannot reach the point,
// and with MIS never the constant environment (phase/BSDF rays find it).
TEST(LightSelection, ChoicesFollowTheirPmf) {
    Bounds3 bounds;
    bounds.extend(glm::dvec3(-1));
    bounds.extend(glm::dvec3(1));
    std::vector<std::unique_ptr<Light>> lights;
    LightDesc d;
    d.type = LightType::Point;
    d.position = {0, 2, 0};
    d.intensity = RGB(1);
    lights.push_back(makeLight(d, bounds));
    d.type = LightType::Spot;
    d.lookAt = {0, 5, 0};
    d.coneAngle = 20;
    d.coneDelta = 5;  // points away
    lights.push_back(makeLight(d, bounds));
    lights.push_back(makeLight(rectangleAbove(RGB(0.3)), bounds));
    d.type = LightType::Environment;
    d.radiance = RGB(0.02);
    lights.push_back(makeLight(d, bounds));
    const glm::dvec3 p(0.2, 0, 0.1);
    for (bool mis : {false, true}) {
        SCOPED_TRACE(mis ? "with MIS" : "without MIS");
        double total = 0;
        for (const auto& l : lights) total += choicePmf(lights, *l, p, mis);
        EXPECT_NEAR(total, 1, 1e-12);
        EXPECT_EQ(choicePmf(lights, *lights[1], p, mis), 0);
        EXPECT_EQ(choicePmf(lights, *lights[3], p, mis) == 0, mis);
        std::vector<int> count(lights.size(), 0);
        Rng rng(2, 3);
        const int samples = 100000;
        for (int i = 0; i < samples; ++i) {
            const LightChoice c = chooseLight(lights, p, mis, rng.uniform());
            ASSERT_NE(c.light, nullptr);
            for (size_t k = 0; k < lights.size(); ++k)
                if (c.light == lights[k].get()) {
                    ++count[k];
                    EXPECT_EQ(c.pmf, choicePmf(lights, *lights[k], p, mis));
                }
        }
        EXPECT_EQ(count[1], 0);
        for (size_t k : {0, 2, 3}) {
            const double pmf = choicePmf(lights, *lights[k], p, mis);
            EXPECT_NEAR(count[k], samples * pmf, 5 * std::sqrt(samples * pmf * (1 - pmf)) + 1e-9) << k;
        }
    }
}

// volpath with one surface event (max_depth 2): a diffuse floor under a rectangle light facing
// down, in a sky it hides, sends rho (Lq F + Lsky (1 - F)) at every point (F its form factor):
// light sampling, BSDF sampling and their MIS weights (light choice and solid-angle pdfs) agree.
TEST(LightSelection, VolpathDirectLightOnAFloorMatchesClosedForm) {
    SceneDesc desc;
    desc.camera.position = {0, 3, 3};
    desc.camera.lookAt = {0, 0, 0};
    const LightDesc rectangle = rectangleAbove({3, 2, 1});
    LightDesc sky;
    sky.type = LightType::Environment;
    sky.radiance = {0.2, 0.3, 0.4};
    desc.lights = {rectangle, sky};
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
            sum += L;
            sum2 += L * L;
        }
        const double F = overRectangle(cornerFormFactor, -0.5 - p.x, 0.5 - p.x, -0.3 - p.z, 0.3 - p.z, 1.0);
        for (int c = 0; c < 3; ++c) {
            const double mean = sum[c] / samples,
                         se = std::sqrt(std::max(0.0, sum2[c] / samples - mean * mean) / samples);
            const double exact = 0.5 * (rectangle.radiance[c] * F + sky.radiance[c] * (1 - F));
            EXPECT_NEAR(mean, exact, 4 * se) << p.x << " " << p.z << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace tetglow::test
