#include "cli/RenderArgs.h"

#include <charconv>
#include <filesystem>

#include "cli/Commands.h"
#include "scene/SceneLoader.h"

namespace tetglow::cli {
namespace {

// "AxB" (separator x or :) as two ints; {-1, -1} unless the whole text is that. from_chars, not
// sscanf: "4294967297x8" must not wrap to 1x8.
std::pair<int, int> parsePair(const std::string& text, char separator) {
    int a = 0, b = 0;
    const char *begin = text.data(), *end = begin + text.size();
    const auto x = std::from_chars(begin, end, a);
    if (x.ec != std::errc() || x.ptr == end || *x.ptr != separator) return {-1, -1};
    const auto y = std::from_chars(x.ptr + 1, end, b);
    if (y.ec != std::errc() || y.ptr != end || y.ptr == x.ptr + 1) return {-1, -1};
    return {a, b};
}

void applyOverrides(const RenderArgs& o, SceneDesc& scene) {
    IntegratorDesc& integ = scene.integrator;
    // The options were checked against the same tables.
    if (const auto v = valueOf(kIntegratorNames, o.integrator)) integ.type = *v;
    if (const auto v = valueOf(kBoundaryNames, o.boundary)) integ.boundary = *v;
    if (o.spp) {
        integ.spp = o.spp;
        integ.sppGiven = true;
    }
    if (o.maxDepth) integ.maxDepth = o.maxDepth;
    if (o.step > 0) integ.stepSize = o.step;
    if (o.seed >= 0) integ.seed = uint64_t(o.seed);
    if (o.photons) integ.photons = uint64_t(o.photons);
    if (o.k) {
        integ.k = o.k;
        integ.radius = 0;
    }
    if (o.radius > 0) integ.radius = o.radius;
    if (const auto v = valueOf(kEstimateNames, o.estimate)) integ.estimate = *v;
    if (!o.boundaryCorrection.empty()) integ.boundaryCorrection = o.boundaryCorrection == "on";
    if (!o.finalGather.empty()) integ.finalGather = o.finalGather == "on";
    if (o.time > 0) integ.timeLimit = o.time;
    if (!o.resolution.empty()) {
        const auto [w, h] = parsePair(o.resolution, 'x');
        if (w < 1 || h < 1 || w > kMaxResolution || h > kMaxResolution)
            throw CLI::ValidationError("--resolution", "expected WxH with W and H in 1.." +
                                                           std::to_string(kMaxResolution) + ", got '" +
                                                           shorten(o.resolution) + "'");
        scene.camera.width = w;
        scene.camera.height = h;
    }
}

}  // namespace

std::vector<CLI::Option*> addRenderArgs(CLI::App* cmd, RenderArgs& o) {
    cmd->add_option("scene", o.scene, "Scene file: JSON, pbrt-v3 (.pbrt) or glTF 2.0 (.gltf, .glb); see docs/FORMAT.md")
        ->required()
        ->check(CLI::ExistingFile);
    std::vector<CLI::Option*> options;
    auto add = [&](CLI::Option* option) {
        options.push_back(option);
        return option;
    };
    add(cmd->add_option("--integrator", o.integrator,
                        "volpath (reference), single (the parity baseline's ray march) or photon")
            ->check(CLI::IsMember(namesOf(kIntegratorNames))));
    add(cmd->add_option("--spp", o.spp, "Samples per pixel")->check(CLI::Range(1, kMaxSpp)));
    add(cmd->add_option("--threads", o.threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024)));
    add(cmd->add_option("--seed", o.seed, "Random seed: the same seed gives the same image at any thread count")
            ->check(inIntegers(0, INT64_MAX)));
    add(cmd->add_option("--resolution", o.resolution, "Image size WxH")->check(kNonEmpty));
    add(cmd->add_option("--camera", o.camera, "glTF scene: the camera node to look through (default: the first)")
            ->check(kNonEmpty));
    add(cmd->add_option(
               "--boundary", o.boundary,
               "single: where the medium is: tet (exact), parity (the parity baseline's ray-parity test) or bbox")
            ->check(CLI::IsMember(namesOf(kBoundaryNames))));
    add(cmd->add_option("--step", o.step, "single: ray-march step in world units")->check(inRange(kPositive)));
    add(cmd->add_option("--max-depth", o.maxDepth, "Events per path")->check(CLI::Range(1, kMaxDepth)));
    add(cmd->add_option("--photons", o.photons, "photon: photon paths per pass")
            ->check(CLI::Range(int64_t(1), kMaxPhotons)));
    auto* k = add(cmd->add_option("--k", o.k,
                                  "photon: neighbours that set the radius of each lookup (k-NN) or photon ball (beam)")
                      ->check(CLI::Range(1, 100000)));
    add(cmd->add_option("--radius", o.radius, "photon: a fixed radius (world units) instead of --k")
            ->check(inRange(kPositive))
            ->excludes(k));
    add(cmd->add_option("--estimate", o.estimate,
                        "photon: knn-march (the parity baseline's march with a k-NN lookup per step) or beam")
            ->check(CLI::IsMember(namesOf(kEstimateNames))));
    add(cmd->add_option("--boundary-correction", o.boundaryCorrection,
                        "photon: divide each kernel by the part of its ball inside the medium (on|off)")
            ->check(CLI::IsMember({"on", "off"})));
    add(cmd->add_option("--final-gather", o.finalGather,
                        "photon: diffuse surfaces seen from the eye gather indirect light by one more bounce (on|off)")
            ->check(CLI::IsMember({"on", "off"})));
    add(cmd->add_option("--passes", o.spp,
                        "photon: passes, each with fresh photons and one sample per pixel (the same as --spp)")
            ->check(CLI::Range(1, kMaxSpp)));
    add(cmd->add_option("--time", o.time,
                        "Render passes until this many seconds have passed, at most the spp of the scene or --spp "
                        "(photon: progressive)")
            ->check(inRange(kPositive)));
    add(cmd->add_option("--noise", o.noise,
                        "Adaptive sampling: every 8x8 tile of pixels takes the passes that bring its estimated "
                        "relative MSE to this, planned after 16 passes; the spp, of the scene or --spp, caps them")
            ->check(inRange(kPositive)));
    add(cmd->add_option("--exposure", o.exposure, "PNG preview exposure in stops")->check(kFinite));
    return options;
}

SceneDesc loadSceneWith(const RenderArgs& args) {
    SceneDesc desc = loadScene(args.scene, args.camera);
    applyOverrides(args, desc);
    return desc;
}

std::string defaultOutput(const RenderArgs& args, const SceneDesc& scene) {
    if (!scene.output.empty()) return scene.output;
    return std::filesystem::path(args.scene).stem().string() + ".exr";
}

std::pair<int, int> parseRange(const std::string& option, const std::string& text, int total, const std::string& what) {
    const auto [a, b] = parsePair(text, ':');
    if (a < 0 || b <= a || b > total)
        throw CLI::ValidationError(option, "expected A:B with 0 <= A < B <= " + std::to_string(total) +
                                               " (the scene's " + what + "), got '" + shorten(text) + "'");
    return {a, b};
}

}  // namespace tetglow::cli
