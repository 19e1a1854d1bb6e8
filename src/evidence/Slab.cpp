#include "evidence/Slab.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "base/Error.h"
#include "photon/PhotonWalk.h"
#include "tet/Shapes.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {

namespace {

// Per-photon fractions of the incident flux, summed over a block of photons.
struct Sums {
    double value[4] = {}, square[4] = {};  // reflected, transmitted, absorbed, lost sideways
    void add(const double (&x)[4]) {
        for (int k = 0; k < 4; ++k) value[k] += x[k], square[k] += x[k] * x[k];
    }
    void add(const Sums& o) {
        for (int k = 0; k < 4; ++k) value[k] += o.value[k], square[k] += o.square[k];
    }
};

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

Tally tally(double sum, double sumSquares, double n) {
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / (n - 1))};
}

}  // namespace

SlabResult simulateSlab(const SlabParams& p) {
    if (!(p.tau > 0) || !std::isfinite(p.tau)) throw InputError("slab: --tau must be a finite number > 0");
    if (!(p.albedo >= 0 && p.albedo <= 1)) throw InputError("slab: --albedo must be in [0, 1]");
    if (!(p.g > -1 && p.g < 1)) throw InputError("slab: --g must be in (-1, 1)");
    if (p.photons < 2) throw InputError("slab: --photons must be at least 2");
    const auto start = std::chrono::steady_clock::now();

    TetOptions options;
    options.useCache = false;
    // One unit thick (z from -1 to 0) and wide enough that photons leaving through the sides
    // are a negligible fraction (they are counted apart, as `lost`).
    const double width = 200;
    const TriangleMesh slab = box({-width / 2, -width / 2, -1}, {width / 2, width / 2, 0});
    const Volume volume({RGB(p.tau * (1 - p.albedo)), RGB(p.tau * p.albedo), p.g, RGB(0)},
                        tetrahedralize(slab, options));
    const TetMesh& mesh = volume.mesh();
    // The lit face is z = 0; entry triangles are found once by Embree, then each photon's walk
    // starts there. Entry points are spread over the middle of the face (the slab is
    // translation invariant), away from its diagonal.
    const SurfaceBVH& bvh = volume.traversal().bvh();

    constexpr uint64_t kBlock = 4096;
    // Blocks are summed in order, so the sum is the same for any thread count; a few hundred at
    // a time, so that 2^40 photons do not need 2^28 block sums in memory at once, and progress
    // is reported every million photons.
    constexpr uint64_t kBlocksAtOnce = 256;
    const uint64_t blocks = (p.photons + kBlock - 1) / kBlock;
    std::vector<Sums> blockSums(std::min(blocks, kBlocksAtOnce));
    Sums total;
    std::atomic<bool> stuck{false}, late{false};
    std::atomic<uint64_t> traced{0};
    const auto pastTime = [&] {
        return p.timeLimit > 0 &&
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > p.timeLimit;
    };
    tbb::task_arena arena(p.threads > 0 ? p.threads : tbb::task_arena::automatic);
    for (uint64_t first = 0; first < blocks && !stuck && !late; first += kBlocksAtOnce) {
        const uint64_t count = std::min(kBlocksAtOnce, blocks - first);
        std::fill(blockSums.begin(), blockSums.end(), Sums{});
        arena.execute([&] {
            tbb::parallel_for(first, first + count, [&](uint64_t b) {
                for (uint64_t i = b * kBlock; i < std::min(p.photons, (b + 1) * kBlock); ++i) {
                    if (stuck || late) return;
                    if (pastTime()) return void(late = true);  // per photon: one may take 2^20 events
                    Rng rng(p.seed, i);
                    const double x = (rng.uniform() - 0.5) * 0.1 * width, y = (rng.uniform() - 0.5) * 0.1 * width;
                    const Ray ray{{x, y, 1}, {0, 0, -1}};
                    const auto entry = bvh.intersect(ray, 0, INFINITY, Facing::Entering);
                    double x4[4] = {};
                    if (entry) {
                        SpectralPath path(0);
                        const WalkResult r = photonWalk(
                            volume, Ray{ray.at(entry->t), ray.d}, WalkStart::surface(entry->triangle), RGB(1), path,
                            rng, kMaxSlabEvents, [](const Ray&) { return INFINITY; }, [](const PhotonEvent&) {});
                        if (r.events >= kMaxSlabEvents) stuck = true;
                        x4[2] = r.absorbedFlux.x;
                        if (r.exit.left) {
                            const double nz = glm::normalize(bvh.normal(r.exit.triangle)).z, w = path.weight().x;
                            x4[nz > 0.5 ? 0 : nz < -0.5 ? 1 : 3] = w;
                        }
                    }
                    blockSums[b - first].add(x4);
                    ++traced;
                }
            });
        });
        for (uint64_t b = 0; b < count; ++b) total.add(blockSums[b]);
        if (p.progress)
            p.progress(traced.load(), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    if (stuck)
        throw InputError("slab: a photon scattered " + std::to_string(kMaxSlabEvents) +
                         " times without leaving or being absorbed (--tau " + number(p.tau) + ", --albedo " +
                         number(p.albedo) + ", --g " + number(p.g) + "): too thick to simulate; use a smaller --tau");
    if (late)
        throw InputError("slab: " + std::to_string(traced.load()) + " of " + std::to_string(p.photons) +
                         " photons traced in --time " + number(p.timeLimit) + " s: ask for fewer photons or more time");
    SlabResult result;
    const double n = double(p.photons);
    result.reflectance = tally(total.value[0], total.square[0], n);
    result.transmittance = tally(total.value[1], total.square[1], n);
    result.absorbed = tally(total.value[2], total.square[2], n);
    result.lost = tally(total.value[3], total.square[3], n);
    result.tets = mesh.tets.size();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace tetglow
