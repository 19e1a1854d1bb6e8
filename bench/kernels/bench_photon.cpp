// Photon map queries: k-NN and fixed-radius lookups, and beam queries over photon discs, on
// photons uniform in the unit cube; and photon paths traced through the demo fish scene.
// main() is in bench_tet.cpp.
#include <cmath>
#include <map>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "photon/PhotonDiscs.h"
#include "photon/PhotonMap.h"
#include "photon/PhotonTracer.h"
#include "scene/SceneLoader.h"

namespace tetglow {
namespace {

constexpr size_t kQueryPoints = 4096;

std::vector<glm::vec3> uniformPoints(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<glm::vec3> points(n);
    for (auto& p : points) p = {u(rng), u(rng), u(rng)};
    return points;
}

// One map per size, built on first use.
const PhotonMap& photonMap(size_t n) {
    static std::map<size_t, std::unique_ptr<PhotonMap>> maps;
    auto& map = maps[n];
    if (!map) {
        std::vector<Photon> photons;
        photons.reserve(n);
        for (const auto& p : uniformPoints(n, n)) photons.push_back({p, glm::vec3(1), 0, 0});
        map = std::make_unique<PhotonMap>(std::move(photons));
    }
    return *map;
}

void BM_PhotonKnn(benchmark::State& state) {
    const PhotonMap& map = photonMap(size_t(state.range(0)));
    const std::vector<glm::vec3> queries = uniformPoints(kQueryPoints, 1);
    std::vector<Neighbour> out;
    size_t i = 0;
    for (auto _ : state) {
        map.knn(queries[i++ % kQueryPoints], 50, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
    state.counters["bytes/photon"] = double(map.bytes()) / double(map.size());
}
BENCHMARK(BM_PhotonKnn)->Arg(100000)->Arg(1000000);

void BM_PhotonRadius(benchmark::State& state) {
    // The radius whose ball holds 50 photons on average, as the k-NN benchmark finds.
    const size_t n = size_t(state.range(0));
    const PhotonMap& map = photonMap(n);
    const float radius = float(std::cbrt(3 * 50 / (4 * M_PI * double(n))));
    const std::vector<glm::vec3> queries = uniformPoints(kQueryPoints, 2);
    std::vector<Neighbour> out;
    size_t i = 0, found = 0;
    for (auto _ : state) {
        map.withinRadius(queries[i++ % kQueryPoints], radius, out);
        found += out.size();
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
    state.counters["photons/query"] = double(found) / double(state.iterations());
}
BENCHMARK(BM_PhotonRadius)->Arg(100000)->Arg(1000000);

void BM_PhotonBeams(benchmark::State& state) {
    // Rays from a sphere around the cloud towards random points inside it.
    static const PhotonDiscs beams = [] {
        PhotonMap map(photonMap(100000).photons());
        map.assignRadii(20, 0.1f);
        return PhotonDiscs(map.photons());
    }();
    std::vector<glm::dvec3> origins, directions;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    const glm::dvec3 centre(0.5);
    for (size_t k = 0; k < kQueryPoints; ++k) {
        const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), s = std::sqrt(1 - z * z);
        origins.push_back(centre + 1.5 * glm::dvec3(s * std::cos(phi), s * std::sin(phi), z));
        directions.push_back(glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) - origins.back()));
    }
    size_t i = 0, discs = 0;
    for (auto _ : state) {
        const size_t r = i++ % kQueryPoints;
        double sum = 0;
        beams.query(origins[r], directions[r], 0, INFINITY, [&](uint32_t, double t, double distance2) {
            sum += t + distance2;
            ++discs;
        });
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
    state.counters["discs/ray"] = double(discs) / double(state.iterations());
}
BENCHMARK(BM_PhotonBeams);

// Photon paths from every emitter of scenes/fish.json (spot disk, environment, the glowing
// medium) through the glass skin, the medium and off the floor, on all cores.
void BM_TracePhotons(benchmark::State& state) {
    static const Scene scene(loadScene(TETGLOW_SOURCE_DIR "/scenes/fish.json"));
    static const PhotonSource source(scene);
    const uint64_t paths = 100000;
    uint64_t pass = 0, stored = 0;
    for (auto _ : state) {
        const TracedPhotons traced = tracePhotons(scene, source, {paths, 64, 1, pass++});
        stored += traced.volume[0].size() + traced.surface.size();
    }
    state.SetItemsProcessed(int64_t(state.iterations() * paths));
    state.counters["stored_per_path"] = double(stored) / double(state.iterations() * paths);
}
BENCHMARK(BM_TracePhotons)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tetglow
