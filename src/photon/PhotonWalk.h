// A photon's random walk inside one medium: exact free flights through the tets, Henyey-
// Greenstein scattering, hero-channel spectral MIS, Russian roulette. It ends where a flight
// leaves the medium (the exact boundary) or reaches a surface inside it, or when the photon is
// absorbed.
#pragma once
#include "photon/Medium.h"
#include "photon/Rng.h"
#include "photon/SpectralPath.h"

namespace tetglow {

struct PhotonEvent {
    glm::dvec3 position, direction;  // direction of travel before scattering
    RGB power;                       // flux arriving at the event times sigma_s (what is scattered)
};

struct WalkResult {
    bool absorbed = false;    // ended inside (roulette or the event cap); otherwise `ray` flew out
    Ray ray;                  // the last flight: from the last event (or the start), unit direction
    bool left = false;        // that flight left the medium through exitTriangle at exitT
    uint32_t exitTriangle = 0;
    double exitT = 0;
    RGB absorbedFlux{0};      // flux absorbed by the medium on the way (expected value per event)
    int events = 0;           // scattering events
};

// `path` carries the photon's flux as path.weight() * flux; `flux` is what the light emitted.
// limit(ray) is the distance along a flight's ray to the first surface inside the medium
// (INFINITY where there is none). onScatter(event) is called at every scattering event, before
// the new direction is drawn.
template <class Limit, class OnScatter>
WalkResult photonWalk(const Medium& medium, Ray ray, WalkStart start, const RGB& flux, SpectralPath& path, Rng& rng,
                      int maxEvents, Limit&& limit, OnScatter&& onScatter) {
    WalkResult result;
    const MediumParams& params = medium.params();
    for (; result.events < maxEvents; ++result.events) {
        const FreeFlight flight = medium.sampleFlight(ray, start, limit(ray), path.hero, rng.uniform());
        if (!flight.scattered) {
            path.pass(flight.transmittance);
            result.ray = ray;
            result.left = flight.left, result.exitTriangle = flight.exitTriangle, result.exitT = flight.exitT;
            return result;
        }
        path.interact(flight.transmittance, medium.sigmaT() * flight.density);
        const RGB arriving = path.weight() * flux;
        result.absorbedFlux += arriving * params.sigmaA * flight.density;
        path.beta *= params.sigmaS * flight.density;
        const glm::dvec3 p = ray.at(flight.t);
        onScatter(PhotonEvent{p, ray.d, arriving * params.sigmaS * flight.density});
        // Roulette on the flux that goes on, relative to what was emitted.
        const double keep = std::min(1.0, maxComponent(path.weight()));
        if (!(keep > 0) || rng.uniform() >= keep) break;
        path.beta /= keep;
        const double u0 = rng.uniform(), u1 = rng.uniform();
        ray = {p, medium.phase().sample(ray.d, {u0, u1})};
        start = WalkStart::inside(flight.tet);
    }
    result.absorbed = true;
    return result;
}

}  // namespace tetglow
