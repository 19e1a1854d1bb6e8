// tetglow merge PART... -o OUT.exr: the parts of a render (render --pass-range) summed into the
// image one process would have rendered, bit for bit (render/Film.h says why it is exact).
#include <cstdio>

#include "base/OutputFile.h"
#include "cli/Commands.h"
#include "render/ImageIO.h"
#include "render/PartialRender.h"
#include "tet/TriangleMesh.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::vector<std::string> parts;
    std::string output;
    double exposure = 0;
};

void run(const Options& o) {
    if (std::filesystem::path(o.output).extension() != ".exr")
        throw InputError(o.output + ": the output must be an .exr file");
    for (const auto& path : {o.output, previewPath(o.output)}) prepareOutput(path, o.parts);
    const PartialRender whole = mergeParts(o.parts);
    const Image image = whole.film.image();
    writeExrAndPng(o.output, image, o.exposure);
    if (const uint64_t dropped = whole.film.droppedSamples())
        std::fprintf(stderr, "warning: %llu samples were NaN or Inf and were dropped\n", (unsigned long long)dropped);
    std::printf("%s and %s: %zu parts of %s frame %d, %dx%d, %d spp\n", o.output.c_str(), previewPath(o.output).c_str(),
                o.parts.size(), whole.info.scene.c_str(), whole.info.frame, whole.film.width(), whole.film.height(),
                whole.info.totalPasses);
}

}  // namespace

void addMergeCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "merge", "Combine the parts of a render (render --pass-range) into the full image, bit for bit");
    cmd->add_option("parts", o->parts, "Part files written by render --pass-range: together every pass once")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output .exr (a .png preview is written beside it)")
        ->required()
        ->check(kNonEmpty);
    cmd->add_option("--exposure", o->exposure, "PNG preview exposure in stops")->check(kFinite);
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
