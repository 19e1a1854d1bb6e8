// tetglow render SCENE: tetrahedralize every medium the scene names (cached), then render.
// SCENE is a JSON scene or a pbrt-v3 one (docs/FORMAT.md).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <tuple>

#include "base/OutputFile.h"
#include "cli/Commands.h"
#include "cli/Interrupt.h"
#include "cli/MediaReport.h"
#include "cli/Progress.h"
#include "cli/ReferenceLog.h"
#include "cli/RenderArgs.h"
#include "photon/PhotonIntegrator.h"
#include "render/ImageIO.h"
#include "render/IntegratorFactory.h"
#include "render/PartialRender.h"
#include "render/Renderer.h"
#include "scene/SceneFingerprint.h"
#include "scene/Turntable.h"

namespace tetglow::cli {
namespace {

struct Options {
    RenderArgs args;
    std::string output, passRange, reference;
    int frame = -1;
    bool tetsOnly = false;
};

std::string outputPath(const Options& o, const SceneDesc& scene) {
    return o.output.empty() ? defaultOutput(o.args, scene) : o.output;
}

void run(const Options& o) {
    SceneDesc desc = loadSceneWith(o.args);
    // A spp given caps a render for a time or to a noise target; none given leaves them their own stop.
    const bool openEnded = o.args.noise > 0 || desc.integrator.timeLimit > 0;
    std::string passesFrom = o.args.spp ? "--spp" : "the scene's spp";
    if (openEnded && !desc.integrator.sppGiven && o.passRange.empty()) {
        desc.integrator.spp = kMaxSpp;
        passesFrom = "the most there are: neither the scene nor --spp gives a spp";
    }
    PartInfo part;
    if (!o.passRange.empty()) {
        std::tie(part.firstPass, part.endPass) = parseRange("--pass-range", o.passRange, desc.integrator.spp, "passes");
        part.totalPasses = desc.integrator.spp;
        part.scene = o.args.scene;
        part.fingerprint = sceneFingerprint(desc);  // of the whole animation: the frame is checked on its own
        if (o.args.noise > 0) {                     // it plans the samples: parts to another target are another render
            char target[32];
            std::snprintf(target, sizeof target, " noise %.17g", o.args.noise);
            part.fingerprint += target;
        }
    }
    if (o.frame >= desc.turntable.frames)
        throw InputError(o.args.scene + ": --frame " + std::to_string(o.frame) + " is past the scene's frames 0.." +
                         std::to_string(desc.turntable.frames - 1));
    part.frame = std::max(o.frame, 0);
    desc.camera = cameraAtFrame(desc, part.frame);
    const std::string output = outputPath(o, desc);
    if (std::filesystem::path(output).extension() != ".exr")
        throw InputError(output + ": the output must be an .exr file");
    if (!o.tetsOnly) {
        prepareOutput(output, desc.inputs);
        if (o.passRange.empty()) prepareOutput(previewPath(output), desc.inputs);
    }
    std::optional<ReferenceLog> reference;
    if (!o.reference.empty() && !o.tetsOnly) {
        prepareOutput(errorLogPath(output), desc.inputs);
        reference.emplace(o.reference, errorLogPath(output), desc.camera.width, desc.camera.height);
    }

    const Scene scene(desc);
    printVolumes(scene);
    if (o.tetsOnly) {
        // The farm's tasks count on this cache: without it each of them tetrahedralizes again.
        for (const auto& m : scene.volumes())
            if (m.stats.cacheFile.empty())
                throw InputError("render --tetrahedralize-only: medium " + m.name +
                                 ": cannot fill the tet cache: " + m.stats.cacheProblem);
        return;
    }
    const auto integrator = makeIntegrator(scene, desc.integrator);
    for (const std::string& w : integrator->warnings()) std::fprintf(stderr, "tetglow: warning: %s\n", w.c_str());
    const auto* photon = dynamic_cast<const PhotonIntegrator*>(integrator.get());

    RenderOptions options;
    options.spp = desc.integrator.spp;
    options.firstPass = part.firstPass;
    options.endPass = part.endPass;
    options.timeLimit = desc.integrator.timeLimit;
    options.seed = desc.integrator.seed;
    options.threads = o.args.threads;
    options.noiseTarget = o.args.noise;
    options.cancel = &interrupted();
    Progress progress("render", {(part.endPass > 0 ? part.endPass : options.spp) - part.firstPass, passesFrom,
                                 options.timeLimit, options.noiseTarget, photon && photon->tracesPhotons()});
    options.passDone = [&](const PassReport& r) {
        progress.pass(r);
        if (reference) reference->pass(r);
    };
    // From the first pass until the files are renamed into place: a signal in the middle of the
    // write lets the write finish.
    InterruptGuard guard;
    RenderResult result = render(scene, *integrator, options);
    progress.finish(result);
    double samples = 0;  // per pixel, summed: adaptive sampling gives pixels different counts
    for (size_t i = 0; i < result.film.pixelCount(); ++i) samples += result.film.count(i);

    if (!o.passRange.empty()) {
        // A part with an unfinished pass would merge into an image no single render gives.
        if (result.cancelled) {
            std::fprintf(stderr, "interrupted (%s): %s (passes %s) was not written\n", interruptName(), output.c_str(),
                         o.passRange.c_str());
            std::exit(128 + interruptSignal());
        }
        writePartial(output, {part, std::move(result.film)});
    } else {
        writeExrAndPng(output, result.image, o.args.exposure);
    }
    const double pixels = double(desc.camera.width) * desc.camera.height;
    char average[64] = "";
    if (o.args.noise > 0)
        std::snprintf(average, sizeof average, " (the most a pixel took; %.1f on average)", samples / pixels);
    if (interrupted())
        std::fprintf(stderr, "interrupted (%s): wrote %d complete passes%s\n", interruptName(), result.passes,
                     result.cancelled ? " (and the tiles of the next)" : "");
    if (result.droppedSamples)
        std::fprintf(stderr, "warning: %llu samples were NaN or Inf and were dropped\n",
                     (unsigned long long)result.droppedSamples);
    if (o.passRange.empty())
        std::printf(
            "%s and %s: %dx%d, %d spp%s%s\n", output.c_str(), previewPath(output).c_str(), desc.camera.width,
            desc.camera.height, result.passes, average,
            result.noise ? (", noise " + std::to_string(*result.noise) + " (estimated relative MSE)").c_str() : "");
    else
        std::printf("%s: part of %s frame %d: passes %s of %d, %dx%d\n", output.c_str(), o.args.scene.c_str(),
                    part.frame, o.passRange.c_str(), part.totalPasses, desc.camera.width, desc.camera.height);
    double tracing = 0;
    if (photon)
        for (const DomainChoice& c : photon->choices()) {
            if (!c.measured) continue;
            std::string names;
            for (int m : c.media) names += (names.empty() ? "" : "+") + scene.media()[size_t(m)].name;
            std::printf(
                "photons: %s %s: predicted relative MSE at %llu passes %.3g with photons, %.3g walked (%d of the "
                "pilot's %d probes met it); walks %s\n",
                names.c_str(), c.walked ? "walked" : "photons", (unsigned long long)c.passes, c.photonMse, c.walkMse,
                c.probes, PhotonIntegrator::kPilotProbes,
                c.walksPayFrom ? ("pay from " + std::to_string(c.walksPayFrom) + " passes").c_str()
                               : "do not pay within 65536 passes");
        }
    if (photon && !photon->tracesPhotons())
        std::printf(
            "photons: none traced: every medium is walked and no surface is a dielectric, so paths carry "
            "all the light, as in volpath\n");
    else if (photon) {
        const PhotonStats& s = photon->stats();
        tracing = s.tracingSeconds;
        std::printf("photons: %llu paths traced, %llu stored in media, %llu on surfaces, %.1f MB of maps per pass\n",
                    (unsigned long long)s.paths, (unsigned long long)s.volumePhotons,
                    (unsigned long long)s.surfacePhotons, s.bytes / 1e6);
    }
    if (photon && photon->stats().pilotSeconds > 0)
        std::printf("time: photon pilot %.2f s (before the render)\n", photon->stats().pilotSeconds);
    std::printf("time: tetrahedralization %.2f s, photon tracing %.2f s, rendering %.2f s (%.0f samples/s)\n",
                scene.tetrahedralizeSeconds(), tracing, result.seconds - tracing, samples / result.seconds);
    if (interrupted()) {
        std::fflush(stdout);
        std::exit(128 + interruptSignal());  // the shell's code for "stopped by the signal", with the image written
    }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "render", "Tetrahedralize the scene's media (cached) and render it to OpenEXR and a PNG preview");
    const auto renderOptions = addRenderArgs(cmd, o->args);
    cmd->add_option("-o,--output", o->output, "Output .exr (a .png preview is written beside it)")->check(kNonEmpty);
    auto* time = *std::find_if(renderOptions.begin(), renderOptions.end(),
                               [](const CLI::Option* x) { return x->check_name("--time"); });
    cmd->add_option("--pass-range", o->passRange,
                    "Render passes A..B-1 of the scene's (A:B), each with its own seed and radius, into a part for "
                    "`tetglow merge`")
        ->excludes(time);
    cmd->add_option("--frame", o->frame, "The frame of the scene's turntable to render (from 0)")
        ->check(inIntegers(0, INT32_MAX));
    cmd->add_option("--reference", o->reference,
                    "After each pass, print the relative MSE against this EXR and add it to a CSV beside the image")
        ->check(CLI::ExistingFile)
        ->excludes("--pass-range");
    cmd->add_flag("--tetrahedralize-only", o->tetsOnly,
                  "Only fill the tet cache with the scene's media, render nothing");
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
