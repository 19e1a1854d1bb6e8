// tetglow render SCENE: tetrahedralize every medium the scene names (cached), then render.
// SCENE is a JSON scene or a pbrt-v3 one (docs/FORMAT.md).
#include <atomic>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli/Commands.h"
#include "cli/Progress.h"
#include "render/ImageIO.h"
#include "render/PhotonIntegrator.h"
#include "render/Renderer.h"
#include "scene/SceneLoader.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string scene, output, integrator, boundary, resolution, estimate, boundaryCorrection;
    int spp = 0, threads = 0, maxDepth = 0, k = 0;
    double step = 0, exposure = 0, radius = 0, time = 0;
    int64_t seed = -1, photons = 0;
};

std::atomic<bool> interrupted{false};
// A second Ctrl-C ends the program at once.
void onInterrupt(int) {
    interrupted = true;
    std::signal(SIGINT, SIG_DFL);
}

// Ctrl-C stops the render after the tiles in flight; the image so far is still written.
class InterruptGuard {
public:
    InterruptGuard() {
        struct sigaction action {};
        action.sa_handler = onInterrupt;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_);
    }
    ~InterruptGuard() { sigaction(SIGINT, &previous_, nullptr); }

private:
    struct sigaction previous_ {};
};

void applyOverrides(const Options& o, SceneDesc& scene) {
    IntegratorDesc& integ = scene.integrator;
    // The options were checked against the same tables.
    if (const auto v = valueOf(kIntegratorNames, o.integrator)) integ.type = *v;
    if (const auto v = valueOf(kBoundaryNames, o.boundary)) integ.boundary = *v;
    if (o.spp) integ.spp = o.spp;
    if (o.maxDepth) integ.maxDepth = o.maxDepth;
    if (o.step > 0) integ.stepSize = o.step;
    if (o.seed >= 0) integ.seed = uint64_t(o.seed);
    if (o.photons) integ.photons = uint64_t(o.photons);
    if (o.k) integ.k = o.k, integ.radius = 0;
    if (o.radius > 0) integ.radius = o.radius;
    if (const auto v = valueOf(kEstimateNames, o.estimate)) integ.estimate = *v;
    if (!o.boundaryCorrection.empty()) integ.boundaryCorrection = o.boundaryCorrection == "on";
    if (o.time > 0) integ.timeLimit = o.time, integ.spp = o.spp ? o.spp : kMaxSpp;
    if (!o.resolution.empty()) {
        // from_chars, not sscanf: "4294967297x8" must not wrap to 1x8.
        int w = 0, h = 0;
        const char *begin = o.resolution.data(), *end = begin + o.resolution.size();
        const auto x = std::from_chars(begin, end, w);
        const auto y = x.ec == std::errc() && x.ptr != end && *x.ptr == 'x' ? std::from_chars(x.ptr + 1, end, h) : x;
        if (y.ec != std::errc() || y.ptr != end || x.ptr == begin || w < 1 || h < 1 || w > kMaxResolution || h > kMaxResolution)
            throw CLI::ValidationError("--resolution", "expected WxH with W and H in 1.." + std::to_string(kMaxResolution) + ", got '" +
                                                           shorten(o.resolution) + "'");
        scene.camera.width = w, scene.camera.height = h;
    }
}

std::string outputPath(const Options& o, const SceneDesc& scene) {
    if (!o.output.empty()) return o.output;
    if (!scene.output.empty()) return scene.output;
    return std::filesystem::path(o.scene).stem().string() + ".exr";
}

void run(const Options& o) {
    SceneDesc desc = loadScene(o.scene);
    applyOverrides(o, desc);
    const std::string output = outputPath(o, desc);
    if (std::filesystem::path(output).extension() != ".exr") throw InputError(output + ": the output must be an .exr file");
    for (const auto& path : {output, previewPath(output)}) prepareOutput(path, {o.scene});

    const Scene scene(desc);
    for (const auto& m : scene.media())
        std::fprintf(stderr, "medium %s: %zu tets, %zu Steiner points, %s in %.2f s\n", m.name.c_str(), m.medium->mesh().tets.size(),
                     m.steinerPoints, m.stats.fromCache ? "read from the cache" : "tetrahedralized", m.stats.seconds);
    const auto integrator = makeIntegrator(scene, desc.integrator);

    RenderOptions options;
    options.spp = desc.integrator.spp;
    options.timeLimit = desc.integrator.timeLimit;
    options.seed = desc.integrator.seed;
    options.threads = o.threads;
    options.cancel = &interrupted;
    Progress progress("render");
    options.progress = [&](double f) { progress.update(f); };
    RenderResult result;
    {
        InterruptGuard guard;
        result = render(scene, *integrator, options);
    }
    progress.finish();

    writeExr(output, result.image);
    writePng(previewPath(output), result.image, o.exposure);
    const double pixels = double(desc.camera.width) * desc.camera.height;
    if (result.cancelled) std::fprintf(stderr, "interrupted: wrote %d complete passes (and the tiles of the next)\n", result.passes);
    if (result.droppedSamples) std::fprintf(stderr, "warning: %llu samples were NaN or Inf and were dropped\n", (unsigned long long)result.droppedSamples);
    std::printf("%s and %s: %dx%d, %d spp\n", output.c_str(), previewPath(output).c_str(), desc.camera.width, desc.camera.height, result.passes);
    double tracing = 0;
    if (const auto* photon = dynamic_cast<const PhotonIntegrator*>(integrator.get())) {
        const PhotonStats& s = photon->stats();
        tracing = s.tracingSeconds;
        std::printf("photons: %llu paths traced, %llu stored in media, %llu on surfaces, %.1f MB of maps per pass\n",
                    (unsigned long long)s.paths, (unsigned long long)s.volumePhotons, (unsigned long long)s.surfacePhotons, s.bytes / 1e6);
    }
    std::printf("time: tetrahedralization %.2f s, photon tracing %.2f s, rendering %.2f s (%.0f samples/s)\n",
                scene.tetrahedralizeSeconds(), tracing, result.seconds - tracing, pixels * result.passes / result.seconds);
    if (result.cancelled) {
        std::fflush(stdout);
        std::exit(130);  // the shell's code for "stopped by Ctrl-C", with the image written
    }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand("render", "Tetrahedralize the scene's media (cached) and render it to OpenEXR and a PNG preview");
    cmd->add_option("scene", o->scene, "Scene file: JSON, or pbrt-v3 (.pbrt); see docs/FORMAT.md")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o->output, "Output .exr (a .png preview is written beside it)")->check(kNonEmpty);
    cmd->add_option("--integrator", o->integrator, "volpath (reference), single (the seed's ray march) or photon")
        ->check(CLI::IsMember(namesOf(kIntegratorNames)));
    cmd->add_option("--spp", o->spp, "Samples per pixel")->check(CLI::Range(1, kMaxSpp));
    cmd->add_option("--threads", o->threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
    cmd->add_option("--seed", o->seed, "Random seed: the same seed gives the same image at any thread count")->check(inRange(kNonNegative));
    cmd->add_option("--resolution", o->resolution, "Image size WxH")->check(kNonEmpty);
    cmd->add_option("--boundary", o->boundary, "single: where the medium is: tet (exact), parity (the seed's test) or bbox")
        ->check(CLI::IsMember(namesOf(kBoundaryNames)));
    cmd->add_option("--step", o->step, "single: ray-march step in world units")->check(inRange(kPositive));
    cmd->add_option("--max-depth", o->maxDepth, "Events per path")->check(CLI::Range(1, kMaxDepth));
    cmd->add_option("--photons", o->photons, "photon: photon paths per pass")->check(CLI::Range(int64_t(1), kMaxPhotons));
    auto* k = cmd->add_option("--k", o->k, "photon: neighbours that set the radius of each lookup (k-NN) or photon ball (beam)")
                  ->check(CLI::Range(1, 100000));
    cmd->add_option("--radius", o->radius, "photon: a fixed radius (world units) instead of --k")
        ->check(inRange(kPositive))
        ->excludes(k);
    cmd->add_option("--estimate", o->estimate, "photon: knn-march (the seed's march with a k-NN lookup per step) or beam")
        ->check(CLI::IsMember(namesOf(kEstimateNames)));
    cmd->add_option("--boundary-correction", o->boundaryCorrection, "photon: divide each kernel by the part of its ball inside the medium (on|off)")
        ->check(CLI::IsMember({"on", "off"}));
    auto* passes = cmd->add_option("--passes", o->spp, "photon: passes, each with fresh photons and one sample per pixel (the same as --spp)")
                       ->check(CLI::Range(1, kMaxSpp));
    cmd->add_option("--time", o->time, "Render passes until this many seconds have passed (photon: progressive)")
        ->check(inRange(kPositive))
        ->excludes(passes);
    cmd->add_option("--exposure", o->exposure, "PNG preview exposure in stops")->check(kFinite);
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
