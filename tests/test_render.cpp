// The renderer against closed forms: absorption along exact chords, the white furnace, the
// ray march's boundary modes, determinism across thread counts.
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "integrators/PathStep.h"
#include "integrators/VolPathIntegrator.h"
#include "media/FreeFlight.h"
#include "photon/ColumnProfile.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "sampling/Sampling.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

// An index-matched surface (material "interface") is invisible to every ray: camera rays cross
// it, and so must shadow rays (transmittance, PathStep.h) and the single-scatter march's rays
// (Scene::intersectOpaque); a diffuse one in the same place blocks them.
TEST(Render, IndexMatchedSurfacesPassEveryRay) {
    const RGB sigmaA(0.4, 1.1, 2.3);
    for (MaterialType type : {MaterialType::Interface, MaterialType::Diffuse}) {
        SceneDesc desc = sceneWith(sphereMedium(sigmaA, RGB(0)), 8);
        SurfaceDesc wall;
        wall.name = "wall";
        wall.mesh = quad({-3, -3, 2}, {6, 0, 0}, {0, 6, 0});  // between the camera and the sphere
        wall.material.type = type;
        desc.surfaces.push_back(wall);
        const Scene scene(desc);
        const Ray ray{{0, 0, 4}, {0, 0, -1}};
        const bool passes = type == MaterialType::Interface;
        // Through the wall and the whole unit sphere: a chord of 2.
        const RGB tr = transmittance(scene, ray, 10, scene.volumeAt(ray.o));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr[c], passes ? std::exp(-2 * sigmaA[c]) : 0, 1e-9) << int(type);
        const auto opaque = scene.intersectOpaque(ray);
        EXPECT_EQ(opaque.has_value(), !passes) << int(type);
        if (opaque) {
            EXPECT_NEAR(opaque->t, 2, 1e-6);
        }
    }
}

// A surface inside a medium is met by the paths and shadow rays inside it; Scene skips Embree
// inside a volume only when no surface reaches into the volume's bounding box.
TEST(Render, SurfacesInsideAMediumBlockShadowRaysFromInside) {
    const RGB sigmaA(0.4, 1.1, 2.3);
    SceneDesc desc = sceneWith(sphereMedium(sigmaA, RGB(0)), 8);
    SurfaceDesc wall;
    wall.name = "wall";
    wall.mesh = quad({-0.3, -0.3, 0.2}, {0.6, 0, 0}, {0, 0.6, 0});  // inside the unit sphere
    desc.surfaces.push_back(wall);
    const Scene scene(desc);
    const Ray ray{{0, 0, -0.5}, {0, 0, 1}};
    const VolumeState inside = scene.volumeAt(ray.o);
    ASSERT_TRUE(inside.inside());
    const auto hit = scene.intersect(ray, inside);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 0.7, 1e-6);
    EXPECT_EQ(transmittance(scene, ray, 10, inside), RGB(0));
    // Beside the wall the ray leaves the sphere: the chord from (0.5, 0, -0.5) to the surface.
    const Ray beside{{0.5, 0, -0.5}, {0, 0, 1}};
    const RGB tr = transmittance(scene, beside, 10, scene.volumeAt(beside.o));
    const double chord = 0.5 + std::sqrt(1 - 0.25);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr[c], std::exp(-chord * sigmaA[c]), 1e-3) << c;  // the sphere's facets
}

// Shadow rays with Russian roulette (shadowFlight) have the exact transmittance as
// their mean: 0 or exp(-depth) times 4 per survival. A channel that keeps the transmittance
// above 1/20 leaves no room for roulette: then every estimate is exact.
TEST(Render, ShadowRayRouletteKeepsTheTransmittance) {
    // Chords of 2: depths 3.4 to 4 (below 1/20 once, not below 1/80), or one channel at 1.
    for (const RGB sigmaA : {RGB(1.7, 1.8, 2.0), RGB(1.7, 1.8, 0.5)}) {
        const Scene scene(sceneWith(sphereMedium(sigmaA, RGB(0), 0, 4), 8));
        const Ray ray{{0, 0, -3}, {0, 0, 1}};
        const VolumeState outside = scene.volumeAt(ray.o);
        const RGB exact = transmittance(scene, ray, 10, outside);
        const int n = 40000;
        const Estimate e = estimateMean(n, [&](int i) {
            Rng rng(3, uint64_t(i));
            return transmittance(scene, ray, 10, outside, &rng);
        });
        if (sigmaA.z < 1) {
            EXPECT_EQ(e.black, 0);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], exact[c], 1e-12 * exact[c]);
            continue;
        }
        EXPECT_NEAR(double(e.black) / n, 0.75, 0.02);  // one roulette
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], exact[c], 5 * e.stdError[c]) << c;
    }
}

// The photon integrator draws its single-scattering distance from the eye stretch's column
// profile (ColumnProfile::atDepth) instead of walking the tets again: the same point and tet as
// a free flight (sampleFlight) with that optical depth as its target, also where the
// density varies linearly inside each tet.
TEST(Render, ColumnProfileEventsAreFreeFlights) {
    MediumDesc m = sphereMedium(RGB(0.2, 0.5, 1.0), RGB(1, 2, 3));
    m.density.type = DensityDesc::Type::Noise;
    m.density.offset = 1;
    m.density.amplitude = 0.9;
    m.density.frequency = 3;
    m.tetOptions.maxVolume = 0.01;
    const Scene scene(sceneWith(m, 8));
    const Volume& volume = *scene.volumes()[0].volume;
    ASSERT_FALSE(volume.homogeneous());
    const VolumeState centre = scene.volumeAt({0.05, -0.02, 0.03});
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(0, 1);
    int events = 0;
    for (int i = 0; i < 500; ++i) {
        const double z = 2 * u(random) - 1, phi = 2 * M_PI * u(random), s = std::sqrt(1 - z * z);
        const Ray ray{{0.05, -0.02, 0.03}, {s * std::cos(phi), s * std::sin(phi), z}};
        const ColumnProfile column(volume, ray, centre.start, INFINITY);
        const int c = i % 3;
        const double x = u(random) * 1.2;  // past the stretch's optical depth at times
        const double depth = x * column.depth()[c];
        const FreeFlight flight = sampleFlight(volume, ray, centre.start, INFINITY, c, -std::expm1(-depth));
        const auto event = column.atDepth(c, depth);
        ASSERT_EQ(event.has_value(), flight.scattered) << i;
        if (!event) continue;
        ++events;
        EXPECT_NEAR(event->t, flight.t, 1e-9) << i;
        EXPECT_EQ(event->tet, flight.tet) << i;
    }
    EXPECT_GT(events, 350);
}

// (a) A purely absorbing sphere in front of a white environment: every pixel is exactly the
// transmittance along its chord, the chord taken from Embree's hits on the boundary.
TEST(Render, AbsorbingSphereMatchesChords) {
    const RGB sigmaA(0.4, 1.1, 2.3);
    SceneDesc desc = sceneWith(sphereMedium(sigmaA, RGB(0)), 48);
    desc.lights.push_back(environment(1));
    const Scene scene(desc);
    const SurfaceBVH& bvh = scene.volumes()[0].volume->traversal().bvh();
    for (IntegratorType type : {IntegratorType::VolPath, IntegratorType::Single}) {
        IntegratorDesc integ;
        integ.type = type;
        const auto integrator = makeIntegrator(scene, integ);
        int chords = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                const Ray ray = scene.camera().generateRay(x + 0.5, y + 0.5);
                const auto hits = bvh.allHits(ray);
                double chord = 0;
                for (size_t i = 0; i + 1 < hits.size(); i += 2) chord += hits[i + 1].t - hits[i].t;
                chords += chord > 0;
                Rng rng(1, uint64_t(y) * 48 + x);
                const RGB L = integrator->radiance(ray, rng);
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(L[c], std::exp(-sigmaA[c] * chord), 1e-4 * std::exp(-sigmaA[c] * chord))
                        << "pixel " << x << "," << y << " channel " << c << " integrator " << int(type);
            }
        EXPECT_GT(chords, 48 * 48 / 4);  // the sphere fills a good part of the image
    }
}

// Mean and standard error of n samples of one pixel.
Estimate samplePixel(const Integrator& integrator, const Ray& ray, uint64_t key, int n) {
    return estimateMean(n, [&](int i) {
        Rng rng(7, key, uint64_t(i));
        return integrator.radiance(ray, rng);
    });
}

// Russian roulette keeps an eye path's weight at most 1 in a grey medium that absorbs little
// (albedo 0.998, jade's), under an environment of radiance 1: no sample exceeds 1. It used to
// end a path with at least 5% chance at every event, whatever its weight, so a survivor's weight
// grew by albedo / 0.95 per event, and jade rendered samples of 100 to 500 times their pixel.
TEST(Render, RouletteKeepsAPathsWeightInAMediumThatAbsorbsLittle) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.1), RGB(50)), 8);
    desc.lights.push_back(environment(1));
    const Scene scene(desc);
    IntegratorDesc integ;
    integ.maxDepth = 256;
    const auto integrator = makeIntegrator(scene, integ);
    double largest = 0;
    for (uint32_t i = 0; i < 2000; ++i) {
        Rng rng = Rng::pixelSample(1, 0, i);
        largest = std::max(largest, maxComponent(integrator->radiance(scene.camera().generateRay(4, 4), rng)));
    }
    EXPECT_GT(largest, 0.9);
    EXPECT_LE(largest, 1 + 1e-9);
}

// Every stretch through a thin homogeneous medium brings back direct light, not only the few
// whose free flight interacts: a camera ray through a sphere of optical depth 0.1 under a point
// light, single scattering only. Nearly every sample is lit (9% were, those that interacted),
// and the mean is the single-scattering integral along the ray by quadrature, with the scene's own
// transmittances to the camera and to the light.
TEST(Render, AThinMediumIsLitOnEveryStretch) {
    const double sigmaS = 0.05;
    SceneDesc desc = sceneWith(sphereMedium(RGB(0), RGB(sigmaS)), 8);
    const glm::dvec3 lamp(0.3, 3, 0.2);
    const RGB intensity(5);
    desc.lights.push_back(pointLight(lamp, intensity));
    const Scene scene(desc);
    IntegratorDesc integ;
    integ.maxDepth = 2;  // single scattering
    const auto integrator = makeIntegrator(scene, integ);
    const Ray ray{scene.camera().position(), {0, 0, -1}};
    ASSERT_NEAR(ray.o.z, 4, 1e-12);
    const int n = 20000;
    int lit = 0;
    double sum = 0, sum2 = 0;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        Rng rng = Rng::pixelSample(3, 0, i);
        const double L = integrator->radiance(ray, rng).x;
        lit += L > 0;
        sum += L;
        sum2 += L * L;
    }
    const double mean = sum / n, stdError = std::sqrt((sum2 / n - mean * mean) / (n - 1));
    EXPECT_GT(lit, 0.99 * n);
    // The chord lies within t in [2.9, 5.1]; the midpoint rule over it (the integrand jumps at the
    // boundary: an error of about the step's share).
    const int steps = 4000;
    const double t0 = 2.9, t1 = 5.1, h = (t1 - t0) / steps;
    const VolumeState camera = scene.volumeAt(ray.o);
    double integral = 0;
    for (int k = 0; k < steps; ++k) {
        const double t = t0 + (k + 0.5) * h;
        const glm::dvec3 x = ray.at(t);
        const VolumeState here = scene.volumeAt(x);
        if (!here.inside()) continue;
        const glm::dvec3 toLamp = lamp - x;
        const double r = glm::length(toLamp);
        const double toCamera = transmittance(scene, ray, t, camera).x;
        const double toLight = transmittance(scene, Ray{x, toLamp / r}, r, here).x;
        integral += sigmaS * toCamera * toLight * intensity.x / (r * r) * kInv4Pi * h;
    }
    EXPECT_NEAR(mean, integral, 5 * stdError + 2e-3 * integral) << "stdError " << stdError;
}

// A camera path splits in two at its first interaction in a homogeneous medium: the same mean as
// the path that does not split (continuePath from the same camera ray), with less variance per
// sample, multiple scattering under a point light.
TEST(Render, ACameraPathSplitsAtItsFirstInteractionKeepingItsMean) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.1), RGB(1), 0.3), 8);
    desc.lights.push_back(pointLight({0.3, 3, 0.2}, RGB(5)));
    const Scene scene(desc);
    const VolPathIntegrator integrator(scene, 64);
    const Ray ray{scene.camera().position(), glm::normalize(-scene.camera().position())};
    const VolumeState camera = scene.volumeAt(ray.o);
    const int n = 20000;
    const Estimate split = estimateMean(n, [&](int i) {
        Rng rng = Rng::pixelSample(5, 0, uint32_t(i));
        return integrator.radiance(ray, rng);
    });
    const Estimate whole = estimateMean(n, [&](int i) {
        Rng rng = Rng::pixelSample(6, 0, uint32_t(i));
        return integrator.continuePath(ray, camera, 0, true, rng);
    });
    // Variances per sample: n squared standard errors.
    const double variance[2] = {n * split.stdError.x * split.stdError.x, n * whole.stdError.x * whole.stdError.x};
    ASSERT_GT(whole.mean.x, 0);
    EXPECT_NEAR(split.mean.x, whole.mean.x, 5 * std::sqrt((variance[0] + variance[1]) / n));
    EXPECT_LT(variance[0], 0.8 * variance[1])
        << "split " << variance[0] << ", whole " << variance[1] << ", means " << split.mean.x << " " << whole.mean.x;
}

// (b) White furnace: a medium that absorbs nothing, inside an environment of radiance 1, is
// invisible: every pixel is 1 within its statistical error, for any g, chromatic sigma_s and
// a density that varies per vertex.
void expectFurnace(const MediumDesc& medium) {
    SceneDesc desc = sceneWith(medium, 12);
    desc.lights.push_back(environment(1));
    const Scene scene(desc);
    ASSERT_EQ(scene.volumes()[0].volume->homogeneous(), medium.density.isConstant());
    if (!medium.density.isConstant()) {
        ASSERT_GT(scene.volumes()[0].steinerPoints, 50u);  // the density varies inside
    }
    IntegratorDesc integ;
    integ.maxDepth = 1 << 20;  // a furnace is only white without truncation
    const auto integrator = makeIntegrator(scene, integ);
    RGB total(0), totalVar(0);
    int pixels = 0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            const Estimate e =
                samplePixel(*integrator, scene.camera().generateRay(x + 0.5, y + 0.5), uint64_t(y) * 12 + x, 256);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(e.mean[c], 1.0, 5 * e.stdError[c] + 1e-12) << "pixel " << x << "," << y;
            total += e.mean;
            totalVar += e.stdError * e.stdError;
            ++pixels;
        }
    const RGB mean = total / double(pixels), se = glm::sqrt(totalVar) / double(pixels);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0, 3 * se[c]) << "channel " << c;
}

TEST(Render, WhiteFurnaceHomogeneous) { expectFurnace(sphereMedium(RGB(0), RGB(0.5, 2, 6), 0.7)); }

TEST(Render, WhiteFurnacePerVertexDensity) {
    MediumDesc m = sphereMedium(RGB(0), RGB(1, 3, 5), -0.4);
    m.density.type = DensityDesc::Type::Noise;
    m.density.offset = 1;
    m.density.amplitude = 0.9;
    m.density.frequency = 3;
    m.tetOptions.maxVolume = 0.01;  // interior vertices, so the density varies inside
    expectFurnace(m);
}

RGB meanAbsDiff(const Image& a, const Image& b) {
    RGB sum(0);
    for (size_t i = 0; i < a.pixels.size(); ++i) sum += glm::abs(RGB(a.pixels[i]) - RGB(b.pixels[i]));
    return sum / double(a.pixels.size());
}

// (c) The parity baseline's ray march: the parity test agrees with the exact tet segments to within the
// step-size error; filling the bounding box does not.
TEST(Render, SingleScatteringBoundaryModes) {
    SceneDesc desc = sceneWith(sphereMedium(RGB(0.3), RGB(1.5)), 24);
    LightDesc light = pointLight({2, 3, 2}, RGB(20));
    desc.lights.push_back(light);
    const Scene scene(desc);
    auto renderWith = [&](BoundaryMode mode, double step) {
        IntegratorDesc integ;
        integ.type = IntegratorType::Single;
        integ.boundary = mode;
        integ.stepSize = step;
        RenderOptions options;
        options.spp = 8;
        return render(scene, *makeIntegrator(scene, integ), options).image;
    };
    const Image tet = renderWith(BoundaryMode::Tet, 0.01);
    double brightness = 0;
    for (const auto& p : tet.pixels) brightness += p.x;
    brightness /= double(tet.pixels.size());
    const double parityFine = average(meanAbsDiff(renderWith(BoundaryMode::Parity, 0.01), tet));
    const double parityCoarse = average(meanAbsDiff(renderWith(BoundaryMode::Parity, 0.1), tet));
    const double bbox = average(meanAbsDiff(renderWith(BoundaryMode::Bbox, 0.01), tet));
    std::printf("mean |difference| to tet: parity 0.01: %.5f, parity 0.1: %.5f, bbox: %.5f (brightness %.4f)\n",
                parityFine, parityCoarse, bbox, brightness);
    EXPECT_LT(parityFine, 0.05 * brightness);
    EXPECT_LT(parityFine, parityCoarse);  // the difference is the step-size error: it shrinks with the step
    EXPECT_GT(bbox, 5 * parityFine);
}

// (d) The same seed gives the same image, bit for bit, with one thread and with two.
TEST(Render, SameSeedSameImageAnyThreadCount) {
    const Scene scene(glowingSphereUnderQuad(32));
    for (const PhotonEstimate estimate : {PhotonEstimate::Beam, PhotonEstimate::KnnMarch})
        for (const IntegratorType type : {IntegratorType::VolPath, IntegratorType::Photon}) {
            if (type == IntegratorType::VolPath && estimate == PhotonEstimate::KnnMarch) continue;
            SCOPED_TRACE(type == IntegratorType::VolPath    ? "volpath"
                         : estimate == PhotonEstimate::Beam ? "photon, beam"
                                                            : "photon, knn-march");
            IntegratorDesc integ;
            integ.type = type;
            integ.estimate = estimate;
            integ.photons = 20000;
            integ.seed = 42;
            const auto integrator = makeIntegrator(scene, integ);
            RenderOptions options;
            options.spp = 4;
            options.seed = 42;
            options.threads = 1;
            const Image one = render(scene, *integrator, options).image;
            options.threads = 2;
            const Image two = render(scene, *integrator, options).image;
            ASSERT_EQ(one.pixels.size(), two.pixels.size());
            EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(one.pixels[0])));
            options.seed = 43;
            const Image other = render(scene, *integrator, options).image;
            EXPECT_NE(0,
                      std::memcmp(one.pixels.data(), other.pixels.data(), one.pixels.size() * sizeof(one.pixels[0])));
        }
}

}  // namespace
}  // namespace tetglow::test
