// tetglow diff TEST.exr REFERENCE.exr [--json]: how far a render is from a reference.
// A measurement: exit 0 whatever the difference; 1 when the images cannot be compared.
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "render/ImageIO.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string test, reference;
    bool json = false;
};

constexpr const char* kFormulas =
    "a = test, b = reference, over all pixels and R, G, B channels whose test pixel is finite:\n"
    "  rmse       sqrt(mean((a-b)^2))\n"
    "  rel_mse    mean((a-b)^2 / (b^2 + 0.01))\n"
    "  mae        mean(|a-b|)\n"
    "  max_error  max over pixels of max over channels of |a-b|, and its pixel (x, y from the top-left)\n"
    "  non_finite test pixels with NaN or Inf in any channel (left out of the above)\n"
    "Exit 0 when compared, even if the images differ; 1 on unreadable files or different sizes.";

void run(const Options& o) {
    const Image test = readExr(o.test), reference = readExr(o.reference);
    const ImageDiff d = compare(test, reference);
    if (o.json) {
        const nlohmann::json j = {
            {"rmse", d.rmse},          {"rel_mse", d.relMse},           {"mae", d.mae},
            {"max_error", d.maxError}, {"max_pixel", {d.maxX, d.maxY}}, {"non_finite", d.nonFinite},
            {"width", test.width},     {"height", test.height}};
        std::cout << j.dump(2) << '\n';
        return;
    }
    std::printf("test        %s (%dx%d)\n", o.test.c_str(), test.width, test.height);
    std::printf("reference   %s\n", o.reference.c_str());
    std::printf("rmse        %.6g\n", d.rmse);
    std::printf("rel_mse     %.6g\n", d.relMse);
    std::printf("mae         %.6g\n", d.mae);
    std::printf("max_error   %.6g at pixel (%d, %d)\n", d.maxError, d.maxX, d.maxY);
    std::printf("non_finite  %zu\n", d.nonFinite);
}

}  // namespace

void addDiffCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("diff", "Compare a rendered OpenEXR image with a reference");
    cmd->add_option("test", o->test, "The image to measure (OpenEXR)")->required();
    cmd->add_option("reference", o->reference, "The reference image (OpenEXR, same size, finite)")->required();
    cmd->add_flag("--json", o->json, "Print the measurements as one JSON object");
    cmd->footer(kFormulas);
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
