// Light seen through glass: photon mapping splits the chain light over the pixel, which keeps the
// image's expectation (volpath's) and cuts its noise.
#include <cmath>

#include <gtest/gtest.h>

#include "PhotonAgainstVolpath.h"
#include "TestScenes.h"
#include "scene/Camera.h"

namespace tetglow::test {
namespace {

TEST(Camera, FilmPositionInvertsGenerateRay) {
    for (const Handedness hand : {Handedness::Right, Handedness::Left}) {
        CameraDesc desc;
        desc.position = {0.3, -1, 2};
        desc.lookAt = {-0.2, 0.4, -1};
        desc.fov = 50;
        desc.width = 64;
        desc.height = 40;
        desc.handedness = hand;
        const Camera camera(desc);
        for (const glm::dvec2 film : {glm::dvec2(0, 0), glm::dvec2(63.25, 39.75), glm::dvec2(17.5, 3.125)}) {
            const glm::dvec2 back = camera.filmPosition(camera.generateRay(film.x, film.y).d);
            EXPECT_NEAR(back.x, film.x, 1e-9);
            EXPECT_NEAR(back.y, film.y, 1e-9);
        }
    }
}

// A clear glass ball with a small light behind it: the camera sees the light only through the
// glass, as specks where the ball's facets bend pixels' rays onto it. Nothing scatters, so photon
// mapping has no kernel bias here and its image is volpath's in expectation.
SceneDesc lightBehindGlass() {
    MediumDesc glass = sphereMedium(RGB(0), RGB(0));
    glass.boundaryMaterial = {MaterialType::Dielectric, RGB(0), 1.5};
    SceneDesc desc = sceneWith(glass, 24);
    LightDesc light = quadLight({-0.05, -0.05, -3}, {0.1, 0, 0}, {0, 0.1, 0}, RGB(2000));
    light.twoSided = true;
    desc.lights.push_back(light);
    return desc;
}

TEST(SpecularChains, SplittingKeepsTheMeanAndCutsTheNoise) {
    const Scene scene(lightBehindGlass());
    const PhotonAgainstVolpath c = photonAgainstVolpath(scene, 4096, 64, 2000);
    ASSERT_GT(c.reference, 0.05);  // the light shows through the glass
    EXPECT_NEAR(c.photonMean, c.reference, 4 * c.sigma);
    // Five rays a pixel for the chain light: about a fifth of the variance.
    EXPECT_LT(c.photonSpread, c.volpathSpread / 3);
}

// A small glowing medium behind the glass ball, brighter than anything else: the camera sees its
// emission only along specular chains, which is chain light too.
TEST(SpecularChains, AGlowingMediumBehindGlassIsSplitToo) {
    MediumDesc glass = sphereMedium(RGB(0), RGB(0));
    glass.boundaryMaterial = {MaterialType::Dielectric, RGB(0), 1.5};
    SceneDesc desc = sceneWith(glass, 24);
    MediumDesc glow = sphereMedium(RGB(1), RGB(0), 0, 1);
    glow.name = "glow";
    for (auto& p : glow.boundary.positions) p = glm::dvec3(glm::vec3(p * 0.06 + glm::dvec3(0, 0, -3)));
    glow.emission = RGB(3000);
    desc.media.push_back(glow);
    const Scene scene(std::move(desc));
    const PhotonAgainstVolpath c = photonAgainstVolpath(scene, 16384, 64, 2000);
    ASSERT_GT(c.reference, 0.05);
    EXPECT_NEAR(c.photonMean, c.reference, 4 * c.sigma);
    EXPECT_LT(c.photonSpread, c.volpathSpread / 4);
}

// The pixels that split the chain light and their rays depend on the pixel and the pass only.
TEST(SpecularChains, SameImageAtAnyThreadCount) {
    const Scene scene(lightBehindGlass());
    const Image one = renderImage(scene, IntegratorType::Photon, 6, 4, 2000, 1),
                two = renderImage(scene, IntegratorType::Photon, 6, 4, 2000, 2);
    ASSERT_GT(imageMean(one), 0);
    for (size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i], two.pixels[i]) << "pixel " << i;
}

}  // namespace
}  // namespace tetglow::test
