#include "render/Renderer.h"

#include <chrono>

#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "base/Memory.h"
#include "render/NoiseEstimate.h"

namespace tetglow {
namespace {

// The sequence a pass's samples come from, and their index in it.
struct PassSequence {
    uint64_t seed;
    uint32_t index;
};

PassSequence passSequence(const RenderOptions& options, int pass) {
    if (!options.independentHalves) return {options.seed, uint32_t(pass)};
    return {inFirstHalf(pass) ? options.seed : mixBits(options.seed ^ 0x6a09e667f3bcc909ull), uint32_t(pass / 2)};
}

}  // namespace

RenderResult render(const Scene& scene, Integrator& integrator, const RenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const Camera& camera = scene.camera();
    // The film and its first half-image, the image made from it and the PNG preview's bytes.
    checkMemory(double(camera.width()) * camera.height() * 2 *
                    (sizeof(FixedSum) + 3 * sizeof(uint32_t) + sizeof(glm::vec3) + 3),
                "an image of " + std::to_string(camera.width()) + "x" + std::to_string(camera.height()) + " pixels");
    Film film(camera.width(), camera.height()), half(camera.width(), camera.height());
    RenderResult result;
    const int endPass = options.endPass > 0 ? options.endPass : options.spp;
    auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    for (int pass = options.firstPass; pass < endPass && !cancelled(); ++pass) {
        if (pass > options.firstPass && options.timeLimit > 0 && elapsed() >= options.timeLimit) {
            result.stop = RenderStop::Time;
            break;
        }
        const PassSequence sequence = passSequence(options, pass);
        arena.execute([&] {
            integrator.beginPass(uint64_t(pass), options.cancel);
            tbb::parallel_for(
                tbb::blocked_range2d<int>(0, camera.height(), 16, 0, camera.width(), 16), [&](const auto& tile) {
                    if (cancelled()) return;
                    for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                        for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                            // The pass is the sample's index in the pixel's sequence: passes stratify.
                            Rng rng = Rng::pixelSample(sequence.seed, uint64_t(y) * camera.width() + x, sequence.index);
                            const double jx = rng.uniform(), jy = rng.uniform();
                            const RGB L = integrator.radiance(camera.generateRay(x + jx, y + jy), rng);
                            film.add(x, y, L);
                            if (inFirstHalf(pass)) half.add(x, y, L);
                        }
                });
        });
        if (cancelled()) break;
        result.passes = pass + 1 - options.firstPass;
        result.noise = estimateRelMse(film, half);
        if (options.passDone) options.passDone({film, result.passes, elapsed(), result.noise});
        if (options.noiseTarget > 0 && result.passes >= kMinNoisePasses && !inFirstHalf(pass) && result.noise &&
            *result.noise <= options.noiseTarget) {
            result.stop = RenderStop::Noise;
            break;
        }
    }
    result.cancelled = cancelled();
    if (result.cancelled) result.stop = RenderStop::Cancelled;
    result.image = film.image();
    result.droppedSamples = film.droppedSamples();
    result.film = std::move(film);
    result.seconds = elapsed();
    return result;
}

}  // namespace tetglow
