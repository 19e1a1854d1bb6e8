// The photon integrator in an optically dense, non-absorbing medium (a mean free path of 1e-4 in
// a unit sphere): where the traced power goes, and the image against volpath's; which media its
// eye path walks instead of reading photons, and when it traces none.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "TestScenes.h"
#include "integrators/VolPathIntegrator.h"
#include "photon/PhotonIntegrator.h"
#include "photon/PhotonTracer.h"
#include "render/Renderer.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

SceneDesc denseSphere(int resolution) {
    SceneDesc s = sceneWith(sphereMedium(RGB(0), RGB(1e4), 0, 3), resolution);
    LightDesc point = pointLight({2, 3, 2}, RGB(20));
    s.lights.push_back(point);
    return s;
}

// Albedo 1: nothing is absorbed, so all the power that enters leaves (escaped) or is still in a
// walk when the event cap ends it (cut), within three standard errors, at every max depth.
// The deeper the cap, the more events each walk stores, and the less power is cut (of what
// enters, about 1.2 / sqrt(max depth): a walk's return to the surface is heavy-tailed).
TEST(DensePhoton, WalksLoseNoPower) {
    const Scene scene(denseSphere(8));
    const PhotonSource source(scene);
    double cut = INFINITY, stored = 0;
    for (int maxDepth : {16, 64, 256}) {
        const TracedPhotons traced = tracePhotons(scene, source, {20000, maxDepth, 3, 0});
        const EnergyBalance& e = traced.energy;
        RGB power(0);
        for (const Photon& p : traced.volume[0]) power += RGB(p.power);
        std::printf(
            "max depth %d: emitted %.4f, escaped %.4f, cut %.4f, absorbed %.4f, +- %.5f; %zu photons stored, power "
            "%.3f\n",
            maxDepth, e.emitted[0], e.escaped[0], e.cut[0], e.absorbedInMedia[0], std::sqrt(e.deficitSquares[0]),
            traced.volume[0].size(), power[0]);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(e.absorbedInMedia[c], 0);
            EXPECT_EQ(e.absorbedOnSurfaces[c], 0);
            EXPECT_NEAR(e.escaped[c] + e.cut[c], e.emitted[c],
                        3 * std::sqrt(e.deficitSquares[c]) + 1e-9 * e.emitted[c]);
        }
        EXPECT_GT(e.cut[0], 0);
        EXPECT_LE(e.cut[0], cut);
        EXPECT_GT(power[0], stored);
        cut = e.cut[0];
        stored = power[0];
    }
}

// The photon integrator walks a dense medium with the eye path and keeps none of its photons: a
// pass stores none there (it stored up to max depth per path, 32 bytes each, and threw them
// away), while the paths, and so the power reaching everything else, are the same.
TEST(DensePhoton, AWalkedMediumStoresNoPhotons) {
    const Scene scene(denseSphere(8));
    const PhotonSource source(scene);
    const TracedPhotons all = tracePhotons(scene, source, {2000, 64, 3, 0});
    PhotonTracingOptions options{2000, 64, 3, 0};
    options.storedMedia = {0};
    const TracedPhotons none = tracePhotons(scene, source, options);
    EXPECT_GT(all.volume[0].size(), 100u);
    EXPECT_TRUE(none.volume[0].empty());
    EXPECT_EQ(none.surface.size(), all.surface.size());
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(none.energy.escaped[c], all.energy.escaped[c]);
        EXPECT_EQ(none.energy.cut[c], all.energy.cut[c]);
    }
    // A pane of glass aside keeps the passes going (they would trace nothing, see below).
    SceneDesc s = denseSphere(8);
    s.surfaces.push_back({"pane", quad({3, -1, -1}, {0, 0, 2}, {0, 2, 0}), {MaterialType::Dielectric, RGB(0), 1.5}});
    const Scene paned(s);
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 2000;
    PhotonIntegrator photon(paned, desc);
    photon.beginPass(0);
    EXPECT_GT(photon.photonStats().paths, 0u);
    EXPECT_EQ(photon.photonStats().volumePhotons, 0u);
}

// A thin medium beside the view (a small sphere at x = 3): its photons keep the photon passes
// going, so the dense medium's eye stretches are photon mapping's own walk.
MediumDesc thinAside() {
    MediumDesc m = sphereMedium(RGB(0.2), RGB(0.8));
    m.boundary = icosphere(2, 0.25, {3, 0, 0});
    m.name = "aside";
    return m;
}

// The photon kernel cannot resolve a density that changes within a mean free path of the
// boundary, where the eye sees the medium (it read 25 to 50% dark, darker at greater depths):
// the image agrees with volpath's at the same max depth, short and long.
TEST(DensePhoton, AgreesWithVolpath) {
    SceneDesc s = denseSphere(24);
    s.media.push_back(thinAside());
    const Scene scene(s);
    for (int maxDepth : {16, 256}) {
        const RGB reference = meanImage(scene, VolPathIntegrator(scene, maxDepth), 128);
        IntegratorDesc desc;
        desc.type = IntegratorType::Photon;
        desc.photons = 5000;
        desc.maxDepth = maxDepth;
        PhotonIntegrator integrator(scene, desc);
        ASSERT_TRUE(integrator.tracesPhotons());
        const RGB photon = meanImage(scene, std::move(integrator), 128);
        std::printf("max depth %d: volpath %.5f, photon %.5f\n", maxDepth, reference[0], photon[0]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(photon[c], reference[c], 0.04 * reference[c]);
    }
}

// Where the eye path walks every medium and nothing refracts, the only photons a pass would keep
// are the floor's, whose light paths with next-event estimation carry without a kernel's blur:
// photon mapping traces none and renders volpath's image, sample for sample (it traced 100k paths
// a pass on blub.json, 65% of its time, for 0.6% of them on the floor, at twice volpath's error).
// A dielectric floor (caustics) or a medium that keeps its photons brings the passes back.
TEST(DensePhoton, WhereEveryMediumIsWalkedAndNothingRefractsNoPhotonIsTraced) {
    SceneDesc s = denseSphere(12);
    s.surfaces.push_back({"floor", quad({-3, -1.2, -3}, {0, 0, 6}, {6, 0, 0}), {MaterialType::Diffuse, RGB(0.6)}});
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 2000;
    auto paths = [&](const Scene& scene) {
        PhotonIntegrator photon(scene, desc);
        photon.beginPass(0);
        EXPECT_EQ(photon.tracesPhotons(), photon.photonStats().paths > 0);
        return photon.photonStats().paths;
    };
    const Scene scene(s);
    EXPECT_EQ(paths(scene), 0u);
    RenderOptions options;
    options.spp = 4;
    options.seed = 7;
    PhotonIntegrator photon(scene, desc);
    const Image image = render(scene, photon, options).image;
    VolPathIntegrator volpath(scene, desc.maxDepth);
    const Image reference = render(scene, volpath, options).image;
    ASSERT_EQ(image.pixels.size(), reference.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) ASSERT_EQ(image.pixels[i], reference.pixels[i]) << "pixel " << i;

    SceneDesc glass = s;
    glass.surfaces[0].material = {MaterialType::Dielectric, RGB(0), 1.5};
    EXPECT_GT(paths(Scene(glass)), 0u);
    SceneDesc thin = s;
    thin.media.push_back(thinAside());
    EXPECT_GT(paths(Scene(thin)), 0u);
}

// What `tetglow render` prints of the integrator after a render is Integrator::stats(): photon
// mapping reports the photons it traced and that its noise estimate leaves out a bias, or that it
// traced none; volpath reports nothing.
TEST(DensePhoton, StatsReportThePhotonsTraced) {
    SceneDesc s = denseSphere(12);
    s.surfaces.push_back({"floor", quad({-3, -1.2, -3}, {0, 0, 6}, {6, 0, 0}), {MaterialType::Diffuse, RGB(0.6)}});
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 2000;
    const Scene walked(s);
    PhotonIntegrator none(walked, desc);
    none.beginPass(0);
    const IntegratorStats noneStats = static_cast<const Integrator&>(none).stats();
    EXPECT_FALSE(noneStats.biased);
    EXPECT_EQ(noneStats.tracingSeconds, 0);
    ASSERT_EQ(noneStats.lines.size(), 1u);
    EXPECT_EQ(noneStats.lines[0].rfind("photons: none traced", 0), 0u) << noneStats.lines[0];

    s.surfaces[0].material = {MaterialType::Dielectric, RGB(0), 1.5};
    const Scene glass(s);
    PhotonIntegrator traced(glass, desc);
    traced.beginPass(0);
    const IntegratorStats stats = static_cast<const Integrator&>(traced).stats();
    EXPECT_TRUE(stats.biased);
    EXPECT_GT(stats.tracingSeconds, 0);
    EXPECT_EQ(stats.tracingSeconds, traced.photonStats().tracingSeconds);
    ASSERT_EQ(stats.lines.size(), 1u);
    const std::string paths = "photons: " + std::to_string(traced.photonStats().paths) + " paths traced, ";
    EXPECT_EQ(stats.lines[0].rfind(paths, 0), 0u) << stats.lines[0];

    const IntegratorStats volpath = VolPathIntegrator(walked, 8).stats();
    EXPECT_FALSE(volpath.biased);
    EXPECT_TRUE(volpath.lines.empty());
}

// A dense core inside a thin medium, index-matched: an eye ray that meets the core walks its
// stretch as volpath does, the others read the thin medium's photons.
TEST(DensePhoton, DenseCoreInAThinMediumAgreesWithVolpath) {
    SceneDesc s = denseSphere(24);
    s.media[0].sigmaA = RGB(0.2);
    s.media[0].sigmaS = RGB(0.8);
    MediumDesc core = sphereMedium(RGB(0), RGB(1e4), 0, 2);
    for (auto& p : core.boundary.positions) p *= 0.5f;
    core.name = "core";
    s.media.push_back(core);
    const Scene scene(s);
    const RGB reference = meanImage(scene, VolPathIntegrator(scene, 64), 256);
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 20000;
    const RGB photon = meanImage(scene, PhotonIntegrator(scene, desc), 64);
    std::printf("volpath %.5f, photon %.5f\n", reference[0], photon[0]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(photon[c], reference[c], 0.04 * reference[c]);
}

// Photons stored in a pass, before any estimate, by the photon integrator in `scene`.
size_t volumePhotonsOf(const Scene& scene) {
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 20000;  // about 1 in 60 reaches the sphere
    PhotonIntegrator photon(scene, desc);
    photon.beginPass(0);
    return photon.photonStats().volumePhotons;
}

// Behind glass under a point light, where shadow rays cannot reach the light, the walk's mean
// is not the image's and cannot measure the photons' bias: a medium that is not dense keeps its
// photons there (index-matched, the pilot chooses: test_photon_choice.cpp).
TEST(DensePhoton, BehindGlassUnderAPointLightAMediumKeepsItsPhotons) {
    const double diagonal = 2 * std::sqrt(3.0);  // of the unit sphere's bounding box
    SceneDesc s = denseSphere(8);
    s.media[0].sigmaA = RGB(0.1 * 10 / diagonal);
    s.media[0].sigmaS = RGB(0.9 * 10 / diagonal);  // a mean free path of a tenth of the diagonal
    s.media[0].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 1.5};
    EXPECT_GT(volumePhotonsOf(Scene(s)), 50u);
}

// Sealed in glass under a point light alone, photon mapping walks the dense medium as volpath
// does, whose shadow rays cannot refract to the light: the medium renders dark, and now the user
// is told so (it was dark without a word). Index-matched, or under the sky, nothing is said.
TEST(DensePhoton, SealedInGlassUnderAPointLightIsReported) {
    SceneDesc s = denseSphere(8);
    IntegratorDesc desc;
    desc.type = IntegratorType::Photon;
    desc.photons = 1000;
    const Scene matched(s);
    EXPECT_TRUE(PhotonIntegrator(matched, desc).warnings().empty());
    s.media[0].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 1.5};
    const Scene glass(s);
    const std::vector<std::string> lines = PhotonIntegrator(glass, desc).warnings();
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(
        lines[0].find(" lies inside a dielectric boundary and is optically dense: photon mapping walks it as volpath "
                      "does, which cannot carry light from a point, spot or distant light through that boundary"),
        std::string::npos)
        << lines[0];
    s.lights = {environment(1)};
    const Scene sky(s);
    EXPECT_TRUE(PhotonIntegrator(sky, desc).warnings().empty());
}

}  // namespace
}  // namespace tetglow::test
