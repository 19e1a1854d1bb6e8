// Photon mapping: where the traced power goes, and the volume estimates against each other and
// against the volpath reference.
#include <chrono>
#include <cmath>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "photon/PhotonIntegrator.h"
#include "photon/PhotonTracer.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// Every kind of emitter and surface: a glowing, scattering sphere in a glass skin above a
// diffuse floor, lit by a point light, a spot disk and the environment.
SceneDesc closedWorld() {
    MediumDesc m = sphereMedium(RGB(0.3, 0.6, 0.1), RGB(1.5, 0.9, 2.5), 0.5, 2);
    m.emission = RGB(0.2, 0.4, 1.0);
    m.boundaryMaterial = {MaterialType::Dielectric, RGB(0), 1.4};
    SceneDesc s = sceneWith(m, 16);
    s.surfaces.push_back(
        {"floor", quad({-3, -1.2, -3}, {0, 0, 6}, {6, 0, 0}), {MaterialType::Diffuse, RGB(0.6, 0.5, 0.4)}});
    LightDesc point = pointLight({1.5, 2, 1}, RGB(4, 3, 2));
    s.lights.push_back(point);
    LightDesc spot = point;
    spot.type = LightType::Spot;
    spot.position = {-0.5, 3, 0};
    spot.lookAt = {0, 0, 0};
    spot.radius = 0.2;
    s.lights.push_back(spot);
    s.lights.push_back(environment(0.1));
    return s;
}

// Emitted power = absorbed + escaped, per channel, within three standard errors; nothing is
// cut when paths may be as long as they like.
TEST(Photon, EnergyBalance) {
    const Scene scene(closedWorld());
    const PhotonSource source(scene);
    const TracedPhotons traced = tracePhotons(scene, source, {200000, 1 << 20, 3, 0});
    const EnergyBalance& e = traced.energy;
    for (int c = 0; c < 3; ++c) {
        const double accounted = e.absorbedInMedia[c] + e.absorbedOnSurfaces[c] + e.escaped[c];
        std::printf("channel %d: emitted %.5f, absorbed in media %.5f, on surfaces %.5f, escaped %.5f, +- %.5f\n", c,
                    e.emitted[c], e.absorbedInMedia[c], e.absorbedOnSurfaces[c], e.escaped[c],
                    std::sqrt(e.deficitSquares[c]));
        EXPECT_NEAR(accounted, e.emitted[c], 3 * std::sqrt(e.deficitSquares[c]));
        EXPECT_EQ(e.cut[c], 0);
        EXPECT_GT(e.absorbedInMedia[c], 0.05 * e.emitted[c]);
        EXPECT_GT(e.absorbedOnSurfaces[c], 0.05 * e.emitted[c]);
        EXPECT_NEAR(e.emitted[c], source.totalPower()[c], 0.02 * source.totalPower()[c]);
    }
    EXPECT_GT(traced.volume[0].size(), 10000u);
    EXPECT_GT(traced.surface.size(), 1000u);  // caustics and light the sphere sends to the floor
}

// A path stores a photon at every event (from a glowing medium, its first too), up to max depth:
// in a dense sphere far more than one per path. The bound on what a pass stores counts them all and stops the pass
// before one more is stored.
TEST(Photon, StoredPhotonsAreBoundedNotOnePerPath) {
    MediumDesc glowing = sphereMedium(RGB(0), RGB(1000), 0, 2);
    glowing.emission = RGB(1);  // photons start inside and scatter until the event cap
    const Scene scene(sceneWith(glowing, 4));
    const PhotonSource source(scene);
    PhotonTracingOptions options{2000, 64, 3, 0};
    const TracedPhotons all = tracePhotons(scene, source, options);
    const uint64_t stored = all.volume[0].size() + all.surface.size();
    EXPECT_GT(stored, 30 * options.paths);
    options.maxStored = stored;
    EXPECT_EQ(tracePhotons(scene, source, options).volume[0].size(), all.volume[0].size());
    options.maxStored = stored - 1;
    try {
        tracePhotons(scene, source, options);
        ADD_FAILURE() << "stored more than maxStored";
    } catch (const InputError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "photon tracing: 2000 photon paths per pass store more than " + std::to_string(stored - 1) +
                " photons, more than this machine's memory holds: ask for fewer photons per pass or a lower max depth");
    }
}

// Under a time limit a pass traces the blocks of paths begun in time, at least the first, and
// scales their power to the paths it traced: the emitted power is the lights' still.
TEST(Photon, APassPastItsDeadlineTracesOneBlockAtFullPower) {
    const Scene scene(closedWorld());
    const PhotonSource source(scene);
    PhotonTracingOptions options{1000000, 64, 3, 0};
    options.deadline = std::chrono::steady_clock::now();
    const TracedPhotons traced = tracePhotons(scene, source, options);
    EXPECT_EQ(traced.paths, 1024u);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(traced.energy.emitted[c], source.totalPower()[c], 0.1 * source.totalPower()[c]);
    RGB stored(0);
    for (const Photon& p : traced.surface) stored += RGB(p.power);
    EXPECT_GT(average(stored), 0.01 * average(source.totalPower()));  // photons carry the scaled power
}

// A glowing, scattering sphere with an index-matched boundary: all scattered light comes from
// photons (emission is never sampled by next-event estimation), so the volume estimates carry
// the whole difference from volpath. Its mean free path, above a fifth of its diagonal, keeps
// photon mapping estimating it rather than walking it.
SceneDesc glowingSphere() {
    MediumDesc m = sphereMedium(RGB(0.1), RGB(1.2), 0.3);
    m.emission = RGB(0.5);
    return sceneWith(m, 32);
}

struct Measured {
    double mean = 0, rim = 0;
};

// The image mean and the mean over the rim: pixels whose ray passes the sphere's centre at
// 0.85 to 0.97 of its radius, where a k-NN ball pokes out of the surface.
Measured measure(const Scene& scene, const Image& image) {
    Measured m;
    int rim = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double v = average(RGB(image.at(x, y)));
            m.mean += v;
            const Ray ray = scene.camera().generateRay(x + 0.5, y + 0.5);
            const double miss = glm::length(ray.o - glm::dot(ray.o, ray.d) * ray.d);
            if (miss > 0.85 && miss < 0.97) {
                m.rim += v;
                ++rim;
            }
        }
    m.mean /= double(image.width) * image.height;
    m.rim /= rim;
    return m;
}

Image renderPhoton(const Scene& scene, PhotonEstimate estimate, bool boundaryCorrection, int passes) {
    IntegratorDesc integ;
    integ.type = IntegratorType::Photon;
    integ.estimate = estimate;
    integ.boundaryCorrection = boundaryCorrection;
    integ.photons = 20000;
    integ.k = 32;
    integ.stepSize = 0.05;
    auto integrator = makeIntegrator(scene, integ);
    RenderOptions options;
    options.spp = passes;
    return render(scene, *integrator, options).image;
}

TEST(Photon, EstimatesAgreeWithVolpathAndEachOther) {
    const Scene scene(glowingSphere());
    IntegratorDesc volpath;
    auto reference = makeIntegrator(scene, volpath);
    RenderOptions options;
    options.spp = 256;
    const Measured ref = measure(scene, render(scene, *reference, options).image);
    const Measured plain = measure(scene, renderPhoton(scene, PhotonEstimate::KnnMarch, false, 16));
    const Measured corrected = measure(scene, renderPhoton(scene, PhotonEstimate::KnnMarch, true, 16));
    const Measured beam = measure(scene, renderPhoton(scene, PhotonEstimate::Beam, true, 16));
    std::printf("image mean: volpath %.4f, knn-march %.4f, corrected %.4f, beam %.4f\n", ref.mean, plain.mean,
                corrected.mean, beam.mean);
    std::printf("rim mean:   volpath %.4f, knn-march %.4f, corrected %.4f, beam %.4f\n", ref.rim, plain.rim,
                corrected.rim, beam.rim);
    EXPECT_NEAR(beam.mean, ref.mean, 0.03 * ref.mean);
    EXPECT_NEAR(corrected.mean, ref.mean, 0.03 * ref.mean);
    EXPECT_NEAR(beam.mean, corrected.mean, 0.03 * ref.mean);
    // The plain k-NN estimate leaves a dark rim; dividing by the ball's inside part removes it
    // (what is left is the kernel's blur of the light's fall towards the surface).
    EXPECT_LT(plain.rim, ref.rim * 0.95);
    EXPECT_GT(corrected.rim, ref.rim * 0.98);
    EXPECT_LT(std::abs(corrected.rim - ref.rim), std::abs(plain.rim - ref.rim));
    // Beam discs scaled by the inside part of each photon's ball keep each photon's power in
    // the medium.
    EXPECT_NEAR(beam.rim, ref.rim, 0.03 * ref.rim);
}

// A camera ray through a glass ball (an absorbing medium in a dielectric skin) sees a large
// light behind it, and in the skin's reflection a brighter one behind the camera: each sample
// of the photon integrator's eye path follows both branches of its first two dielectric events,
// so it has the Fresnel-weighted sum of both lights, not one of them at random. Choosing, a
// sample was the light behind the camera at 20 times the other in 4% of the samples (the pixels
// that see a small light in glass carried most of an image's error); the mean is volpath's.
TEST(Photon, AnEyePathFollowsBothBranchesOfTheGlassItMeetsFirst) {
    MediumDesc glass = sphereMedium(RGB(0.2, 0.1, 0.05), RGB(0));
    glass.boundaryMaterial = {MaterialType::Dielectric, RGB(0), 1.5};
    SceneDesc desc = sceneWith(glass, 8);
    desc.lights.push_back(quadLight({-10, -10, -5}, {20, 0, 0}, {0, 20, 0}, RGB(1)));  // faces +z
    desc.lights.push_back(quadLight({-10, -10, 6}, {0, 20, 0}, {20, 0, 0}, RGB(20)));  // faces -z
    const Scene scene(desc);
    const Ray ray{scene.camera().position(), glm::normalize(-scene.camera().position())};
    IntegratorDesc integ;
    integ.type = IntegratorType::Photon;
    integ.photons = 1000;
    auto photon = makeIntegrator(scene, integ);
    photon->beginPass(0);
    const auto reference = makeIntegrator(scene, IntegratorDesc{});
    const int n = 20000;
    const Estimate split = estimateMean(n / 10, [&](int i) {
        Rng rng = Rng::pixelSample(5, 0, uint32_t(i));
        return photon->radiance(ray, rng);
    });
    const Estimate chosen = estimateMean(n, [&](int i) {
        Rng rng = Rng::pixelSample(6, 0, uint32_t(i));
        return reference->radiance(ray, rng);
    });
    ASSERT_GT(chosen.mean.x, 1);
    // Per sample, relative: 0.04 left (the third event still chooses), against 2.3 choosing.
    const double spread = std::sqrt(n / 10.0) * split.stdError.x / split.mean.x;
    EXPECT_LT(spread, 0.1) << "mean " << split.mean.x;
    EXPECT_NEAR(split.mean.x, chosen.mean.x, 5 * std::hypot(split.stdError.x, chosen.stdError.x))
        << "spread " << spread;
}

// Surface photons that came from a light by specular events alone are caustics, the only ones
// final gathering takes from photons: through a clear glass ball all of them are, through an
// index-matched scattering sphere none, through a glass skin with a glowing medium some.
TEST(Photon, CausticPhotonsCameFromALightBySpecularEventsOnly) {
    struct Case {
        const char* name;
        MaterialType boundary;
        RGB sigmaS, emission;
    };
    for (const Case& c : {Case{"clear glass", MaterialType::Dielectric, RGB(0), RGB(0)},
                          Case{"index-matched", MaterialType::Interface, RGB(1.5), RGB(0.3)},
                          Case{"glowing, in glass", MaterialType::Dielectric, RGB(1.5), RGB(0.3)}}) {
        SceneDesc desc = closedWorld();
        desc.media[0].sigmaA = RGB(0);
        desc.media[0].sigmaS = c.sigmaS;
        desc.media[0].emission = c.emission;
        desc.media[0].boundaryMaterial = {c.boundary, RGB(0), c.boundary == MaterialType::Dielectric ? 1.4 : 1.0};
        // A black floor: light it reflects (and the glass sends back) would not be a caustic.
        if (isBlack(c.sigmaS)) desc.surfaces[0].material.reflectance = RGB(0);
        const Scene scene(desc);
        const TracedPhotons traced = tracePhotons(scene, PhotonSource(scene), {50000, 1 << 20, 3, 0, true});
        ASSERT_GT(traced.surface.size(), 500u) << c.name;
        if (c.boundary == MaterialType::Interface) {
            EXPECT_EQ(traced.caustic.size(), 0u) << c.name;
        } else if (isBlack(c.sigmaS)) {
            EXPECT_EQ(traced.caustic.size(), traced.surface.size()) << c.name;
        } else {
            EXPECT_GT(traced.caustic.size(), 100u) << c.name;
            EXPECT_LT(traced.caustic.size(), traced.surface.size() * 9 / 10) << c.name;
        }
    }
}

// A floor lit only by what a scattering sphere sends it (the spot's cone holds the sphere, not
// the floor the camera sees): final gathering takes it by one more bounce into the sphere,
// where the medium's own estimate applies (it is thin enough not to be walked), and agrees with
// volpath.
TEST(Photon, FinalGatherTakesAFloorsIndirectLightWithoutBlur) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.05), RGB(1.2), 0.3), 48);
    desc.surfaces.push_back({"floor", quad({-6, -1.2, -6}, {0, 0, 12}, {12, 0, 0}), {MaterialType::Diffuse, RGB(0.8)}});
    LightDesc spot;
    spot.type = LightType::Spot;
    spot.position = {0, 3, 0};
    spot.lookAt = {0, 0, 0};
    spot.coneAngle = 15;
    spot.coneDelta = 2;
    spot.intensity = RGB(40);
    desc.lights = {spot};
    desc.camera.position = {1.8, 0, 0};
    desc.camera.lookAt = {1.8, -1.2, 0};
    desc.camera.up = {0, 0, 1};
    desc.camera.fov = 30;
    const Scene scene(desc);
    const auto mean = [&](const IntegratorDesc& integ, int spp) {
        auto integrator = makeIntegrator(scene, integ);
        RenderOptions options;
        options.spp = spp;
        const Image image = render(scene, *integrator, options).image;
        double sum = 0;
        for (const auto& p : image.pixels) sum += average(RGB(p));
        return sum / double(image.pixels.size());
    };
    IntegratorDesc volpath;
    volpath.seed = 3;
    const double reference = mean(volpath, 2048);
    IntegratorDesc photon;
    photon.type = IntegratorType::Photon;
    photon.photons = 10000;
    photon.seed = 4;
    photon.finalGather = true;
    // One gather ray a pass, noisy (30% a pixel at 64 passes): the mean of many pixels.
    const double gathered = mean(photon, 64);
    std::printf("floor mean: volpath %.5f, photon with final gather %.5f\n", reference, gathered);
    ASSERT_GT(reference, 1e-3);
    EXPECT_NEAR(gathered, reference, 0.03 * reference);
}

TEST(Photon, RadiusShrinksProgressively) {
    EXPECT_EQ(PhotonIntegrator::radiusScale(0, 0.7, 3), 1.0);
    // pass 1: r^3 scales by (1 + 0.7) / 2
    EXPECT_NEAR(std::pow(PhotonIntegrator::radiusScale(1, 0.7, 3), 3), 0.85, 1e-12);
    EXPECT_NEAR(std::pow(PhotonIntegrator::radiusScale(2, 0.5, 2), 2), 0.75 * (2.5 / 3), 1e-12);
    // The product of (i + alpha) / (i + 1) falls like n^(alpha - 1): slowly, but without end.
    const double r1000 = PhotonIntegrator::radiusScale(1000, 0.7, 2),
                 r2000 = PhotonIntegrator::radiusScale(2000, 0.7, 2);
    EXPECT_LT(r2000, r1000);
    EXPECT_NEAR(r2000 / r1000, std::pow(2.0, -0.3 / 2), 1e-3);
}

// The mean of N passes: its squared bias follows the mean of the passes' radius^2, its variance
// the mean of 1 / radius^d over N. With the default alpha both fall as N^-alpha; with the old
// 0.7 the discs' squared bias fell as N^-0.6, slower than their variance (N^-0.7).
TEST(Photon, DefaultAlphaBalancesBiasAndVariance) {
    EXPECT_EQ(IntegratorDesc{}.alpha, 0);  // 0: balancedAlpha for each kernel
    auto slopes = [](double alpha, int dim) {
        auto at = [&](int n) {
            double bias = 0, variance = 0;
            for (int i = 0; i < n; ++i) {
                const double r = PhotonIntegrator::radiusScale(uint64_t(i), alpha, dim);
                bias += r * r / n;
                variance += std::pow(r, -dim) / (double(n) * n);
            }
            return std::pair{bias * bias, variance};
        };
        const auto [b1, v1] = at(1000);
        const auto [b2, v2] = at(8000);
        return std::pair{std::log(b2 / b1) / std::log(8.0), std::log(v2 / v1) / std::log(8.0)};
    };
    for (int dim : {2, 3}) {
        const double alpha = PhotonIntegrator::balancedAlpha(dim);
        const auto [bias2, variance] = slopes(alpha, dim);
        EXPECT_NEAR(bias2, -alpha, 0.02) << "dimension " << dim;
        EXPECT_NEAR(variance, -alpha, 0.02) << "dimension " << dim;
    }
    const auto [bias2, variance] = slopes(0.7, 2);
    EXPECT_GT(bias2, variance + 0.08);
}

}  // namespace
}  // namespace tetglow::test
