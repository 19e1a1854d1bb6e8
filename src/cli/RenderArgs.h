// The options `render` shares with `farm` (which hands them on to every task's render): what
// the scene is rendered with, as opposed to where the result goes or which part is rendered.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/SceneDescription.h"

namespace tetglow::cli {

struct RenderArgs {
    std::string scene, integrator, boundary, resolution, estimate, boundaryCorrection, finalGather, camera;
    int spp = 0, threads = 0, maxDepth = 0, k = 0;
    double step = 0, exposure = 0, radius = 0, time = 0, noise = 0;
    int64_t seed = -1, photons = 0;
};

// Adds the scene argument and the render options to `cmd`; returns the options (not the scene)
// so that `farm` can pass on the ones given.
std::vector<CLI::Option*> addRenderArgs(CLI::App* cmd, RenderArgs& args);

// The scene file with the options applied. InputError on a bad scene, CLI::ValidationError on a bad option.
SceneDesc loadSceneWith(const RenderArgs& args);

// Where a render of the scene goes without -o: the scene's "output", else SCENE.exr in the
// working folder.
std::string defaultOutput(const RenderArgs& args, const SceneDesc& scene);

// A..B-1 of the scene's `total` passes or frames (`what`), from "A:B" with 0 <= A < B <= total;
// CLI::ValidationError naming `option` otherwise.
std::pair<int, int> parseRange(const std::string& option, const std::string& text, int total, const std::string& what);

}  // namespace tetglow::cli
