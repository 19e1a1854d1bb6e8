#include "render/Renderer.h"

#include <chrono>

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "base/Memory.h"
#include "render/AdaptiveSampling.h"
#include "render/NoiseEstimate.h"

namespace tetglow {
namespace {

// The sequence a pass's samples come from, and their index in it.
struct PassSequence {
    uint64_t seed;
    uint32_t index;
};

PassSequence passSequence(const RenderOptions& options, int pass) {
    if (!options.independentHalves && options.noiseTarget <= 0) return {options.seed, uint32_t(pass)};
    return {inFirstHalf(pass) ? options.seed : mixBits(options.seed ^ 0x6a09e667f3bcc909ull), uint32_t(pass / 2)};
}

}  // namespace

RenderResult render(const Scene& scene, Integrator& integrator, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const Camera& camera = scene.camera();
    const int endPass = options.endPass > 0 ? options.endPass : options.spp;
    // Adaptive: every pixel takes the pilot's passes, then its tile's budget. A part that starts
    // after pass 0 renders the pilot's earlier passes too, into a film of its own, to plan the
    // same budgets as the whole render; it keeps only its own passes' samples.
    const int pilotEnd = options.noiseTarget > 0 && options.spp > kPilotPasses ? kPilotPasses : 0;
    const bool replaysPilot = options.firstPass > 0 && options.firstPass < endPass && pilotEnd > 0;
    // The film and its first half-image (and the pilot's pair), the image made from it and the
    // PNG preview's bytes.
    checkMemory(double(camera.width()) * camera.height() * (replaysPilot ? 4 : 2) *
                    (sizeof(FixedSum) + 3 * sizeof(uint32_t) + sizeof(glm::vec3) + 3),
                "an image of " + std::to_string(camera.width()) + "x" + std::to_string(camera.height()) + " pixels");
    Film film(camera.width(), camera.height()), half(camera.width(), camera.height());
    Film pilot(replaysPilot ? camera.width() : 0, replaysPilot ? camera.height() : 0), pilotHalf = pilot;
    SampleBudget budget;
    RenderResult result;
    auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    for (int pass = replaysPilot ? 0 : options.firstPass; pass < endPass && !cancelled(); ++pass) {
        if (pass == pilotEnd && pilotEnd > 0) {
            budget = replaysPilot ? SampleBudget::plan(pilot, pilotHalf, pilotEnd, options.noiseTarget, options.spp)
                                  : SampleBudget::plan(film, half, pilotEnd, options.noiseTarget, options.spp);
            pass = std::max(pass, options.firstPass);  // a part after the pilot goes on at its own passes
        }
        if (budget.planned() && pass >= budget.mostPasses()) break;
        if (pass > options.firstPass && options.timeLimit > 0 && elapsed() >= options.timeLimit) {
            result.stop = RenderStop::Time;
            break;
        }
        const bool kept = pass >= options.firstPass, toPilot = replaysPilot && pass < pilotEnd;
        const PassSequence sequence = passSequence(options, pass);
        arena.execute([&] {
            integrator.beginPass(uint64_t(pass), options.cancel);
            tbb::parallel_for(
                tbb::blocked_range2d<int>(0, camera.height(), 16, 0, camera.width(), 16), [&](const auto& tile) {
                    if (cancelled()) return;
                    for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                        for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                            if (!budget.takes(x, y, pass)) continue;
                            // The pass is the sample's index in the pixel's sequence: passes stratify.
                            Rng rng = Rng::pixelSample(sequence.seed, uint64_t(y) * camera.width() + x, sequence.index);
                            const double jx = rng.uniform(), jy = rng.uniform();
                            const RGB L = integrator.radiance(camera.generateRay(x + jx, y + jy), rng);
                            if (kept) {
                                film.add(x, y, L);
                                if (inFirstHalf(pass)) half.add(x, y, L);
                            }
                            if (toPilot) {
                                pilot.add(x, y, L);
                                if (inFirstHalf(pass)) pilotHalf.add(x, y, L);
                            }
                        }
                });
        });
        if (cancelled() || !kept) continue;
        result.passes = pass + 1 - options.firstPass;
        result.noise = estimateRelMse(film, half);
        if (options.passDone) options.passDone({film, result.passes, elapsed(), result.noise, budget.neededPasses()});
    }
    result.cancelled = cancelled();
    if (result.cancelled)
        result.stop = RenderStop::Cancelled;
    else if (result.stop != RenderStop::Time && budget.planned() && budget.mostPasses() <= endPass &&
             budget.neededPasses() <= options.spp)
        result.stop = RenderStop::Noise;  // every tile took the passes its target needs
    result.neededPasses = budget.neededPasses();
    result.image = film.image();
    result.droppedSamples = film.droppedSamples();
    result.film = std::move(film);
    result.seconds = elapsed();
    return result;
}

}  // namespace tetglow
