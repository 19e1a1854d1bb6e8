// Kernels of the exact boundary: tet steps, full ray walks against Embree, point location
// along a path against the parity test. Usage: tetglow_bench [benchmark flags] [MESH.obj]
#include <cmath>
#include <memory>
#include <random>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include "scene/MeshFile.h"
#include "tet/TetTraversal.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow {
namespace {

std::string gMeshPath = std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/fish.obj";

struct Fixture {
    std::unique_ptr<TetTraversal> volume;
    Bounds3 box;                                  // of the medium: the parity baseline's march samples only inside it
    std::vector<Ray> rays;                        // each crosses the medium
    std::vector<uint32_t> entries;                // Embree's entry triangle per ray
    std::vector<double> t0, t1;                   // each ray's stretch in the box
    std::vector<std::vector<glm::dvec3>> inside;  // march samples (step diagonal / 100) inside the medium
};

// The parity baseline's ray march along ray r: sample k at t0 + (k + 0.5) step, for the samples inside the box.
size_t marchSamples(const Fixture& f, size_t r, double step) {
    return size_t(std::max(0.0, std::ceil((f.t1[r] - f.t0[r]) / step - 0.5)));
}
double marchT(const Fixture& f, size_t r, size_t k, double step) { return f.t0[r] + (double(k) + 0.5) * step; }

const Fixture& fixture() {
    static const Fixture f = [] {
        Fixture f;
        f.volume = std::make_unique<TetTraversal>(tetrahedralize(readMesh(gMeshPath)));
        for (const auto& v : f.volume->mesh().vertices) f.box.extend(v);
        const double diag = f.box.diagonal();
        std::mt19937_64 rng(1);
        std::uniform_real_distribution<double> u(0, 1);
        while (f.rays.size() < 4096) {
            const glm::dvec3 target = f.box.lo + (f.box.hi - f.box.lo) * glm::dvec3(u(rng), u(rng), u(rng));
            const double z = 2 * u(rng) - 1, phi = 2 * M_PI * u(rng), s = std::sqrt(1 - z * z);
            const glm::dvec3 d(s * std::cos(phi), s * std::sin(phi), z);
            const Ray ray{target - d * diag, d};
            auto hit = f.volume->bvh().intersect(ray, 0, INFINITY, Facing::Entering);
            double t0 = 0, t1 = INFINITY;
            if (!hit || !clip(f.box, ray, t0, t1)) continue;
            f.rays.push_back(ray);
            f.entries.push_back(hit->triangle);
            f.t0.push_back(t0);
            f.t1.push_back(t1);
            const size_t r = f.rays.size() - 1;
            std::vector<glm::dvec3> in;
            for (size_t k = 0, n = marchSamples(f, r, diag / 100); k < n; ++k)
                if (const glm::dvec3 p = ray.at(marchT(f, r, k, diag / 100)); f.volume->locate(p) >= 0) in.push_back(p);
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

// The showcase fish against the old one in one run: the same body alone (Arg 0), and
// with its photophores, eyes and lure core nested in it (Arg 1), one tet mesh with a region each.
// The same rays as above (the fixture's, which cross the body), walked across every interface.
void BM_TetStepsAcrossRegions(benchmark::State& state) {
    const Fixture& f = fixture();
    static std::unique_ptr<TetTraversal> volumes[2];
    static std::vector<uint32_t> entries[2];  // each volume's own entry triangles for the rays
    auto& volume = volumes[state.range(0)];
    if (!volume) {
        const std::string dir = std::string(TETGLOW_SOURCE_DIR) + "/scenes/meshes/";
        std::vector<TriangleMesh> meshes{readMesh(dir + "fish.obj")};
        std::vector<std::string> names{"fish"};
        if (state.range(0) == 1)
            for (const std::string part : {"fish-photophores", "fish-eyes", "fish-lure-core"}) {
                meshes.push_back(readMesh(dir + part + ".obj"));
                names.push_back(part);
            }
        volume = std::make_unique<TetTraversal>(tetrahedralize(meshes, names, TetOptions{}));
        for (const Ray& ray : f.rays)
            entries[state.range(0)].push_back(volume->bvh().intersect(ray, 0, INFINITY, Facing::Entering)->triangle);
    }
    size_t steps = 0, interfaces = 0, i = 0;
    double length = 0;  // the same for both: the organs only split the body's chords
    for (auto _ : state) {
        const size_t r = i++ % f.rays.size();
        TetWalk w = TetWalk::enter(volume->mesh(), f.rays[r], entries[state.range(0)][r]);
        WalkSegment s;
        do
            while (w.next(s)) length += s.tOut - s.tIn;
        while (w.crossInterface() && ++interfaces);
        steps += w.steps();
    }
    state.counters["steps/s"] = benchmark::Counter(double(steps), benchmark::Counter::kIsRate);
    state.counters["steps/walk"] = double(steps) / double(state.iterations());
    state.counters["interfaces/walk"] = double(interfaces) / double(state.iterations());
    state.counters["length/walk"] = length / double(state.iterations());
    state.counters["tets"] = double(volume->mesh().tets.size());
}
BENCHMARK(BM_TetStepsAcrossRegions)->Arg(0)->Arg(1);

void BM_RayWalkFull(benchmark::State& state) {
    // Embree finds the entry, the tets do the rest (re-entry through concavities via Embree).
    const Fixture& f = fixture();
    size_t i = 0;
    for (auto _ : state) {
        double length = 0;
        f.volume->traverse(
            f.rays[i++ % f.rays.size()], 0, INFINITY,
            [&](const WalkSegment& s) {
                length += s.tOut - s.tIn;
                return true;
            },
            TetTraversal::kOutside);
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

void BM_FirstEntry(benchmark::State& state) {
    // The exact first entry of rays from outside, each crossing the medium: the grown-triangle
    // candidates of the whole ray, then the walk's exact tests.
    const Fixture& f = fixture();
    size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(f.volume->firstEntry(f.rays[i++ % f.rays.size()], 0, INFINITY));
    state.counters["rays/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FirstEntry);

void BM_EmbreeClosestHit(benchmark::State& state) {
    // What an exact first entry could cost at best: Embree's closest hit on the triangles
    // themselves (robust mode), which near an edge or a vertex may name the wrong triangle.
    const Fixture& f = fixture();
    size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(f.volume->bvh().intersect(f.rays[i++ % f.rays.size()], 0, INFINITY));
    state.counters["rays/s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EmbreeClosestHit);

void BM_GrownCandidates(benchmark::State& state) {
    // The first entry's Embree part alone: the grown triangles' candidates of the same rays,
    // all of them (argument 0), or as far as the first entry's search looks past the nearest (1).
    const Fixture& f = fixture();
    size_t i = 0, found = 0;
    for (auto _ : state)
        f.volume->bvh().visitCandidates(f.rays[i++ % f.rays.size()], 0, INFINITY, [&](const SurfaceHit& hit) {
            ++found;
            return state.range(0) ? hit.t : INFINITY;
        });
    state.counters["candidates"] = double(found) / double(state.iterations());
}
BENCHMARK(BM_GrownCandidates)->Arg(0)->Arg(1);

void BM_LocateAlongPath(benchmark::State& state) {
    // The march's inside test with tets, as the single-scattering integrator does it: walk the
    // ray once through the box and give each sample the tet of the segment holding it (-1
    // between segments), on the fly. The walk's cost is included. Argument: diagonal / step.
    const Fixture& f = fixture();
    const double step = f.box.diagonal() / double(state.range(0));
    std::vector<int64_t> tets;
    size_t i = 0, points = 0, wrong = 0;
    auto locateAll = [&](size_t r) {
        const size_t n = marchSamples(f, r, step);
        tets.assign(n, -1);
        size_t k = 0;  // the next sample
        f.volume->traverse(
            f.rays[r], f.t0[r], f.t1[r],
            [&](const WalkSegment& s) {
                while (k < n && marchT(f, r, k, step) < s.tIn) ++k;  // between segments: outside
                for (; k < n && marchT(f, r, k, step) < s.tOut; ++k) tets[k] = s.tet;
                return true;
            },
            TetTraversal::kOutside);
        return n;
    };
    for (size_t r = 0; r < 256; ++r)  // once, untimed: the located tets hold their samples
        for (size_t k = 0, n = locateAll(r); k < n; ++k) {
            const glm::dvec3 p = f.rays[r].at(marchT(f, r, k, step));
            wrong += tets[k] >= 0 ? !f.volume->contains(uint32_t(tets[k]), p) : f.volume->locate(p) >= 0;
        }
    for (auto _ : state) {
        points += locateAll(i++ % f.rays.size());
        benchmark::DoNotOptimize(tets.data());
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
    state.counters["points/ray"] = double(points) / double(state.iterations());
    state.counters["wrong"] = double(wrong);
    state.counters["bytes/tet"] = double(f.volume->mesh().bytesPerTet());
}
BENCHMARK(BM_LocateAlongPath)->Arg(100)->Arg(500)->Arg(2500);

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
    // The parity baseline's inside test at the same samples: rays from each (majority of range(0)).
    const Fixture& f = fixture();
    const int rays = int(state.range(0));
    const double step = f.box.diagonal() / double(state.range(1));
    size_t i = 0, points = 0;
    for (auto _ : state) {
        const size_t r = i++ % f.rays.size(), n = marchSamples(f, r, step);
        for (size_t k = 0; k < n; ++k)
            benchmark::DoNotOptimize(insideByParity(f.volume->bvh(), f.rays[r].at(marchT(f, r, k, step)), rays));
        points += n;
    }
    state.counters["points/s"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ParityAlongPath)->ArgsProduct({{1, 3, 5}, {100, 500, 2500}});

}  // namespace
}  // namespace tetglow

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (argc > 1) tetglow::gMeshPath = argv[1];
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
