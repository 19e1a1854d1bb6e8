// Where each renderer breaks: camera rays exactly through vertices and edges and grazing the
// surface, extreme coefficients (optical thickness 1e-4 and 1e4 per unit, albedo 0 and 1,
// g = -0.99 and 0.99), photon counts and radii at their extremes, broken media. No NaN or Inf
// anywhere, energy bounded; bench/results/stability.py puts the figures printed here in
// docs/RESULTS.md. Moderate coefficients: Render.* in test_render.cpp.
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "StabilityCases.h"
#include "TestMeshes.h"
#include "TestScenes.h"
#include "integrators/Integrator.h"
#include "render/Image.h"
#include "render/ImageIO.h"
#include "render/IntegratorFactory.h"
#include "render/Renderer.h"

namespace tetglow::test {
namespace {

struct Mode {
    std::string name;
    IntegratorDesc desc;
};

IntegratorDesc photon(PhotonEstimate estimate, uint64_t photons) {
    IntegratorDesc d;
    d.type = IntegratorType::Photon;
    d.estimate = estimate;
    d.photons = photons;
    return d;
}

std::vector<Mode> modes(double step) {
    std::vector<Mode> all;
    IntegratorDesc volpath;
    all.push_back({"volpath", volpath});
    for (const auto& [name, boundary] :
         {std::pair{"single, tets", BoundaryMode::Tet}, std::pair{"single, parity", BoundaryMode::Parity},
          std::pair{"single, bbox", BoundaryMode::Bbox}}) {
        IntegratorDesc single;
        single.type = IntegratorType::Single;
        single.boundary = boundary;
        single.stepSize = step;
        all.push_back({name, single});
    }
    for (const auto& [name, estimate] :
         {std::pair{"photon, beam", PhotonEstimate::Beam}, std::pair{"photon, knn-march", PhotonEstimate::KnnMarch}}) {
        all.push_back({name, photon(estimate, 20000)});
        all.back().desc.stepSize = step;
    }
    return all;
}

// A medium in a white environment of radiance 1, seen by a 6x6 camera.
SceneDesc furnace(TriangleMesh boundary, const RGB& sigmaA, const RGB& sigmaS, double g) {
    MediumDesc m = sphereMedium(sigmaA, sigmaS, g);
    m.boundary = roundedToFloat(std::move(boundary));
    SceneDesc s = sceneWith(m, 6);
    s.lights.push_back(environment(1));
    return s;
}

// Every integrator's radiance along the lines against `exact`, printed per kind of line.
// Volpath, photon and the tet march find every entry with the tets' exact tests and every exit,
// interface included, from the walk's exit face: within 1e-6 on every line (at 1e-8 rad the
// chord itself is only known to about 1e-16 / 1e-8 in double precision). Parity and bbox are
// only bounded.
template <class Exact>
void expectEveryIntegratorAlong(const Scene& scene, const std::vector<NamedLine>& lines, Exact&& exact,
                                const char* what) {
    for (const auto& mode : modes(0.01)) {
        const auto integrator = makeIntegrator(scene, mode.desc);
        integrator->beginPass(0);
        struct Error {
            double sum = 0, max = 0;
            size_t lines = 0;
        };
        std::map<std::string, Error> errorByKind;  // of |L - exact|
        for (const auto& [kind, ray] : lines) {
            Error& e = errorByKind[kind];
            Rng rng(3, e.lines);
            const double L = integrator->radiance(ray, rng).x, truth = exact(ray);
            ASSERT_TRUE(std::isfinite(L)) << mode.name << ", " << kind;
            EXPECT_GE(L, 0) << mode.name << ", " << kind;
            EXPECT_LE(L, 1 + 1e-12) << mode.name << ", " << kind;
            if (mode.name.rfind("single, ", 0) != 0 || mode.name == "single, tets") {
                EXPECT_NEAR(L, truth, 1e-6) << mode.name << ", " << kind;
            }
            e.sum += std::abs(L - truth);
            e.max = std::max(e.max, std::abs(L - truth));
            ++e.lines;
        }
        std::printf("%-15s %s, mean (max):", mode.name.c_str(), what);
        for (const auto& [kind, e] : errorByKind)
            std::printf(" %s %.1e (%.1e);", kind.c_str(), e.sum / double(e.lines), e.max);
        std::printf("\n");
    }
}

// An absorbing polyhedron: along every line the radiance is exp(-sigma_a * chord), the chord
// from exact plane tests.
TEST(StabilityRender, RaysThroughVerticesEdgesAndGrazingEveryIntegrator) {
    const double sigma = 1.5;
    const Scene scene(furnace(tiltedPolyhedron(2), RGB(sigma), RGB(0), 0));
    const TriangleMesh surface = scene.volumes()[0].volume->mesh().surfaceMesh();
    expectEveryIntegratorAlong(
        scene, degenerateLines(surface), [&](const Ray& ray) { return std::exp(-sigma * convexChord(surface, ray)); },
        "|radiance - exp(-sigma chord)|");
}

// The same lines against the interface of a polyhedron nested in another (index-matched, other
// coefficients): through the inner one's vertices and edges and grazing its faces, where the
// walk crosses from region to region itself.
TEST(StabilityRender, RaysThroughVerticesEdgesAndGrazingAnInterface) {
    const double outer = 0.5, inner = 3.0;
    SceneDesc desc = furnace(tiltedPolyhedron(2), RGB(outer), RGB(0), 0);
    MediumDesc core = desc.media[0];
    core.name = "core";
    core.sigmaA = RGB(inner);
    const glm::dvec3 centre = 0.5 * (bounds(core.boundary).lo + bounds(core.boundary).hi);
    for (auto& p : core.boundary.positions) p = centre + 0.5 * (p - centre);
    core.boundary = roundedToFloat(std::move(core.boundary));
    desc.media.push_back(core);
    const Scene scene(desc);
    ASSERT_EQ(scene.volumes().size(), 1u);
    const TriangleMesh& out = desc.media[0].boundary;
    const TriangleMesh& in = desc.media[1].boundary;
    std::vector<NamedLine> lines = degenerateLines(in);
    const double back = 2 * bounds(out).diagonal();
    for (auto& line : lines) line.ray.o -= back * line.ray.d;  // from outside both
    expectEveryIntegratorAlong(
        scene, lines,
        [&](const Ray& ray) {
            const double c = convexChord(in, ray);
            return std::exp(-(outer * (convexChord(out, ray) - c) + inner * c));
        },
        "at an interface |radiance - exp(-sum sigma_i L_i)|");
}

// Mean and standard error over every sample of every pixel, and the non-finite samples.
struct Stats {
    double mean = 0, stdError = 0;
    size_t nonFinite = 0;
};
Stats sampleImage(const Scene& scene, Integrator& integrator, int spp) {
    integrator.beginPass(0);
    double sum = 0, sum2 = 0;
    size_t n = 0, bad = 0;
    const Camera& camera = scene.camera();
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x)
            for (int s = 0; s < spp; ++s) {
                Rng rng(5, uint64_t(y) * camera.width() + x, uint64_t(s));
                const RGB L = integrator.radiance(camera.generateRay(x + rng.uniform(), y + rng.uniform()), rng);
                if (!isFinite(L)) {
                    ++bad;
                    continue;
                }
                const double v = average(L);
                sum += v;
                sum2 += v * v;
                ++n;
            }
    const double mean = sum / double(n);
    return {mean, std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean) / double(n - 1)), bad};
}

// The furnace bound: nothing emits but the environment of radiance 1, so no estimate may
// exceed 1 in expectation, whatever the coefficients; with albedo 1 volpath keeps it all
// (up to its depth limit), with albedo 0 every method shows the transmittance.
TEST(StabilityRender, ExtremeCoefficientsStayFiniteAndBounded) {
    for (double sigmaT : {1e-4, 1e4})
        for (double albedo : {0.0, 1.0})
            for (double g : {-0.99, 0.99}) {
                const Scene scene(furnace(icosphere(2, 1.0), RGB(sigmaT * (1 - albedo)), RGB(sigmaT * albedo), g));
                std::printf("sigma_t %.0e, albedo %.0f, g %+.2f:", sigmaT, albedo, g);
                for (const auto& mode : modes(0.05)) {
                    const Stats s = sampleImage(scene, *makeIntegrator(scene, mode.desc), 16);
                    std::printf(" %s %.4f +- %.4f;", mode.name.c_str(), s.mean, s.stdError);
                    EXPECT_EQ(s.nonFinite, 0u) << mode.name;
                    EXPECT_GE(s.mean, 0) << mode.name;
                    EXPECT_LE(s.mean, 1 + 5 * s.stdError + 1e-9) << mode.name;
                    if (sigmaT < 1) {
                        EXPECT_GT(s.mean, 0.999) << mode.name;  // nearly transparent
                    }
                }
                std::printf("\n");
            }
}

double imageMean(const Image& image) {
    double sum = 0;
    for (const auto& p : image.pixels) sum += (double(p.x) + p.y + p.z) / 3;
    return sum / double(image.pixels.size());
}

// Photon parameters at their extremes on a glowing sphere, where all scattered light comes from
// photons, against volpath: few photons or a tiny radius give noise (and, in 4 passes, missing
// light), a huge radius bias. Nothing non-finite, the mean bounded: even a beam radius larger than
// the medium stays within about 6%, as each ball's chord along the ray is clipped to the medium
// and divided by the ball's volume inside it.
TEST(StabilityRender, PhotonCountsAndRadiiAtTheirExtremes) {
    MediumDesc glowing = sphereMedium(RGB(0.1), RGB(2.0), 0.3, 2);
    glowing.emission = RGB(0.5);
    const Scene scene(sceneWith(glowing, 16));
    RenderOptions options;
    options.spp = 64;
    IntegratorDesc volpath;
    const Image reference = render(scene, *makeIntegrator(scene, volpath), options).image;
    const double referenceMean = imageMean(reference);
    struct Case {
        const char* name;
        PhotonEstimate estimate;
        uint64_t photons;
        double radius;  // 0: k = 16 neighbours
    };
    const PhotonEstimate beam = PhotonEstimate::Beam, knn = PhotonEstimate::KnnMarch;
    const Case cases[] = {{"beam, 20000 photons (moderate)", beam, 20000, 0},
                          {"beam, 1 photon", beam, 1, 0},
                          {"beam, 30 photons", beam, 30, 0},
                          {"beam, 300 photons", beam, 300, 0},
                          {"beam, radius 1e-4", beam, 20000, 1e-4},
                          {"beam, radius 1e-2", beam, 20000, 1e-2},
                          {"beam, radius 3 (> the sphere)", beam, 20000, 3},
                          {"knn-march, 30 photons", knn, 30, 0},
                          {"knn-march, radius 1e-4", knn, 20000, 1e-4},
                          {"knn-march, radius 3", knn, 2000, 3}};
    options.spp = 4;  // passes
    std::printf("volpath 64 spp: mean %.4f\n", referenceMean);
    for (const Case& c : cases) {
        IntegratorDesc desc = photon(c.estimate, c.photons);
        desc.radius = c.radius;
        desc.stepSize = 0.05;
        const Image image = render(scene, *makeIntegrator(scene, desc), options).image;
        const ImageDiff d = compare(image, reference);
        const double bias = imageMean(image) / referenceMean - 1;
        std::printf("%-32s mean %+.1f%%, RMSE %.4f, non-finite %zu\n", c.name, 100 * bias, d.rmse, d.nonFinite);
        EXPECT_EQ(d.nonFinite, 0u) << c.name;
        EXPECT_GT(bias, -1) << c.name;
        // Beam balls of radius 1e-4 (about 38000 per pass, cross-section pi r^2, in a volume of
        // 4.2) met by some 600 eye rays of chord about 1.5 expect a quarter of a crossing in the
        // whole render, so its mean is the emission alone or one crossing's huge weight (seeds 0-7:
        // one render in eight has a crossing, with independent or Sobol samples alike): no upper
        // bound holds for it.
        const bool rareCrossings = c.estimate == beam && c.radius > 0 && c.radius < 1e-3;
        if (!rareCrossings) {
            EXPECT_LT(bias, 1.5) << c.name;
        }
        // The moderate setting, and radii beyond the medium: with enough photons, a huge kernel
        // clipped to the medium only blurs, so the mean holds.
        if (&c == cases) {
            EXPECT_LT(std::abs(bias), 0.05);
        }
        if (c.radius >= 1 && c.photons >= 2000) {
            EXPECT_LT(std::abs(bias), 0.1) << c.name;
        }
    }
}

// The scene of a medium in `obj`, lit by the sky, with the given "tetgen" options.
std::string mediumScene(const std::string& name, const std::string& obj, const std::string& tetgen) {
    return writeTemp(name + ".json", R"({"camera": {"position": [0.5, 0.5, 4], "look_at": [0.5, 0.5, 0]},
            "lights": [{"type": "environment", "radiance": 1}],
            "media": [{"shape": {"type": "mesh", "file": ")" +
                                         obj + R"("}, "sigma_s": 1, "tetgen": )" + tetgen + "}]}");
}

// A scene whose medium is broken, with strict tets: the render stops with the validation's
// one-line error instead of rendering whatever the parity test would make of it.
TEST(StabilityRender, BrokenMediaAreRefusedWhenStrict) {
    TriangleMesh holed = box();
    holed.triangles.pop_back();
    for (const auto& [name, mesh, expected] :
         {std::tuple{"holed", holed, "not closed"},
          std::tuple{"crossing", merge(box(), box(glm::dvec3(0.5), glm::dvec3(1.5))), "intersects itself"}}) {
        const std::string obj = tempDir() + "/" + name + ".obj", out = tempDir() + "/" + name + ".exr";
        writeObj(mesh, obj);
        const auto r = runTetglow("render " + mediumScene(name, obj, R"({"strict": true})") +
                                  " --resolution 8x8 --spp 1 -o " + out);
        EXPECT_EQ(r.exitCode, 1) << name << ": " << r.err;
        EXPECT_NE(r.err.find(expected), std::string::npos) << name << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << name;
        std::printf("%s: %s", name, r.err.substr(r.err.find("): ") + 3).c_str());  // without the temporary path
    }
}

// A sphere with small holes renders as the closed sphere does: the repaired medium differs from
// it only inside the holes' caps, so the images agree to within their noise.
TEST(StabilityRender, SmallHolesRenderLikeTheClosedMesh) {
    const TriangleMesh closed = icosphere(3, 0.5, glm::dvec3(0.5));
    TriangleMesh holed = closed;
    for (size_t k : {3u, 200u, 700u}) holed.triangles.erase(holed.triangles.begin() + long(k));
    std::vector<Image> images;
    for (const auto& [name, mesh] : {std::pair{"closed", closed}, std::pair{"holed", holed}}) {
        const std::string obj = tempDir() + "/" + name + ".obj", out = tempDir() + "/" + name + ".exr";
        writeObj(mesh, obj);
        const auto r =
            runTetglow("render " + mediumScene(name, obj, "{}") + " --resolution 24x24 --spp 16 --seed 3 -o " + out);
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        images.push_back(readExr(out));
    }
    double difference = 0, mean = 0;
    ASSERT_EQ(images[0].pixels.size(), images[1].pixels.size());
    for (size_t i = 0; i < images[0].pixels.size(); ++i) {
        const glm::vec3 a = images[0].pixels[i], b = images[1].pixels[i];
        difference += std::abs(a.x + a.y + a.z - b.x - b.y - b.z);
        mean += a.x + a.y + a.z;
    }
    std::printf("closed against holed sphere: summed |difference| %.4g of a sum %.4g\n", difference, mean);
    EXPECT_LT(difference, 0.02 * mean);
}

}  // namespace
}  // namespace tetglow::test
