// Media inside media through the integrators, against closed forms: transmittance along random
// lines through three levels of absorbing spheres and a cavity, touching boxes, a core in a
// dielectric skin (an incoherent multilayer), volpath against photon mapping on a nested
// scattering scene, and the photon tracer's energy balance with nested emitters.
#include <cmath>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/DirectLighting.h"
#include "integrators/Integrator.h"
#include "integrators/PathStep.h"
#include "integrators/SingleScatterIntegrator.h"
#include "integrators/VolPathIntegrator.h"
#include "photon/PhotonDomains.h"
#include "photon/PhotonIntegrator.h"
#include "photon/PhotonTracer.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"
#include "scene/Scene.h"
#include "tet/Shapes.h"

namespace tetglow::test {
namespace {

MediumDesc absorber(const std::string& name, TriangleMesh mesh, double sigmaA) {
    MediumDesc m;
    m.name = name;
    m.boundary = roundedToFloat(std::move(mesh));
    m.sigmaA = RGB(sigmaA);
    m.sigmaS = RGB(0);
    m.tetOptions.useCache = false;
    return m;
}

MediumDesc cavity(const std::string& name, TriangleMesh mesh) {
    MediumDesc m = absorber(name, std::move(mesh), 0);
    m.cavity = true;
    return m;
}

// Three levels of absorbing spheres, the innermost holding an empty cavity.
SceneDesc nestedSpheres() {
    SceneDesc s = sceneWith(absorber("body", icosphere(3, 1.0), 0.7), 8);
    s.media.push_back(absorber("organ", icosphere(3, 0.6, {0.1, 0, 0}), 2.0));
    s.media.push_back(absorber("core", icosphere(2, 0.3, {0.2, 0.05, 0}), 5.0));
    s.media.push_back(cavity("bubble", icosphere(2, 0.12, {0.22, 0.05, 0.03})));
    s.lights.push_back(environment(1));
    return s;
}

// Optical depth along the ray (t >= 0) from the meshes: each region's chord is its mesh's
// minus those of the meshes directly inside it (`parent`).
double exactDepth(const SceneDesc& s, const std::vector<int>& parent, const Ray& ray) {
    double tau = 0;
    for (size_t r = 0; r < s.media.size(); ++r) {
        double length = convexChord(s.media[r].boundary, ray);
        for (size_t c = 0; c < s.media.size(); ++c)
            if (parent[c] == int(r)) length -= convexChord(s.media[c].boundary, ray);
        tau += s.media[r].sigmaA.x * length;
    }
    return tau * glm::length(ray.d);
}

TEST(NestedRender, TransmittanceThroughNestedSpheresAndACavityIsTheClosedForm) {
    const SceneDesc desc = nestedSpheres();
    const Scene scene(desc);
    ASSERT_EQ(scene.volumes().size(), 1u);
    ASSERT_EQ(scene.volumes()[0].regionMedium.size(), 4u);
    const std::vector<int> parent{-1, 0, 1, 2};
    for (int r = 0; r < 4; ++r) EXPECT_EQ(scene.volumes()[0].volume->mesh().regionParent[r], parent[r]);
    std::mt19937_64 rng(14);
    constexpr int kLines = 100000;
    double worst = 0;
    int through = 0;
    for (int i = 0; i < kLines; ++i) {
        const glm::dvec3 a = onSphere(rng, 1.3), b = onSphere(rng, 1.3);
        const Ray ray{a, glm::normalize(b - a)};
        const double exact = exactDepth(desc, parent, ray);
        const RGB tr = transmittance(scene, ray, INFINITY, scene.volumeAt(ray.o));
        through += exact > 0;
        worst = std::max(worst, std::abs(tr.x / std::exp(-exact) - 1));
    }
    std::printf("worst relative transmittance error %.2e over %d lines (%d through the media)\n", worst, kLines,
                through);
    EXPECT_LE(worst, 1e-9);
    EXPECT_GT(through, kLines / 2);
}

TEST(NestedRender, VolpathSeesTheClosedFormThroughNestedAbsorbers) {
    // Absorbers only in a white sky: each camera ray's radiance is exactly its transmittance.
    const SceneDesc desc = nestedSpheres();
    const Scene scene(desc);
    const VolPathIntegrator volpath(scene, 64);
    const std::vector<int> parent{-1, 0, 1, 2};
    std::mt19937_64 lines(3);
    Rng rng(1, 0, 0);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 a = onSphere(lines, 1.3), b = onSphere(lines, 1.3);
        const Ray ray{a, glm::normalize(b - a)};
        const double L = volpath.radiance(ray, rng).x;
        // Beyond b the line leaves the media: the sky behind sends 1.
        worst = std::max(worst, std::abs(L / std::exp(-exactDepth(desc, parent, ray)) - 1));
    }
    EXPECT_LE(worst, 1e-9);
}

TEST(NestedRender, EachRegionHasItsOwnDensity) {
    // The core's density rises along z; the body around it is constant. Tets are linear in
    // each region's own field, also at the vertices the two share, so along a line of constant
    // z the core's density is 1 + 2 z exactly.
    SceneDesc desc = sceneWith(absorber("body", icosphere(3, 1.0), 0.5), 8);
    desc.media.push_back(absorber("core", icosphere(2, 0.5, {0.1, 0, 0.05}), 1.5));
    desc.media[1].density.type = DensityDesc::Type::Linear;
    desc.media[1].density.gradient = {0, 0, 2};
    const Scene scene(desc);
    ASSERT_FALSE(scene.volumes()[0].volume->homogeneous());
    std::mt19937_64 gen(12);
    std::uniform_real_distribution<double> u(-0.4, 0.4), angle(0, 2 * kPi);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        const double z = u(gen), a = angle(gen);
        const glm::dvec3 d(std::cos(a), std::sin(a), 0), o = glm::dvec3(u(gen), u(gen), z) - 2.0 * d;
        const Ray ray{o, d};
        const double core = convexChord(desc.media[1].boundary, ray),
                     body = convexChord(desc.media[0].boundary, ray) - core;
        const double exact = std::exp(-(0.5 * body + 1.5 * (1 + 2 * z) * core));
        worst = std::max(worst, std::abs(transmittance(scene, ray, INFINITY, {}).x / exact - 1));
    }
    EXPECT_LE(worst, 1e-12);
}

TEST(NestedRender, TouchingBoxesShareAFaceExactly) {
    SceneDesc desc = sceneWith(absorber("left", box({-1, -0.5, -0.5}, {0, 0.5, 0.5}), 0.8), 8);
    desc.media.push_back(absorber("right", box({0, -0.5, -0.5}, {1.5, 0.5, 0.5}), 0.3));
    desc.lights.push_back(environment(1));
    const Scene scene(desc);
    ASSERT_EQ(scene.volumes().size(), 1u);  // one tet mesh, the shared face an interface
    const VolPathIntegrator volpath(scene, 64);
    Rng rng(2, 0, 0);
    std::mt19937_64 gen(9);
    std::uniform_real_distribution<double> u(-0.45, 0.45);
    for (int i = 0; i < 200; ++i) {
        // Along x at a random height, and slanted across the shared face.
        const glm::dvec3 o(-3, u(gen), u(gen)), target(3, u(gen), u(gen));
        const Ray ray{o, glm::normalize(target - o)};
        const double exact = std::exp(
            -(0.8 * convexChord(desc.media[0].boundary, ray) + 0.3 * convexChord(desc.media[1].boundary, ray)));
        EXPECT_NEAR(transmittance(scene, ray, INFINITY, {}).x / exact, 1, 1e-12);
        EXPECT_NEAR(volpath.radiance(ray, rng).x / exact, 1, 1e-12);
    }
}

// Incoherent layers at normal incidence: reflectance from the front and the back, and the
// transmittance (the same both ways).
struct Layer {
    double front, back, through;
};
Layer interfaceLayer(double n1, double n2) {
    const double r = (n1 - n2) * (n1 - n2) / ((n1 + n2) * (n1 + n2));
    return {r, r, 1 - r};
}
Layer stack(const Layer& a, const Layer& b) {
    const double bounce = 1 / (1 - a.back * b.front);
    return {a.front + a.through * a.through * b.front * bounce, b.back + b.through * b.through * a.back * bounce,
            a.through * b.through * bounce};
}

TEST(NestedRender, ACoreInADielectricSkinIsTheMultilayer) {
    // A skin of glass (n 1.5, nothing in it) around an absorbing core of n 2 and an index-matched
    // absorbing core inside that: along x every face is met at normal incidence, so the paths
    // stay on the line and the white sky's radiance seen is 1 - absorbed, the incoherent
    // multilayer's reflectance plus transmittance.
    SceneDesc desc = sceneWith(absorber("skin", box(glm::dvec3(-1), glm::dvec3(1)), 0), 8);
    desc.media[0].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 1.5};
    desc.media.push_back(absorber("core", box(glm::dvec3(-0.5), glm::dvec3(0.5)), 0.6));
    desc.media[1].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 2.0};
    desc.media.push_back(
        absorber("heart", box(glm::dvec3(-0.25), glm::dvec3(0.25)), 1.5));  // index-matched to the core
    desc.lights.push_back(environment(1));
    const Scene scene(desc);
    const SceneVolume& v = scene.volumes()[0];
    const TetMesh& mesh = v.volume->mesh();
    for (size_t s = 0; s < mesh.surface.size(); ++s) {
        const MaterialDesc& m = v.materials[v.triangleMaterial[s]];
        const auto [behind, front] = mesh.surfaceRegions[s];
        // The heart is index-matched to the core, the core's face a dielectric of 2 / 1.5.
        const MaterialDesc expected =
            behind == 2 ? MaterialDesc{MaterialType::Interface}
                        : MaterialDesc{MaterialType::Dielectric, RGB(0.5), behind == 1 ? 2.0 / 1.5 : 1.5};
        EXPECT_EQ(m.type, expected.type) << "triangle " << s << " behind region " << behind << ", front " << front;
        if (m.type == MaterialType::Dielectric) {
            EXPECT_DOUBLE_EQ(m.ior, expected.ior);
        }
    }
    const auto absorbing = [](double length) { return Layer{0, 0, std::exp(-length)}; };
    const Layer core = stack(stack(absorbing(0.6 * 0.25), absorbing(1.5 * 0.5)), absorbing(0.6 * 0.25));
    const Layer all = stack(stack(stack(interfaceLayer(1, 1.5), interfaceLayer(1.5, 2)), core),
                            stack(interfaceLayer(2, 1.5), interfaceLayer(1.5, 1)));
    const double exact = all.front + all.through;
    // Every integrator follows the specular chain: volpath and photon through the walk's exit
    // faces, single through Embree's hits on every boundary, the parity baseline's way.
    for (IntegratorType type : {IntegratorType::VolPath, IntegratorType::Single, IntegratorType::Photon}) {
        IntegratorDesc d;
        d.type = type;
        d.maxDepth = 1 << 20;
        d.photons = 1000;
        const auto integrator = makeIntegrator(scene, d);
        integrator->beginPass(0);
        Rng rng(4, 0, 0);
        const Ray ray{{-3, 0.1, 0.2}, {1, 0, 0}};
        constexpr int kSamples = 40000;
        double sum = 0, squares = 0;
        for (int i = 0; i < kSamples; ++i) {
            const double L = integrator->radiance(ray, rng).x;
            sum += L;
            squares += L * L;
        }
        const double mean = sum / kSamples, error = std::sqrt((squares / kSamples - mean * mean) / kSamples);
        std::printf("skin and cores, %s: %.5f +- %.5f, multilayer %.5f\n",
                    std::string(nameOf(kIntegratorNames, type)).c_str(), mean, error, exact);
        EXPECT_NEAR(mean, exact, 4 * error + 1e-12);
        EXPECT_GT(error, 0);  // the Fresnel choices are random: the test has noise to compare
    }
}

// A scattering body with a glowing, scattering organ and an empty eye inside, in a dim sky. Both
// media are thin enough (mean free paths above a fifth of their diagonals) for photon mapping to
// estimate them, not walk them.
SceneDesc nestedScattering() {
    MediumDesc body = absorber("body", icosphere(3, 1.0), 0.2);
    body.sigmaS = RGB(1.0, 1.2, 1.4);
    body.g = 0.3;
    MediumDesc organ = absorber("organ", icosphere(2, 0.45, {0.2, -0.1, 0.1}), 0.3);
    organ.sigmaS = RGB(2.5);
    organ.emission = RGB(0.5, 1.0, 2.0);
    SceneDesc s = sceneWith(body, 6);
    s.media.push_back(organ);
    s.media.push_back(cavity("eye", icosphere(2, 0.2, {-0.4, 0.3, 0.5})));
    s.lights.push_back(environment(0.1));
    return s;
}

TEST(NestedRender, VolpathAndPhotonMappingAgreeOnNestedScatteringMedia) {
    const SceneDesc desc = nestedScattering();
    const Scene scene(desc);
    const RGB reference = meanImage(scene, VolPathIntegrator(scene, 256), 1024);
    IntegratorDesc photon = desc.integrator;
    photon.type = IntegratorType::Photon;
    photon.photons = 100000;
    const RGB photons = meanImage(scene, PhotonIntegrator(scene, photon), 16);
    for (int c = 0; c < 3; ++c) {
        std::printf("channel %d: volpath %.5f, photon %.5f\n", c, reference[c], photons[c]);
        EXPECT_NEAR(photons[c], reference[c], 0.04 * reference[c]);
    }
}

// Regions pool their photons only where light cannot tell them apart: the same coefficients and
// an index-matched interface between them. The pooled domain's kernel boundary is the outer
// surface alone.
TEST(NestedRender, RegionsOfOneMediumWithoutAnInterfaceShareAPhotonDomain) {
    MediumDesc outer = absorber("outer", icosphere(2, 1.0), 0.1);
    outer.sigmaS = RGB(2);
    MediumDesc inner = absorber("inner", icosphere(2, 0.6), 0.1);
    inner.sigmaS = RGB(2);
    const auto domainsOf = [&](const MediumDesc& in) {
        SceneDesc desc = sceneWith(outer, 4);
        desc.media.push_back(in);
        desc.lights.push_back(environment(1));
        const Scene scene(desc);
        return photonDomains(scene);
    };
    const PhotonDomains same = domainsOf(inner);
    ASSERT_EQ(same.media.size(), 1u);
    EXPECT_EQ(same.media[0], (std::vector<int>{0, 1}));
    EXPECT_EQ(same.boundary[0].size(), outer.boundary.triangles.size());
    MediumDesc denser = inner;
    denser.sigmaS = RGB(2.5);
    EXPECT_EQ(domainsOf(denser).media.size(), 2u);
    MediumDesc glass = inner;
    glass.boundaryMaterial = {MaterialType::Dielectric, RGB(0), 1.5};
    const PhotonDomains apart = domainsOf(glass);
    ASSERT_EQ(apart.media.size(), 2u);
    EXPECT_EQ(apart.boundary[0].size(), outer.boundary.triangles.size() + glass.boundary.triangles.size());
    EXPECT_EQ(apart.boundary[1].size(), glass.boundary.triangles.size());
}

// A sphere of medium inside a sphere of the same medium, 2 % smaller: one medium as far as light
// can tell, so photon mapping must render what volpath renders, though the shell between them is
// thin (its photons and kernels are pooled with the core's; kept apart, the image was 43 % too
// bright). The medium is thin enough for photon mapping to estimate it, not walk it.
TEST(NestedRender, PhotonMappingOverAThinShellOfTheSameMediumAgreesWithVolpath) {
    MediumDesc outer = absorber("outer", icosphere(3, 1.0), 0.1);
    outer.sigmaS = RGB(1.2);
    outer.g = 0.3;
    MediumDesc inner = outer;
    inner.name = "inner";
    inner.boundary = roundedToFloat(icosphere(3, 0.98));
    SceneDesc desc = sceneWith(outer, 6);
    desc.media.push_back(inner);
    LightDesc point = pointLight({2, 3, 2}, RGB(20));  // no sky: the image is the medium's light alone
    desc.lights.push_back(point);
    const Scene scene(desc);
    ASSERT_EQ(scene.volumes().size(), 1u);
    ASSERT_EQ(scene.volumes()[0].regionMedium.size(), 2u);
    const RGB reference = meanImage(scene, VolPathIntegrator(scene, 256), 1024);
    IntegratorDesc photon = desc.integrator;
    photon.type = IntegratorType::Photon;
    photon.photons = 100000;
    const RGB photons = meanImage(scene, PhotonIntegrator(scene, photon), 16);
    std::printf("volpath %.5f, photon %.5f\n", reference[0], photons[0]);
    EXPECT_NEAR(photons[0], reference[0], 0.04 * reference[0]);
}

void expectEnergyBalance(const SceneDesc& desc) {
    const Scene scene(desc);
    const PhotonSource source(scene);
    const TracedPhotons traced = tracePhotons(scene, source, {100000, 1 << 20, 5, 0});
    const EnergyBalance& e = traced.energy;
    for (int c = 0; c < 3; ++c) {
        const double accounted = e.absorbedInMedia[c] + e.absorbedOnSurfaces[c] + e.escaped[c] + e.cut[c];
        std::printf("channel %d: emitted %.5f, absorbed in media %.5f, escaped %.5f, cut %.5f, +- %.5f\n", c,
                    e.emitted[c], e.absorbedInMedia[c], e.escaped[c], e.cut[c], std::sqrt(e.deficitSquares[c]));
        EXPECT_NEAR(accounted, e.emitted[c], 3 * std::sqrt(e.deficitSquares[c]));
        EXPECT_NEAR(e.emitted[c], source.totalPower()[c], 0.02 * source.totalPower()[c]);
    }
    // Photons are kept by the medium that scattered them; the cavity holds none.
    EXPECT_GT(traced.volume[0].size(), 1000u);
    EXPECT_GT(traced.volume[1].size(), 1000u);
    EXPECT_EQ(traced.volume[2].size(), 0u);
}

TEST(NestedRender, EnergyBalancesWithNestedEmitters) { expectEnergyBalance(nestedScattering()); }

TEST(NestedRender, EnergyBalancesWithNestedEmittersBehindDielectricInterfaces) {
    // The body in a skin of n 1.4, the organ of n 1.6 in it: photons reflect and refract at the
    // walk's exit faces, inside and out.
    SceneDesc desc = nestedScattering();
    desc.media[0].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 1.4};
    desc.media[1].boundaryMaterial = {MaterialType::Dielectric, RGB(0.5), 1.6};
    expectEnergyBalance(desc);
}

// Next-event estimation is skipped in a sealed volume (Scene::sealed): there it must be exactly
// 0. A dielectric sphere under a point light and a sky is sealed, and so is an index-matched
// sphere in a dielectric box; an index-matched sphere is not, nor a dielectric one with the
// light inside it, nor one in an index-matched box (conservative: its own face blocks).
TEST(NestedRender, OnlyVolumesNoShadowRayLeavesAreSealed) {
    struct Case {
        const char* name;
        MaterialType sphere;
        glm::dvec3 light;
        std::optional<MaterialType> outerBox;  // a box medium around the sphere
        bool sealed, reaches;
    };
    const glm::dvec3 above(0.3, 3, 0.2), within(0.2, 0.1, 0.7);
    for (const Case& c :
         {Case{"dielectric", MaterialType::Dielectric, above, {}, true, false},
          Case{"index-matched", MaterialType::Interface, above, {}, false, true},
          Case{"light inside", MaterialType::Dielectric, within, {}, false, true},
          Case{"in a dielectric box", MaterialType::Interface, above, MaterialType::Dielectric, true, false},
          Case{"in an index-matched box", MaterialType::Dielectric, above, MaterialType::Interface, false, false}}) {
        SceneDesc desc = sceneWith(sphereMedium(RGB(0.1), RGB(1)), 8);
        const auto material = [](MaterialType t) {
            return MaterialDesc{t, RGB(0.5), t == MaterialType::Dielectric ? 1.5 : 1.0};
        };
        desc.media[0].boundaryMaterial = material(c.sphere);
        if (c.outerBox) {
            desc.media.push_back(absorber("box", box(glm::dvec3(-2), glm::dvec3(2)), 0.1));
            desc.media[1].boundaryMaterial = material(*c.outerBox);
        }
        LightDesc point = pointLight(c.light, RGB(5));
        desc.lights = {point, environment(0.5)};
        const Scene scene(desc);
        ASSERT_EQ(scene.sealed(0), c.sealed) << c.name;
        std::mt19937 random(5);
        std::uniform_real_distribution<double> u(-0.55, 0.55);  // inside the sphere
        int lit = 0;
        for (int i = 0; i < 200; ++i) {
            const glm::dvec3 p(u(random), u(random), u(random));
            const VolumeState at = scene.volumeAt(p);
            ASSERT_TRUE(at.inside());
            Rng rng(9, uint64_t(i));
            // A light sample as directInMedium takes it, without its skip for sealed volumes.
            const HenyeyGreenstein& phase = scene.volumes()[at.volume].volume->at(at.start.index).phase;
            lit += !isBlack(sampleDirect(scene, p, rng, false, phaseScattering(phase, {0, 0, 1}),
                                         [&](const Ray& r, double t) { return transmittance(scene, r, t, at); }));
        }
        if (c.sealed || !c.reaches) {
            EXPECT_EQ(lit, 0) << c.name;
        } else {
            EXPECT_GT(lit, 100) << c.name;
        }
    }
}

TEST(NestedRender, ParityAndBboxPickTheInnermostMedium) {
    SceneDesc desc = nestedSpheres();
    for (MediumDesc& m : desc.media) m.sigmaS = RGB(m.cavity ? 0 : 1);
    const Scene scene(desc);
    for (BoundaryMode mode : {BoundaryMode::Parity, BoundaryMode::Bbox}) {
        IntegratorDesc d;
        d.type = IntegratorType::Single;
        d.boundary = mode;
        const SingleScatterIntegrator single(scene, d);
        EXPECT_EQ(single.pick(0, {0.9, 0, 0}), mode == BoundaryMode::Parity ? 0 : 0);
        EXPECT_EQ(single.pick(0, {-0.3, 0, 0}), 1);
        EXPECT_EQ(single.pick(0, {0.2, 0.05, -0.2}), 2);
        EXPECT_EQ(single.pick(0, {0.22, 0.05, 0.03}), 3);  // the cavity
        EXPECT_EQ(single.pick(0, {0, 0, 1.2}), -1);
    }
    // Near a corner of the body's box, the box holds the point and the sphere does not.
    IntegratorDesc d;
    d.type = IntegratorType::Single;
    d.boundary = BoundaryMode::Bbox;
    EXPECT_EQ(SingleScatterIntegrator(scene, d).pick(0, {0.9, 0.9, 0.9}), 0);
    d.boundary = BoundaryMode::Parity;
    EXPECT_EQ(SingleScatterIntegrator(scene, d).pick(0, {0.9, 0.9, 0.9}), -1);
}

}  // namespace
}  // namespace tetglow::test
