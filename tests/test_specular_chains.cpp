// Light seen through glass: photon mapping splits the chain light over the pixel, which keeps the
// image's expectation (volpath's) and cuts its noise.
#include <cmath>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"

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

Image renderWith(const Scene& scene, IntegratorType type, uint64_t seed, int spp, int threads = 0) {
    IntegratorDesc integ;
    integ.type = type;
    integ.photons = 2000;
    integ.seed = seed;
    auto integrator = makeIntegrator(scene, integ);
    RenderOptions options;
    options.spp = spp;
    options.seed = seed;
    options.threads = threads;
    return render(scene, *integrator, options).image;
}

double mean(const Image& image) {
    double sum = 0;
    for (const auto& p : image.pixels) sum += average(RGB(p));
    return sum / double(image.pixels.size());
}

// The mean squared difference of two independent renders: twice the per-pixel variance.
double spread(const Image& a, const Image& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const double d = average(RGB(a.pixels[i])) - average(RGB(b.pixels[i]));
        sum += d * d;
    }
    return sum / double(a.pixels.size());
}

TEST(SpecularChains, SplittingKeepsTheMeanAndCutsTheNoise) {
    const Scene scene(lightBehindGlass());
    const double reference = mean(renderWith(scene, IntegratorType::VolPath, 1, 4096));
    ASSERT_GT(reference, 0.05);  // the light shows through the glass
    const Image photonA = renderWith(scene, IntegratorType::Photon, 2, 64),
                photonB = renderWith(scene, IntegratorType::Photon, 3, 64);
    const Image volpathA = renderWith(scene, IntegratorType::VolPath, 4, 64),
                volpathB = renderWith(scene, IntegratorType::VolPath, 5, 64);
    const double photonMean = 0.5 * (mean(photonA) + mean(photonB));
    const double photonSpread = spread(photonA, photonB), volpathSpread = spread(volpathA, volpathB);
    std::printf("image mean: volpath %.4f, photon %.4f; spread of two renders: volpath %.4g, photon %.4g\n", reference,
                photonMean, volpathSpread, photonSpread);
    // Within four standard errors of the two means (the spreads give the per-pixel variances;
    // the reference's is volpath's at 4096 samples).
    const double pixels = double(photonA.pixels.size());
    const double sigma = std::sqrt(photonSpread / 4 / pixels + volpathSpread / 2 * 64 / 4096 / pixels);
    EXPECT_NEAR(photonMean, reference, 4 * sigma);
    // Five rays a pixel for the chain light: about a fifth of the variance.
    EXPECT_LT(photonSpread, volpathSpread / 3);
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
    const double reference = mean(renderWith(scene, IntegratorType::VolPath, 1, 16384));
    ASSERT_GT(reference, 0.05);
    const Image photonA = renderWith(scene, IntegratorType::Photon, 2, 64),
                photonB = renderWith(scene, IntegratorType::Photon, 3, 64);
    const Image volpathA = renderWith(scene, IntegratorType::VolPath, 4, 64),
                volpathB = renderWith(scene, IntegratorType::VolPath, 5, 64);
    const double photonMean = 0.5 * (mean(photonA) + mean(photonB));
    const double photonSpread = spread(photonA, photonB), volpathSpread = spread(volpathA, volpathB);
    std::printf("image mean: volpath %.4f, photon %.4f; spread of two renders: volpath %.4g, photon %.4g\n", reference,
                photonMean, volpathSpread, photonSpread);
    const double pixels = double(photonA.pixels.size());
    const double sigma = std::sqrt(photonSpread / 4 / pixels + volpathSpread / 2 * 64 / 16384 / pixels);
    EXPECT_NEAR(photonMean, reference, 4 * sigma);
    EXPECT_LT(photonSpread, volpathSpread / 4);
}

// The pixels that split the chain light and their rays depend on the pixel and the pass only.
TEST(SpecularChains, SameImageAtAnyThreadCount) {
    const Scene scene(lightBehindGlass());
    const Image one = renderWith(scene, IntegratorType::Photon, 6, 4, 1),
                two = renderWith(scene, IntegratorType::Photon, 6, 4, 2);
    ASSERT_GT(mean(one), 0);
    for (size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i], two.pixels[i]) << "pixel " << i;
}

}  // namespace
}  // namespace tetglow::test
