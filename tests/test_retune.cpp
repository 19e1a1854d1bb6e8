// Re-tuning a built scene (the preview's path: new coefficients and camera on the same tets)
// must render exactly what a scene built afresh from the new description renders; and the
// loader's pieces the preview reuses read and reject as inside a scene file.
#include <cstring>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "integrators/Renderer.h"
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
    for (const IntegratorType type : {IntegratorType::VolPath, IntegratorType::Photon}) {
        SCOPED_TRACE(type == IntegratorType::VolPath ? "volpath" : "photon");
        IntegratorDesc integ;
        integ.type = type;
        integ.photons = 5000;
        integ.seed = 7;
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
    JsonValue(&j, nlohmann::json::json_pointer(), "request").readObject([&](JsonObject& o) { readMediumCoefficients(o, read); return 0; });
    EXPECT_EQ(read.sigmaA, 2.0 * m.sigmaA);
    EXPECT_EQ(read.sigmaS, 2.0 * m.sigmaS);
    EXPECT_EQ(read.g, m.g);
    EXPECT_EQ(read.emission, m.emission);
    j["g"] = 1.5;
    try {
        JsonValue(&j, nlohmann::json::json_pointer(), "request").readObject([&](JsonObject& o) { readMediumCoefficients(o, read); return 0; });
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
