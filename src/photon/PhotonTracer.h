// Photon tracing (Jensen 2001): photons leave the lights and the emissive media, cross
// index-matched boundaries, reflect and refract at dielectrics, bounce off diffuse surfaces and
// scatter in media with exact free flights through the tets. The photon integrator computes
// direct light by next-event estimation, so a photon is stored only where its path is one that
// next-event estimation cannot take: after a scattering event, a specular or diffuse bounce, or
// when it was emitted by a medium. Volume photons are stored at scattering events, surface
// photons on diffuse surfaces (the caustics under the fish).
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/Spectrum.h"
#include "photon/Photon.h"
#include "sampling/Rng.h"
#include "scene/Scene.h"

namespace tetglow {

struct PhotonTracingOptions {
    uint64_t paths = 100000;  // photon paths emitted
    int maxDepth = 64;        // scattering and surface events per path
    uint64_t seed = 0;
    uint64_t pass = 0;      // independent photons for every pass
    bool caustics = false;  // also keep the caustic photons apart (TracedPhotons::caustic)
    // Photons the pass may store (volume, surface and caustic together): a path stores up to
    // maxDepth, so only the count itself bounds the memory. One more is an InputError, raised
    // before it is stored.
    uint64_t maxStored = UINT64_MAX;
    // Blocks of paths not begun by then are not traced (the first always is), and the photons'
    // power is scaled to the paths that were: a pass under a time limit ends in time.
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt;
    const std::atomic<bool>* cancel = nullptr;  // once set, the paths not yet begun are skipped
    // Per scene medium, whether the photons it scatters are stored (empty: all are). Paths still
    // cross the others and scatter in them; only their photons there are not kept.
    std::vector<char> storedMedia = {};
};

// Where the emitted power went, summed over the paths: emitted = absorbed + escaped + cut in
// expectation. deficitSquares sums, per path, (emitted - absorbed - escaped - cut)^2, for the
// standard error of that balance.
struct EnergyBalance {
    RGB emitted{0}, absorbedInMedia{0}, absorbedOnSurfaces{0}, escaped{0}, cut{0}, deficitSquares{0};
    void add(const EnergyBalance& o);
};

struct TracedPhotons {
    std::vector<std::vector<Photon>> volume;  // per scene medium (region), by the medium that scattered them
    std::vector<Photon> surface;              // on diffuse surfaces, every photon not straight from its light
    std::vector<Photon> caustic;              // those of them that came from a light by specular events only (if asked)
    EnergyBalance energy;
    uint64_t paths = 0;  // traced: fewer than asked for when the deadline passed
};

// Chooses emitters in proportion to their power: every light and every emissive medium (a
// point by tet, in proportion to its integrated density).
class PhotonSource {
public:
    explicit PhotonSource(const Scene& scene);
    RGB totalPower() const { return total_; }
    struct Emission {
        Ray ray;
        RGB flux{0};
        VolumeState state;  // the volume the photon starts in
        bool fromMedium = false;
    };
    Emission sample(const Scene& scene, Rng& rng) const;

private:
    struct Emitter {
        int light = -1, medium = -1;
        RGB power{0};
        std::vector<double> tetCdf;  // media: integrated density per tet of its region, cumulative
        uint32_t firstTet = 0;       // media: its region's first tet
    };
    std::vector<Emitter> emitters_;
    std::vector<double> cdf_;  // over emitters, by mean power
    RGB total_{0};
};

// Traces options.paths photon paths in parallel. Path i uses Rng(seed, i, stream of pass) only
// and photons are kept in path order, so the result is the same for any thread count.
TracedPhotons tracePhotons(const Scene& scene, const PhotonSource& source, const PhotonTracingOptions& options);

}  // namespace tetglow
