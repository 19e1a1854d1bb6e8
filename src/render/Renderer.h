// Runs an integrator over the image: passes of one sample per pixel, tiles in parallel.
#pragma once
#include <atomic>
#include <functional>
#include <optional>

#include "integrators/Integrator.h"
#include "render/Film.h"

namespace tetglow {

// What the renderer knows after each complete pass.
struct PassReport {
    const Film& film;
    int passes = 0;  // complete passes so far
    double seconds = 0;
    std::optional<double> noise;  // estimateRelMse (render/NoiseEstimate.h), from the second pass on
    // noiseTarget: the passes the noisiest tile needs (before the cap), once the pilot has planned
    // them (render/AdaptiveSampling.h); 0 before.
    double neededPasses = 0;
};

struct RenderOptions {
    int spp = 16;
    // Passes firstPass .. endPass - 1 of the spp (endPass 0: spp). Each keeps its global index
    // (its seeds, its photon radius), so parts rendered apart merge into the full render.
    int firstPass = 0, endPass = 0;
    uint64_t seed = 0;
    int threads = 0;       // 0: all cores
    double timeLimit = 0;  // > 0: no pass starts after this many seconds (at least one runs)
    // > 0: adaptive sampling (render/AdaptiveSampling.h): after the pilot's passes each tile of
    // pixels takes the passes its own noise estimate says bring it to this relative MSE (at most
    // spp), and the render stops when every tile has them. Implies independentHalves. Planned from
    // the pilot's exact sums, so the same seed gives the same bits at any thread count, and parts
    // (firstPass, endPass) replay the pilot to plan the same budgets as the whole render.
    double noiseTarget = 0;
    // The even and the odd passes draw from two independently scrambled sequences (a pass's index
    // in its half is pass / 2), so the halves are independent and the noise estimate of an even
    // pass count is unbiased (render/NoiseEstimate.h). One sequence over all passes stratifies
    // better: a smooth scene's image is then better than its halves predict, and the estimate
    // conservative (by about 2 on a lit sphere). Set it where the estimate decides.
    bool independentHalves = false;
    const std::atomic<bool>* cancel = nullptr;  // checked between tiles
    // After each complete pass (progress, live previews), on the thread that called render().
    std::function<void(const PassReport&)> passDone;
};

// What ended a render: its last pass (spp or endPass), timeLimit, noiseTarget, or the cancel flag.
enum class RenderStop { Passes, Time, Noise, Cancelled };

struct RenderResult {
    RenderStop stop = RenderStop::Passes;
    Image image;
    Film film{0, 0};  // the exact sums behind `image`, for partial renders
    int passes = 0;   // complete passes (samples per pixel; with noiseTarget, the most a pixel took)
    bool cancelled = false;
    uint64_t droppedSamples = 0;  // NaN or Inf radiance, discarded
    double seconds = 0;
    std::optional<double> noise;  // the last complete pass's estimate
    double neededPasses = 0;      // noiseTarget: as in PassReport
};

// Pixel (x, y) in pass s uses Rng::pixelSample(seed, pixel index, s) only (or its half's seed and
// s / 2, independentHalves), and takes pass s when its tile's budget has it, so the image is the
// same for any thread count and any tile schedule; the first numbers it draws (the point in the
// pixel, then the path's) are stratified over the passes.
RenderResult render(const Scene& scene, Integrator& integrator, const RenderOptions& options);

}  // namespace tetglow
