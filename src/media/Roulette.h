// The two Russian roulette rules of every path: eye paths (volpath, the photon integrator's
// eye path) and photons (the photon tracer, the photon walk in a medium). Each returns the
// probability the path went on with, by which the caller divides its weight, or 0 when it
// ended; a path that goes on draws one number, one that is never at risk none.
#pragma once
#include <algorithm>

#include "base/Spectrum.h"
#include "sampling/Rng.h"

namespace tetglow {

// An eye path after `events` scattering events, none at risk for the first three: it ends with
// probability q = max(0.05, 1 - the weight's largest channel).
inline double eyePathSurvival(const RGB& weight, int events, Rng& rng) {
    if (events <= 3) return 1;
    const double q = std::max(0.05, 1 - maxComponent(weight));
    return rng.uniform() < q ? 0 : 1 - q;
}

// A photon goes on with probability min(1, its flux's largest channel relative to what it was
// emitted with), so a surviving photon keeps about its emitted power.
inline double photonSurvival(const RGB& relativeFlux, Rng& rng) {
    const double keep = std::min(1.0, maxComponent(relativeFlux));
    return !(keep > 0) || rng.uniform() >= keep ? 0 : keep;
}

}  // namespace tetglow
