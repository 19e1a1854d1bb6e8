// The published validation: a plane-parallel slab with matched boundaries under collimated
// normal incidence (van de Hulst's tables, as used to validate MCML), traced with the same
// photon walk as the renderer, through a tetrahedralized box.
#pragma once
#include <cstdint>
#include <functional>

namespace tetglow {

struct SlabParams {
    double tau = 2, albedo = 0.9, g = 0.75;
    uint64_t photons = 1000000, seed = 1;
    int threads = 0;       // 0: all cores
    double timeLimit = 0;  // > 0: an InputError when the photons are not all traced by then (seconds)
    // Called after every few million photons with the photons traced and the seconds since the start.
    std::function<void(uint64_t traced, double seconds)> progress;
};

struct Tally {
    double mean = 0, stdError = 0;
};

struct SlabResult {
    Tally reflectance;     // diffuse reflectance Rd: flux leaving through the lit face
    Tally transmittance;   // total transmittance Tt: through the far face, unscattered light included
    Tally absorbed, lost;  // absorbed by the medium; left through the side faces (should be ~0)
    uint64_t tets = 0;
    double seconds = 0;
};

// Throws InputError for parameters outside tau > 0, 0 <= albedo <= 1, -1 < g < 1, photons >= 2;
// when a photon reaches kMaxSlabEvents scattering events inside (a slab too thick to simulate: its
// share of the flux would be lost from every tally); and when timeLimit passes first.
inline constexpr int kMaxSlabEvents = 1 << 20;
SlabResult simulateSlab(const SlabParams& params);

}  // namespace tetglow
