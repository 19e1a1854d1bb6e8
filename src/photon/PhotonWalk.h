// A photon's random walk inside one medium: exact free flights through the tets, Henyey-
// Greenstein scattering, hero-channel spectral MIS, Russian roulette. It ends where the tet
// walk leaves the medium (the exact boundary) or when the photon is absorbed.
#pragma once
#include "photon/Medium.h"
#include "photon/Rng.h"
#include "photon/SpectralPath.h"

namespace tetglow {

struct PhotonEvent {
    glm::dvec3 position, direction;  // direction of travel before scattering
    RGB power;                       // flux arriving at the event
};

struct WalkResult {
    bool escaped = false;     // left through exitTriangle at `exit` (otherwise absorbed)
    Ray exit;                 // exit point and direction of travel (unit)
    uint32_t exitTriangle = 0;
    RGB absorbed{0};          // flux absorbed by the medium on the way (expected value per event)
};

// `path` carries the photon's flux as path.weight() * flux; `flux` is what the light emitted.
// onScatter(event) is called at every scattering event, before the new direction is drawn.
template <class OnScatter>
WalkResult photonWalk(const Medium& medium, Ray ray, WalkStart start, const RGB& flux, SpectralPath& path, Rng& rng,
                      int maxEvents, OnScatter&& onScatter) {
    WalkResult result;
    const MediumParams& params = medium.params();
    for (int events = 0; events < maxEvents; ++events) {
        const FreeFlight flight = medium.sampleFlight(ray, start, INFINITY, path.hero, rng.uniform());
        if (!flight.scattered) {
            path.pass(flight.transmittance);
            result.escaped = flight.left;
            result.exit = {ray.at(flight.exitT), ray.d};
            result.exitTriangle = flight.exitTriangle;
            return result;
        }
        path.interact(flight.transmittance, medium.sigmaT() * flight.density);
        const RGB arriving = path.weight() * flux;
        result.absorbed += arriving * params.sigmaA * flight.density;
        path.beta *= params.sigmaS * flight.density;
        const glm::dvec3 p = ray.at(flight.t);
        onScatter(PhotonEvent{p, ray.d, arriving * params.sigmaS * flight.density});
        // Roulette on the flux that goes on, relative to what was emitted.
        const double keep = std::min(1.0, maxComponent(path.weight()));
        if (!(keep > 0) || rng.uniform() >= keep) return result;
        path.beta /= keep;
        const double u0 = rng.uniform(), u1 = rng.uniform();
        ray = {p, medium.phase().sample(ray.d, {u0, u1})};
        start = WalkStart::inside(flight.tet);
    }
    return result;
}

}  // namespace tetglow
