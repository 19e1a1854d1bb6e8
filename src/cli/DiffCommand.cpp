// tetglow diff TEST.exr REFERENCE.exr [--json]: how far a render is from a reference.
// A measurement: exit 0 whatever the difference; 1 when the images cannot be compared.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "render/ImageIO.h"
#include "render/TileError.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string test, reference;
    bool json = false;
    int tile = 0;
};

constexpr const char* kFormulas =
    "a = test, b = reference, over all pixels and R, G, B channels whose test pixel is finite:\n"
    "  rmse       sqrt(mean((a-b)^2))\n"
    "  rel_mse    mean((a-b)^2 / (b^2 + 0.01))\n"
    "  mae        mean(|a-b|)\n"
    "  max_error  max over pixels of max over channels of |a-b|, and its pixel (x, y from the top-left)\n"
    "  non_finite test pixels with NaN or Inf in any channel (left out of the above)\n"
    "  tile_rel_mse (--tile N) rel_mse of each NxN tile, row-major from the top-left\n"
    "Exit 0 when compared, even if the images differ; 1 on unreadable files or different sizes.";

void run(const Options& o) {
    const Image test = readExr(o.test), reference = readExr(o.reference);
    const ImageDiff d = compare(test, reference);
    const std::vector<double> tiles = o.tile > 0 ? tileRelMse(test, reference, o.tile) : std::vector<double>{};
    if (o.json) {
        nlohmann::json j = {{"rmse", d.rmse},          {"rel_mse", d.relMse},           {"mae", d.mae},
                            {"max_error", d.maxError}, {"max_pixel", {d.maxX, d.maxY}}, {"non_finite", d.nonFinite},
                            {"width", test.width},     {"height", test.height}};
        if (o.tile > 0) j["tile_rel_mse"] = tiles;
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
    if (!tiles.empty())
        std::printf("tile_rel_mse largest %.6g of %zu tiles of %dx%d\n", *std::max_element(tiles.begin(), tiles.end()),
                    tiles.size(), o.tile, o.tile);
}

}  // namespace

void addDiffCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("diff", "Compare a rendered OpenEXR image with a reference");
    cmd->add_option("test", o->test, "The image to measure (OpenEXR)")->required();
    cmd->add_option("reference", o->reference, "The reference image (OpenEXR, same size, finite)")->required();
    cmd->add_flag("--json", o->json, "Print the measurements as one JSON object");
    cmd->add_option("--tile", o->tile, "Also the rel_mse of each NxN tile of pixels (tile_rel_mse)")
        ->check(CLI::Range(1, 65536));
    cmd->footer(kFormulas);
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
