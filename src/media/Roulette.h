// The Russian roulette rules of every path: eye paths (volpath, the photon integrator's eye
// path) and photons (the photon tracer, the photon walk in a medium) return the probability the
// path went on with, by which the caller divides its weight, or 0 when it ended; a path that goes
// on draws one number, one that is never at risk none. Shadow rays keep theirs as they walk.
#pragma once
#include <algorithm>
#include <cmath>

#include "base/Spectrum.h"
#include "sampling/Rng.h"

namespace tetglow {

// An eye path after `events` scattering events, none at risk for the first three: while its
// weight's largest channel w is below 1 it goes on with probability sqrt(w) (Cycles' rule), so a
// survivor's weight, sqrt(w), stays below 1 and falls slowly; at 1 or above it always goes on. A
// 5% chance of ending at every event, whatever the weight, made survivors' weights grow by
// albedo / 0.95 per event: in jade (albedo 0.998, a hundred events) samples of 100 to 500 times
// their pixel's value.
inline double eyePathSurvival(const RGB& weight, int events, Rng& rng) {
    if (events <= 3) return 1;
    const double keep = std::sqrt(maxComponent(weight));
    if (keep >= 1) return 1;
    return rng.uniform() < keep ? keep : 0;
}

// A photon goes on with probability min(1, its flux's largest channel relative to what it was
// emitted with), so a surviving photon keeps about its emitted power.
inline double photonSurvival(const RGB& relativeFlux, Rng& rng) {
    const double keep = std::min(1.0, maxComponent(relativeFlux));
    return !(keep > 0) || rng.uniform() >= keep ? 0 : keep;
}

// A shadow ray's Russian roulette (shadowFlight): once the optical depth it has
// gathered (its smallest channel's) passes `at`, where its weighted transmittance is below 1/20,
// it ends with probability 3/4 and a survivor counts 4 times, tested again where that is below
// 1/20 once more. Each test draws one number.
struct ShadowRoulette {
    static constexpr double kSurvive = 0.25;
    double at = std::log(20.0);
    double weight = 1;
    // Decides every test up to optical depth `depth` not decided yet; false: the ray ended.
    bool reach(double depth, Rng& rng) {
        while (depth > at) {
            if (rng.uniform() >= kSurvive) return false;
            weight /= kSurvive;
            at -= std::log(kSurvive);
        }
        return true;
    }
};

}  // namespace tetglow
