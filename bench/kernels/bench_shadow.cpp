// Kernels of shadow rays and free flights from interior points of a homogeneous medium: the
// transmittance to the boundary, shadowFlight (with Russian roulette) in a dense medium, with and
// without the tests its ball clear of the boundary makes certain decided first, and
// sampleFlight walked or jumping to its interaction. For the exit kernels the argument is the number
// of tets walked before the region's exit is asked of the surface BVH (0: walk every tet, the
// behaviour before the exit query), so one run measures before and after. Each reports its rays
// per second, the tet steps a ray takes and skips (against the walk), and the steps per second
// that rate stands for. Mesh:
// TETGLOW_SHADOW_MESH, else blub (../shared/meshes), else the demo fish.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "../../tests/ExitQueryAccess.h"
#include "media/ShadowRay.h"
#include "media/Volume.h"
#include "scene/MeshFile.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

struct ShadowFixture {
    std::unique_ptr<Volume> volume;
    double diagonal = 0;
    std::vector<Ray> rays;       // from located interior points, unit directions
    std::vector<uint32_t> tets;  // holding each ray's origin
    std::vector<size_t> steps;   // each ray's tet steps to the boundary
    double stepsPerLength = 0;   // the walk's steps over the distance they cover, all rays together
};

std::string shadowMesh() {
    if (const char* path = std::getenv("TETGLOW_SHADOW_MESH")) return path;
    const std::string blub = std::string(TETGLOW_SOURCE_DIR) + "/../shared/meshes/blub.obj";
    return std::filesystem::exists(blub) ? blub : std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/fish.obj";
}

ShadowFixture& shadowFixture() {
    static ShadowFixture f = [] {
        ShadowFixture f;
        f.volume = std::make_unique<Volume>(MediumParams{}, tetrahedralize(readMesh(shadowMesh())));
        const Bounds3& box = f.volume->traversal().bounds();
        f.diagonal = box.diagonal();
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> u(0, 1);
        std::normal_distribution<double> n;
        double length = 0;
        while (f.rays.size() < 4096) {
            const glm::dvec3 p = box.lo + (box.hi - box.lo) * glm::dvec3(u(rng), u(rng), u(rng));
            const int64_t t = f.volume->traversal().locate(p);
            if (t < 0) continue;
            const glm::dvec3 d(n(rng), n(rng), n(rng));
            f.rays.push_back({p, d / glm::length(d)});
            f.tets.push_back(uint32_t(t));
            size_t steps = 0;
            double end = 0;
            f.volume->walk(f.rays.back(), WalkStart::inside(uint32_t(t)), [&](const WalkSegment& s) {
                end = s.tOut;
                return ++steps;
            });
            f.steps.push_back(steps);
            length += end;
        }
        size_t steps = 0;
        for (size_t s : f.steps) steps += s;
        f.stepsPerLength = double(steps) / length;
        return f;
    }();
    return f;
}

// The steps the rays take with the exit asked after `after` steps: all of them where no query
// was made (surfaceQueries), `after` where one was. A walk that goes on after an unsure query
// counts as skipping: those are about 1 in 200 on blub (RegionExit.IsTheWalksExitInReferenceMeshes).
void countSteps(benchmark::State& state, ShadowFixture& f, size_t after, size_t rays, const auto& trace) {
    double walked = 0, taken = 0;
    for (size_t i = 0; i < f.rays.size(); ++i) {
        const uint64_t queries = surfaceQueries();
        trace(i);
        walked += double(f.steps[i]);
        taken += double(surfaceQueries() > queries ? std::min(after, f.steps[i]) : f.steps[i]);
    }
    const double n = double(f.rays.size());
    state.counters["walk steps/ray"] = walked / n;
    state.counters["walk steps/length"] = f.stepsPerLength;  // per unit of the mesh's length
    state.counters["steps/ray"] = taken / n;
    state.counters["skipped/ray"] = (walked - taken) / n;
    state.counters["steps/s"] = benchmark::Counter(double(rays) * taken / n, benchmark::Counter::kIsRate);
}

// Scattering only, sigma_t = 1 / (mean free path).
void setMeanFreePath(ShadowFixture& f, double path) {
    MediumParams p;
    p.sigmaS = RGB(1 / path);
    f.volume->setRegions(
        std::vector<MediumField>(std::max<size_t>(1, f.volume->mesh().regionCount()), MediumField{p, {}}));
}

// Transmittance to the boundary (transmittance), mean free path the box's diagonal.
void BM_ShadowExit(benchmark::State& state) {
    ShadowFixture& f = shadowFixture();
    setMeanFreePath(f, f.diagonal);
    ExitQueryAccess::setExitQueryAfter(*f.volume, size_t(state.range(0)));
    size_t rays = 0;
    for (auto _ : state) {
        const size_t i = rays++ % f.rays.size();
        benchmark::DoNotOptimize(transmittance(*f.volume, f.rays[i], WalkStart::inside(f.tets[i]), INFINITY));
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    countSteps(state, f, size_t(state.range(0)), rays, [&](size_t i) {
        benchmark::DoNotOptimize(transmittance(*f.volume, f.rays[i], WalkStart::inside(f.tets[i]), INFINITY));
    });
}
BENCHMARK(BM_ShadowExit)->Arg(0)->Arg(1)->Arg(2)->Arg(4)->Arg(8);

// shadowFlight in a dense medium (mean free path 1% of the diagonal, as jade): roulette ends
// most rays after a few tets, where one query may cost more than the steps it saves.
void BM_DenseShadowExit(benchmark::State& state) {
    ShadowFixture& f = shadowFixture();
    setMeanFreePath(f, 0.01 * f.diagonal);
    ExitQueryAccess::setExitQueryAfter(*f.volume, size_t(state.range(0)));
    Rng rng(1, 2);
    size_t rays = 0;
    for (auto _ : state) {
        const size_t i = rays++ % f.rays.size();
        benchmark::DoNotOptimize(shadowFlight(*f.volume, f.rays[i], WalkStart::inside(f.tets[i]), INFINITY, rng));
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DenseShadowExit)->Arg(0)->Arg(1)->Arg(2)->Arg(4)->Arg(8);

// The same shadow rays as the next-event estimation's transmittance starts them, argument 1: the
// roulette's tests that the ray's ball clear of the boundary makes certain (sureDepth) decided
// before any walk; 0: each decided where the walk reaches it, as before. Reports the share of
// rays that end before walking a tet.
void BM_DenseShadowSure(benchmark::State& state) {
    ShadowFixture& f = shadowFixture();
    setMeanFreePath(f, 0.01 * f.diagonal);
    ExitQueryAccess::setExitQueryAfter(*f.volume, 1);
    const bool sure = state.range(0) == 1;
    Rng rng(1, 2);
    size_t rays = 0, unwalked = 0;
    for (auto _ : state) {
        const size_t i = rays++ % f.rays.size();
        const WalkStart start = WalkStart::inside(f.tets[i]);
        ShadowRoulette roulette;
        if (sure && !roulette.reach(sureDepth(*f.volume, start, f.rays[i].o, INFINITY), rng)) {
            ++unwalked;
            continue;
        }
        benchmark::DoNotOptimize(shadowFlight(*f.volume, f.rays[i], start, INFINITY, rng, roulette));
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["unwalked"] = double(unwalked) / double(std::max<size_t>(1, rays));
}
BENCHMARK(BM_DenseShadowSure)->Arg(0)->Arg(1);

// Free flights (sampleFlight, the volpath integrator's), first argument 0: walked tet by tet, 1:
// jumping to the interaction where the region's exit query is worth it. Second argument: the mean
// free path in mean tet steps (blub's is about 30, the sphere scene's 12, jade's 1).
void BM_FreeFlight(benchmark::State& state) {
    ShadowFixture& f = shadowFixture();
    setMeanFreePath(f, double(state.range(1)) / f.stepsPerLength);
    const bool jump = state.range(0) == 1;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0, 1);
    std::vector<double> u(f.rays.size());
    for (double& x : u) x = u01(rng);
    auto flight = [&](size_t i) {
        return sampleFlight(*f.volume, f.rays[i], WalkStart::inside(f.tets[i]), INFINITY, 0, u[i], RGB(1), jump);
    };
    size_t flights = 0;
    for (auto _ : state) {
        const size_t i = flights++ % f.rays.size();
        benchmark::DoNotOptimize(flight(i));
    }
    state.counters["flights/s"] = benchmark::Counter(double(flights), benchmark::Counter::kIsRate);
    // Steps: those of the walk to the interaction (or the boundary), none where a query decided
    // (a walk after an unsure query, about 1 in 200, counts as skipping).
    double walked = 0, taken = 0;
    for (size_t i = 0; i < f.rays.size(); ++i) {
        const uint64_t queries = surfaceQueries();
        const FreeFlight fl = flight(i);
        // A query decided the flight unless the walk placed its interaction (a located tet).
        const bool decided = surfaceQueries() > queries && !(fl.scattered && fl.located);
        const double end = fl.scattered ? fl.t : INFINITY;
        size_t steps = 0;
        f.volume->walk(f.rays[i], WalkStart::inside(f.tets[i]), [&](const WalkSegment& s) {
            ++steps;
            return s.tOut < end;
        });
        walked += double(steps);
        taken += decided ? 0.0 : double(steps);
    }
    const double n = double(f.rays.size());
    state.counters["walk steps/flight"] = walked / n;
    state.counters["steps/flight"] = taken / n;
    state.counters["skipped/flight"] = (walked - taken) / n;
    state.counters["steps/s"] = benchmark::Counter(double(flights) * taken / n, benchmark::Counter::kIsRate);
    // The walk's steps the flights cover per second, taken or skipped: the walk's own rate for comparison.
    state.counters["covered/s"] = benchmark::Counter(double(flights) * walked / n, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FreeFlight)->ArgsProduct({{0, 1}, {1, 12, 30}});

}  // namespace
}  // namespace tetglow
