// Kernels of the exact boundary: tet steps, full ray walks against Embree, point location
// along a path against the parity test. Usage: tetglow_bench [benchmark flags] [MESH.obj]
#include <cmath>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "tet/Tetrahedralizer.h"
#include "tet/TetVolume.h"

namespace tetglow {
namespace {

std::string gMeshPath = std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/fish.obj";

struct Fixture {
    std::unique_ptr<TetVolume> volume;
    std::vector<Ray> rays;                        // each crosses the medium
    std::vector<uint32_t> entries;                // Embree's entry triangle per ray
    std::vector<std::vector<glm::dvec3>> paths;   // ray-march sample points, inside and outside
    std::vector<std::vector<glm::dvec3>> inside;  // the samples of each path inside the medium
    double spacing = 0;                           // between samples, in t
};

const Fixture& fixture() {
    static const Fixture f = [] {
        Fixture f;
        f.volume = std::make_unique<TetVolume>(tetrahedralize(readMesh(gMeshPath)));
        Bounds3 b;
        for (const auto& v : f.volume->mesh().vertices) b.extend(v);
        const double diag = b.diagonal();
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> u(0, 1);
        while (f.rays.size() < 4096) {
            const glm::dvec3 target = b.lo + (b.hi - b.lo) * glm::dvec3(u(rng), u(rng), u(rng));
            const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), s = std::sqrt(1 - z * z);
            const glm::dvec3 d(s * std::cos(phi), s * std::sin(phi), z);
            const Ray ray{target - d * diag, d};
            auto hit = f.volume->bvh().intersect(ray, 0, INFINITY, Facing::Entering);
            if (!hit) continue;
            f.rays.push_back(ray);
            f.entries.push_back(hit->triangle);
            std::vector<glm::dvec3> path, in;  // the seed's ray march: 200 steps across the box
            f.spacing = 2 * diag / 200;
            for (int k = 0; k < 200; ++k) {
                path.push_back(ray.at((k + 0.5) * f.spacing));
                if (f.volume->locate(path.back()) >= 0) in.push_back(path.back());
            }
            f.paths.push_back(std::move(path));
            if (!in.empty()) f.inside.push_back(std::move(in));
        }
        return f;
    }();
    return f;
}

void BM_TetSteps(benchmark::State& state) {
    const Fixture& f = fixture();
    size_t steps = 0, i = 0;
    for (auto _ : state) {
        const size_t r = i++ % f.rays.size();
        TetWalk w = TetWalk::enter(f.volume->mesh(), f.rays[r], f.entries[r]);
        WalkSegment s;
        while (w.next(s)) benchmark::DoNotOptimize(s);
        steps += w.steps();
    }
    state.counters["steps/s"] = benchmark::Counter(double(steps), benchmark::Counter::kIsRate);
    state.counters["steps/walk"] = double(steps) / double(state.iterations());
}
BENCHMARK(BM_TetSteps);

void BM_RayWalkFull(benchmark::State& state) {
    // Embree finds the entry, the tets do the rest (re-entry through concavities via Embree).
    const Fixture& f = fixture();
    size_t i = 0;
    for (auto _ : state) {
        double length = 0;
        f.volume->traverse(f.rays[i++ % f.rays.size()], 0, INFINITY,
                           [&](const WalkSegment& s) { return length += s.tOut - s.tIn, true; }, TetVolume::kOutside);
        benchmark::DoNotOptimize(length);
    }
    state.counters["rays/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RayWalkFull);

void BM_EmbreeEntryExit(benchmark::State& state) {
    // The baseline: Embree alone finding every boundary crossing of the same rays (no per-tet
    // segments, which the renderer needs for heterogeneous media).
    const Fixture& f = fixture();
    size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(f.volume->bvh().allHits(f.rays[i++ % f.rays.size()]));
    state.counters["rays/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EmbreeEntryExit);

void BM_LocateAlongPath(benchmark::State& state) {
    // The ray march's inside test with tets: walk the ray once, then each sample's tet is the
    // segment holding it (-1 between segments). The walk's cost is included.
    const Fixture& f = fixture();
    size_t i = 0, points = 0;
    std::vector<WalkSegment> segments;
    for (auto _ : state) {
        const size_t r = i++ % f.rays.size();
        const Ray& ray = f.rays[r];
        segments.clear();
        f.volume->traverse(ray, 0, INFINITY, [&](const WalkSegment& s) { return segments.push_back(s), true; },
                           TetVolume::kOutside);
        size_t k = 0;
        for (int j = 0; j < 200; ++j) {
            const double t = (j + 0.5) * f.spacing;
            while (k < segments.size() && segments[k].tOut < t) ++k;
            benchmark::DoNotOptimize(k < segments.size() && segments[k].tIn <= t ? int64_t(segments[k].tet) : -1);
        }
        points += 200;
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
    state.counters["bytes/tet"] = double(f.volume->mesh().bytesPerTet());
}
BENCHMARK(BM_LocateAlongPath);

void BM_LocateWithHint(benchmark::State& state) {
    // Point location by visibility walk from the previous sample's tet, for the samples inside.
    const Fixture& f = fixture();
    size_t i = 0, points = 0;
    for (auto _ : state) {
        const auto& path = f.inside[i++ % f.inside.size()];
        int64_t hint = -1;
        for (const auto& p : path) benchmark::DoNotOptimize(hint = f.volume->locate(p, hint));
        points += path.size();
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LocateWithHint);

void BM_ParityAlongPath(benchmark::State& state) {
    const Fixture& f = fixture();
    const int rays = int(state.range(0));
    size_t i = 0, points = 0;
    for (auto _ : state) {
        for (const auto& p : f.paths[i++ % f.paths.size()]) benchmark::DoNotOptimize(insideByParity(f.volume->bvh(), p, rays));
        points += 200;
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ParityAlongPath)->Arg(1)->Arg(3)->Arg(5);

}  // namespace
}  // namespace tetglow

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (argc > 1) tetglow::gMeshPath = argv[1];
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
