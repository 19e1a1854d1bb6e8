// A photon's random walk inside one medium and across its index-matched interfaces: exact free
// flights through the tets, Henyey-Greenstein scattering with each region's coefficients,
// hero-channel spectral MIS, Russian roulette. It ends where a flight leaves the medium (the
// exact boundary), stops at a dielectric interface or reaches a surface inside it, or when the
// photon is absorbed.
#pragma once
#include "media/FreeFlight.h"
#include "media/Roulette.h"
#include "media/SpectralPath.h"
#include "media/Volume.h"
#include "sampling/Rng.h"

namespace tetglow {

struct PhotonEvent {
    glm::dvec3 position, direction;  // direction of travel before scattering
    RGB power;                       // flux arriving at the event times sigma_s (what is scattered)
    uint32_t tet;                    // where it is (its region's medium scattered it)
};

struct WalkResult {
    bool absorbed = false;  // ended inside (roulette or the event cap); otherwise `ray` flew out
    Ray ray;                // the last flight: from the last event (or the start), unit direction
    WalkExit exit;          // where that flight left the medium or stopped
    RGB absorbedFlux{0};    // flux absorbed by the medium on the way (expected value per event)
    int events = 0;         // scattering events
};

// `path` carries the photon's flux as path.weight() * flux; `flux` is what the light emitted.
// limit(ray) is the distance along a flight's ray to the first surface inside the medium
// (INFINITY where there is none). onScatter(event) is called at every scattering event, before
// the new direction is drawn.
template <class Limit, class OnScatter>
WalkResult photonWalk(const Volume& volume, Ray ray, WalkStart start, const RGB& flux, SpectralPath& path, Rng& rng,
                      int maxEvents, Limit&& limit, OnScatter&& onScatter) {
    WalkResult result;
    for (; result.events < maxEvents; ++result.events) {
        const FreeFlight flight = sampleFlight(volume, ray, start, limit(ray), path.hero, rng.uniform());
        if (!flight.scattered) {
            path.pass(flight.transmittance);
            result.ray = ray;
            result.exit = flight.exit;
            return result;
        }
        const Medium& medium = volume.at(flight.tet);
        const MediumParams& params = medium.params;
        path.interact(flight.transmittance, medium.sigmaT * flight.density);
        const RGB arriving = path.weight() * flux;
        result.absorbedFlux += arriving * params.sigmaA * flight.density;
        path.beta *= params.sigmaS * flight.density;
        const glm::dvec3 p = ray.at(flight.t);
        onScatter(PhotonEvent{p, ray.d, arriving * params.sigmaS * flight.density, flight.tet});
        const double keep = photonSurvival(path.weight(), rng);
        if (keep == 0) break;
        path.beta /= keep;
        const double u0 = rng.uniform(), u1 = rng.uniform();
        ray = {p, medium.phase.sample(ray.d, {u0, u1})};
        start = WalkStart::inside(flight.tet);
    }
    result.absorbed = true;
    return result;
}

}  // namespace tetglow
