// Re-tuning a built scene (the preview's path: new coefficients, lights and camera on the same tets)
// must render exactly what a scene built afresh from the new description renders; and the
// loader's pieces the preview reuses read and reject as inside a scene file.
#include <cstring>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "scene/SceneLoader.h"
#include "scene/SceneWriter.h"

namespace tetglow::test {
namespace {

Image renderPasses(const Scene& scene, const IntegratorDesc& integ, int passes) {
    const auto integrator = makeIntegrator(scene, integ);
    RenderOptions options;
    options.spp = passes;
    options.seed = integ.seed;
    return render(scene, *integrator, options).image;
}

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

// Both kinds of pass a retuned scene must reproduce: volpath's, and photon mapping's (whose
// photons come from the lights and media as retuned).
std::vector<IntegratorDesc> integrators() {
    std::vector<IntegratorDesc> all(2);
    all[0].type = IntegratorType::VolPath;
    all[1].type = IntegratorType::Photon;
    for (IntegratorDesc& integ : all) {
        integ.photons = 5000;
        integ.seed = 7;
    }
    return all;
}

TEST(Retune, SameImageAsAFreshScene) {
    MediumDesc m = sphereMedium(RGB(0.2, 0.5, 0.1), RGB(0.8, 0.6, 1.2), 0.5);
    m.emission = RGB(0.1, 0.2, 0.9);
    SceneDesc before = sceneWith(m, 24);
    before.lights.push_back(environment(0.3));
    SceneDesc after = before;
    after.media[0].sigmaS = RGB(2, 1, 0.5);
    after.media[0].g = -0.3;
    after.media[0].emission = RGB(0.5, 0, 0);
    after.media[0].density.type = DensityDesc::Type::Noise;  // per-vertex density on the old tets
    after.camera.width = 16;
    after.camera.height = 12;
    for (const IntegratorDesc& integ : integrators()) {
        SCOPED_TRACE(std::string(nameOf(kIntegratorNames, integ.type)));
        Scene retuned(before);
        renderPasses(retuned, integ, 1);
        retuned.retuneMedia(after.media);
        retuned.setCamera(after.camera);
        const Image image = renderPasses(retuned, integ, 2);
        EXPECT_TRUE(sameBits(image, renderPasses(Scene(after), integ, 2)));
        // The old coefficients at the new size render otherwise: the comparison can fail.
        SceneDesc cameraOnly = before;
        cameraOnly.camera = after.camera;
        EXPECT_FALSE(sameBits(image, renderPasses(Scene(cameraOnly), integ, 2)));
        EXPECT_EQ(retuned.desc().media[0].g, -0.3);
    }
}

// A camera moved away from the origin (the preview's orbit and zoom) sets a larger ray epsilon
// in a scene built with it: the moved scene takes it too, and renders the same.
TEST(Retune, AMovedCameraRendersAsInAFreshScene) {
    const SceneDesc before = glowingSphereUnderQuad(16);
    SceneDesc after = before;
    after.camera.position = 3.0 * before.camera.position + glm::dvec3(0.5, 1, 0);
    Scene moved(before);
    ASSERT_NE(moved.rayEpsilon(), Scene(after).rayEpsilon()) << "the move must change the epsilon to test it";
    moved.setCamera(after.camera);
    EXPECT_EQ(moved.rayEpsilon(), Scene(after).rayEpsilon());
    for (const IntegratorDesc& integ : integrators()) {
        SCOPED_TRACE(std::string(nameOf(kIntegratorNames, integ.type)));
        EXPECT_TRUE(sameBits(renderPasses(moved, integ, 2), renderPasses(Scene(after), integ, 2)));
    }
}

// New light emission on a built scene (the preview's light controls): an area light, a point
// light and the sky retuned, one turned off, render what a scene built with them renders.
TEST(Retune, LightsRenderAsInAFreshScene) {
    SceneDesc before = glowingSphereUnderQuad(16);
    LightDesc point = pointLight({2, 2, 2}, RGB(4, 2, 1));
    before.lights.push_back(point);
    SceneDesc after = before;
    after.lights[0].radiance = RGB(0.1, 0.2, 0.6);  // the environment
    after.lights[1].on = false;                     // the quad
    after.lights[2].intensity = RGB(1, 5, 9);
    for (const IntegratorDesc& integ : integrators()) {
        SCOPED_TRACE(std::string(nameOf(kIntegratorNames, integ.type)));
        Scene retuned(before);
        renderPasses(retuned, integ, 1);
        retuned.retuneLights(after.lights);
        const Image image = renderPasses(retuned, integ, 2);
        EXPECT_TRUE(sameBits(image, renderPasses(Scene(after), integ, 2)));
        // An off light is a light of no emission, where it was.
        SceneDesc dark = after;
        dark.lights[1].on = true;
        dark.lights[1].radiance = RGB(0);
        EXPECT_TRUE(sameBits(image, renderPasses(Scene(dark), integ, 2)));
        EXPECT_FALSE(sameBits(image, renderPasses(Scene(before), integ, 2))) << "the lights changed nothing";
        EXPECT_FALSE(retuned.desc().lights[1].on);
        EXPECT_EQ(retuned.desc().lights[1].radiance, RGB(5)) << "the off light's values were lost";
    }
    Scene scene(before);
    EXPECT_THROW(scene.retuneLights({}), std::invalid_argument);
    after.lights[2].type = LightType::Spot;
    EXPECT_THROW(scene.retuneLights(after.lights), std::invalid_argument);
}

TEST(Retune, RefusesOtherTets) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.1), RGB(1)), 8);
    Scene scene(desc);
    desc.media[0].boundary.positions[0].x += 0.01;
    EXPECT_THROW(scene.retuneMedia(desc.media), std::invalid_argument);
    EXPECT_THROW(scene.retuneMedia({}), std::invalid_argument);
}

// What the writer gives for the coefficients, the reader takes back as the same values;
// "scale" multiplies sigma_a and sigma_s; a bad value is the loader's one-line error.
TEST(Retune, CoefficientsRoundTripThroughTheLoadersChecks) {
    MediumDesc m = sphereMedium(RGB(0.25, 0.5, 1), RGB(3, 2, 1), 0.4);
    m.emission = RGB(0, 0.1, 0.2);
    nlohmann::json j = nlohmann::json::parse(mediumCoefficientsJson(m).dump());
    j["scale"] = 2;
    MediumDesc read;
    JsonValue(&j, nlohmann::json::json_pointer(), "request").readObject([&](JsonObject& o) {
        readMediumCoefficients(o, read);
        return 0;
    });
    EXPECT_EQ(read.sigmaA, 2.0 * m.sigmaA);
    EXPECT_EQ(read.sigmaS, 2.0 * m.sigmaS);
    EXPECT_EQ(read.g, m.g);
    EXPECT_EQ(read.emission, m.emission);
    j["g"] = 1.5;
    try {
        JsonValue(&j, nlohmann::json::json_pointer(), "request").readObject([&](JsonObject& o) {
            readMediumCoefficients(o, read);
            return 0;
        });
        FAIL() << "g = 1.5 was accepted";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "request: /g: expected a number in (-1, 1), got 1.5");
    }
    IntegratorDesc integ;
    integ.photons = 1234;
    integ.k = 5;
    integ.maxDepth = 9;
    const nlohmann::json ij = nlohmann::json::parse(integratorJson(integ).dump());
    const IntegratorDesc back = JsonValue(&ij, nlohmann::json::json_pointer(), "request").readObject(readIntegrator);
    EXPECT_EQ(back.photons, 1234u);
    EXPECT_EQ(back.k, 5);
    EXPECT_EQ(back.maxDepth, 9);
}

}  // namespace
}  // namespace tetglow::test
