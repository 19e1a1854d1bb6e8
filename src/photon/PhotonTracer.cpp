#include "photon/PhotonTracer.h"

#include <algorithm>
#include <atomic>
#include <string>

#include <tbb/parallel_for.h>

#include "integrators/PathStep.h"
#include "media/Roulette.h"
#include "photon/OctahedralDirection.h"
#include "photon/PhotonWalk.h"
#include "sampling/Sampling.h"
#include "scene/Material.h"

namespace tetglow {

namespace {

// Photon streams sit far above the pixel streams (one per pass), so the two never share one.
constexpr uint64_t kPhotonStream = uint64_t(1) << 62;
constexpr uint64_t kBlock = 1024;  // paths per parallel task

double probability(const std::vector<double>& cdf, size_t i) { return (cdf[i] - (i ? cdf[i - 1] : 0)) / cdf.back(); }

Photon makePhoton(const glm::dvec3& p, const RGB& power, const glm::dvec3& direction) {
    return {glm::vec3(p), glm::vec3(power), packDirection(glm::vec3(direction)), 0};
}

// One photon path, from emission to absorption, escape or the event cap.
class PhotonPath {
public:
    PhotonPath(const Scene& scene, const PhotonTracingOptions& options, TracedPhotons& out,
               std::atomic<uint64_t>& stored)
        : scene_(scene), options_(options), out_(out), stored_(stored) {}

    void trace(const PhotonSource::Emission& e, Rng& rng) {
        EnergyBalance energy;
        energy.emitted = e.flux;
        SpectralPath path = SpectralPath::pick(rng.uniform());
        Ray ray = e.ray;
        VolumeState state = e.state;
        // Next-event estimation follows light that has crossed only index-matched boundaries;
        // what else arrives is stored.
        bool direct = !e.fromMedium;
        // From a light by specular events alone (a caustic), which final gathering cannot find.
        bool specularOnly = !e.fromMedium;
        int depth = 0;
        auto flux = [&] { return path.weight() * e.flux; };
        for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
            std::optional<Intersection> hit;
            WalkExit exit;
            if (state.inside()) {
                const SceneVolume& volume = scene_.volumes()[state.volume];
                const WalkResult walk = photonWalk(
                    *volume.volume, ray, state.start, e.flux, path, rng, options_.maxDepth - depth,
                    [&](const Ray& r) {
                        hit = scene_.intersect(r, state);
                        return hit ? hit->t : INFINITY;
                    },
                    [&](const PhotonEvent& event) {
                        // Stored in the photon map of the medium that scattered it.
                        const int m = volume.regionMedium[size_t(volume.volume->mesh().region(event.tet))];
                        if (!direct && (options_.storedMedia.empty() || options_.storedMedia[size_t(m)]))
                            store(out_.volume[m], makePhoton(event.position, event.power, event.direction));
                        direct = specularOnly = false;
                    });
                energy.absorbedInMedia += walk.absorbedFlux;
                depth += walk.events;
                if (walk.absorbed) {
                    if (depth >= options_.maxDepth) energy.cut += flux();
                    break;
                }
                ray = walk.ray;
                exit = walk.exit;
            } else {
                hit = scene_.intersect(ray);
            }
            const StretchEnd end = endStretch(scene_, hit, exit, ray, state);
            if (end == StretchEnd::Crossed) continue;
            if (end == StretchEnd::Escaped) {
                energy.escaped += flux();
                break;
            }
            if (end == StretchEnd::Emitter) {  // emitters are black
                energy.absorbedOnSurfaces += flux();
                break;
            }
            const MaterialDesc& material = scene_.material(*hit);
            if (++depth >= options_.maxDepth) {
                energy.cut += flux();
                break;
            }
            const RGB arriving = flux();
            if (material.type == MaterialType::Diffuse && !direct) {
                store(out_.surface, makePhoton(hit->p, arriving, ray.d));
                if (specularOnly && options_.caustics) store(out_.caustic, out_.surface.back());
            }
            specularOnly = specularOnly && material.type != MaterialType::Diffuse;
            const double u0 = rng.uniform(), u1 = rng.uniform();
            const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1}, TransportMode::Importance);
            energy.absorbedOnSurfaces += arriving * (RGB(1) - bs.weight);
            path.beta *= bs.weight;
            direct = false;
            leaveSurface(scene_, *hit, bs.direction, ray, state);
            const double keep = photonSurvival(path.weight(), rng);
            if (keep == 0) break;
            path.beta /= keep;
        }
        const RGB deficit =
            energy.emitted - energy.absorbedInMedia - energy.absorbedOnSurfaces - energy.escaped - energy.cut;
        energy.deficitSquares = deficit * deficit;
        out_.energy.add(energy);
    }

private:
    void store(std::vector<Photon>& photons, const Photon& photon) {
        if (stored_.fetch_add(1, std::memory_order_relaxed) >= options_.maxStored)
            throw InputError("photon tracing: " + std::to_string(options_.paths) +
                             " photon paths per pass store more than " + std::to_string(options_.maxStored) +
                             " photons, more than this machine's memory holds: ask for fewer "
                             "photons per pass or a lower max depth");
        photons.push_back(photon);
    }

    const Scene& scene_;
    const PhotonTracingOptions& options_;
    TracedPhotons& out_;
    std::atomic<uint64_t>& stored_;
};

}  // namespace

void EnergyBalance::add(const EnergyBalance& o) {
    emitted += o.emitted;
    absorbedInMedia += o.absorbedInMedia;
    absorbedOnSurfaces += o.absorbedOnSurfaces;
    escaped += o.escaped;
    cut += o.cut;
    deficitSquares += o.deficitSquares;
}

PhotonSource::PhotonSource(const Scene& scene) {
    for (int i = 0; i < int(scene.lights().size()); ++i) emitters_.push_back({i, -1, scene.lights()[i]->power(), {}});
    for (int m = 0; m < int(scene.media().size()); ++m) {
        const MediumPlace& sm = scene.media()[m];
        const Volume& volume = *scene.volumes()[sm.volume].volume;
        const Medium& medium = volume.region(sm.region);
        if (!(maxComponent(medium.params.emission) > 0)) continue;
        Emitter e{-1, m, RGB(0), {}, volume.mesh().regionTets[sm.region]};
        const TetMesh& mesh = volume.mesh();
        double total = 0;
        // Density is linear in a tet: its value at the centroid is its mean.
        for (uint32_t t = e.firstTet; t < mesh.regionTets[sm.region + 1]; ++t)
            e.tetCdf.push_back(total += mesh.tetVolume(t) * volume.density(t, mesh.centroid(t)));
        // Isotropic emission of radiance `emission` per unit length: 4 pi emission per unit volume.
        e.power = medium.params.emission * (4 * kPi * total);
        if (total > 0) emitters_.push_back(std::move(e));
    }
    double total = 0;
    for (const Emitter& e : emitters_) {
        cdf_.push_back(total += average(e.power));
        total_ += e.power;
    }
    if (!(total > 0)) throw InputError("photon tracing: nothing in the scene emits power");
}

PhotonSource::Emission PhotonSource::sample(const Scene& scene, Rng& rng) const {
    const size_t i = sampleCdf(cdf_, rng.uniform());
    const double chosen = probability(cdf_, i);
    const Emitter& e = emitters_[i];
    Emission out;
    if (e.light >= 0) {
        const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
        const PhotonEmission p = scene.lights()[e.light]->emitPhoton({u0, u1}, {u2, u3});
        out.ray = p.ray;
        out.flux = p.flux / chosen;
        out.state = scene.volumeAt(p.ray.o);
        return out;
    }
    const int index = scene.media()[e.medium].volume;
    const Volume& volume = *scene.volumes()[index].volume;
    const TetMesh& mesh = volume.mesh();
    const auto tet = e.firstTet + uint32_t(sampleCdf(e.tetCdf, rng.uniform()));
    const auto& v = mesh.tets[tet];
    const glm::dvec3 p0 = mesh.vertices[v[0]];
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const glm::dvec3 w = sampleUniformTetrahedron({u0, u1, u2});
    const glm::dvec3 p =
        p0 + w.x * (mesh.vertices[v[1]] - p0) + w.y * (mesh.vertices[v[2]] - p0) + w.z * (mesh.vertices[v[3]] - p0);
    const double u3 = rng.uniform(), u4 = rng.uniform();
    out.ray = {p, sampleUniformSphere({u3, u4})};
    // The point is uniform in the tet; its density relative to the tet's mean corrects for that.
    out.flux = e.power * (volume.density(tet, p) / volume.density(tet, mesh.centroid(tet)) / chosen);
    out.state = {index, WalkStart::inside(tet)};
    out.fromMedium = true;
    return out;
}

TracedPhotons tracePhotons(const Scene& scene, const PhotonSource& source, const PhotonTracingOptions& options) {
    const uint64_t blocks = (options.paths + kBlock - 1) / kBlock;
    std::vector<TracedPhotons> parts(blocks);
    std::atomic<uint64_t> stored{0};
    tbb::parallel_for(uint64_t(0), blocks, [&](uint64_t b) {
        TracedPhotons& part = parts[b];
        part.volume.resize(scene.media().size());
        if (b > 0 && options.deadline && std::chrono::steady_clock::now() > *options.deadline) return;
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
        part.paths = std::min(options.paths, (b + 1) * kBlock) - b * kBlock;
        PhotonPath tracer(scene, options, part, stored);
        for (uint64_t i = b * kBlock; i < std::min(options.paths, (b + 1) * kBlock); ++i) {
            Rng rng(options.seed, i, kPhotonStream + options.pass);
            PhotonSource::Emission e = source.sample(scene, rng);
            e.flux /= double(options.paths);
            tracer.trace(e, rng);
        }
    });
    // Concatenated in block order: the same photons in the same order for any thread count.
    TracedPhotons all;
    all.volume.resize(scene.media().size());
    for (const TracedPhotons& part : parts) {
        all.paths += part.paths;
        for (size_t m = 0; m < all.volume.size(); ++m)
            all.volume[m].insert(all.volume[m].end(), part.volume[m].begin(), part.volume[m].end());
        all.surface.insert(all.surface.end(), part.surface.begin(), part.surface.end());
        all.caustic.insert(all.caustic.end(), part.caustic.begin(), part.caustic.end());
        all.energy.add(part.energy);
    }
    if (all.paths < options.paths) {  // each path carried 1 / options.paths of the emitted power
        const double scale = double(options.paths) / double(all.paths);
        for (auto* photons : {&all.surface, &all.caustic})
            for (Photon& p : *photons) p.power *= float(scale);
        for (auto& photons : all.volume)
            for (Photon& p : photons) p.power *= float(scale);
        EnergyBalance& e = all.energy;
        for (RGB* x : {&e.emitted, &e.absorbedInMedia, &e.absorbedOnSurfaces, &e.escaped, &e.cut}) *x *= scale;
        e.deficitSquares *= scale * scale;
    }
    return all;
}

}  // namespace tetglow
