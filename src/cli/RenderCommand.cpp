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

// What the options make of the scene: its passes, the part and frame to render, and where to.
struct Plan {
    SceneDesc desc;
    PartInfo part;
    std::string passesFrom;  // what set the passes, for the progress
    std::string output;
};

Plan planRender(const Options& o) {
    Plan p{loadSceneWith(o.args), {}, o.args.spp ? "--spp" : "the scene's spp", ""};
    SceneDesc& desc = p.desc;
    // A spp given caps a render for a time or to a noise target; none given leaves them their own stop.
    const bool openEnded = o.args.noise > 0 || desc.integrator.timeLimit > 0;
    if (openEnded && !desc.integrator.sppGiven && o.passRange.empty()) {
        desc.integrator.spp = kMaxSpp;
        p.passesFrom = "the most there are: neither the scene nor --spp gives a spp";
    }
    PartInfo& part = p.part;
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
    p.output = outputPath(o, desc);
    if (std::filesystem::path(p.output).extension() != ".exr")
        throw InputError(p.output + ": the output must be an .exr file");
    return p;
}

// Checks the files a render will write before it starts; the reference's log is one of them.
std::optional<ReferenceLog> prepareOutputs(const Options& o, const Plan& p) {
    prepareOutput(p.output, p.desc.inputs);
    if (o.passRange.empty()) prepareOutput(previewPath(p.output), p.desc.inputs);
    std::optional<ReferenceLog> reference;
    if (!o.reference.empty()) {
        prepareOutput(errorLogPath(p.output), p.desc.inputs);
        reference.emplace(o.reference, errorLogPath(p.output), p.desc.camera.width, p.desc.camera.height);
    }
    return reference;
}

// The farm's tasks count on this cache: without it each of them tetrahedralizes again.
void checkTetCache(const Scene& scene) {
    for (const auto& m : scene.volumes())
        if (m.stats.cacheFile.empty())
            throw InputError("render --tetrahedralize-only: medium " + m.name +
                             ": cannot fill the tet cache: " + m.stats.cacheProblem);
}

RenderOptions renderOptions(const Options& o, const Plan& p) {
    RenderOptions options;
    options.spp = p.desc.integrator.spp;
    options.firstPass = p.part.firstPass;
    options.endPass = p.part.endPass;
    options.timeLimit = p.desc.integrator.timeLimit;
    options.seed = p.desc.integrator.seed;
    options.threads = o.args.threads;
    options.noiseTarget = o.args.noise;
    options.cancel = &interrupted();
    return options;
}

void writeResult(const Options& o, const Plan& p, RenderResult& result) {
    if (!o.passRange.empty()) {
        // A part with an unfinished pass would merge into an image no single render gives.
        if (result.cancelled) {
            std::fprintf(stderr, "interrupted (%s): %s (passes %s) was not written\n", interruptName(),
                         p.output.c_str(), o.passRange.c_str());
            std::exit(128 + interruptSignal());
        }
        writePartial(p.output, {p.part, std::move(result.film)});
    } else {
        writeExrAndPng(p.output, result.image, o.args.exposure);
    }
}

// What was written, what went wrong on the way, and where the time went.
// The samples taken, summed over the pixels: adaptive sampling gives pixels different counts.
double samplesTaken(const Film& film) {
    double samples = 0;
    for (size_t i = 0; i < film.pixelCount(); ++i) samples += film.count(i);
    return samples;
}

void reportResult(const Options& o, const Plan& p, const RenderResult& result, double samples, const Scene& scene,
                  const IntegratorStats& stats) {
    const CameraDesc& camera = p.desc.camera;
    const double pixels = double(camera.width) * camera.height;
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
            "%s and %s: %dx%d, %d spp%s%s\n", p.output.c_str(), previewPath(p.output).c_str(), camera.width,
            camera.height, result.passes, average,
            result.noise ? (", noise " + std::to_string(*result.noise) + " (estimated relative MSE)").c_str() : "");
    else
        std::printf("%s: part of %s frame %d: passes %s of %d, %dx%d\n", p.output.c_str(), o.args.scene.c_str(),
                    p.part.frame, o.passRange.c_str(), p.part.totalPasses, camera.width, camera.height);
    for (const std::string& line : stats.lines) std::printf("%s\n", line.c_str());
    std::printf("time: tetrahedralization %.2f s, photon tracing %.2f s, rendering %.2f s (%.0f samples/s)\n",
                scene.tetrahedralizeSeconds(), stats.tracingSeconds, result.seconds - stats.tracingSeconds,
                samples / result.seconds);
}

void run(const Options& o) {
    Plan p = planRender(o);
    std::optional<ReferenceLog> reference;
    if (!o.tetsOnly) reference = prepareOutputs(o, p);

    const Scene scene(p.desc);
    printVolumes(scene);
    if (o.tetsOnly) return checkTetCache(scene);
    const auto integrator = makeIntegrator(scene, p.desc.integrator);
    for (const std::string& w : integrator->warnings()) std::fprintf(stderr, "tetglow: warning: %s\n", w.c_str());

    RenderOptions options = renderOptions(o, p);
    Progress progress("render", {(p.part.endPass > 0 ? p.part.endPass : options.spp) - p.part.firstPass, p.passesFrom,
                                 options.timeLimit, options.noiseTarget, integrator->stats().biased});
    options.passDone = [&](const PassReport& r) {
        progress.pass(r);
        if (reference) reference->pass(r);
    };
    // From the first pass until the files are renamed into place: a signal in the middle of the
    // write lets the write finish.
    InterruptGuard guard;
    RenderResult result = render(scene, *integrator, options);
    progress.finish(result);
    const double samples = samplesTaken(result.film);  // before a part's film is written away
    writeResult(o, p, result);
    reportResult(o, p, result, samples, scene, integrator->stats());
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
