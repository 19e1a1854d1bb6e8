// Throughput of a path whose free flights are all sampled with one "hero" RGB channel, and the
// per-channel ratios of path pdfs for one-sample spectral MIS over the whole path (the r_u of
// pbrt-v4's volpath). An estimate multiplies by weight() = beta / mean(r): for an albedo-1
// medium that is at most 3, where MIS per event would let the ratios of many events multiply
// into a heavy tail.
#pragma once
#include "base/Spectrum.h"

namespace tetglow {

struct SpectralPath {
    int hero = 0;
    RGB beta{1};  // f / p_hero
    RGB r{1};     // p_c / p_hero

    explicit SpectralPath(int heroChannel) : hero(heroChannel) {}
    static SpectralPath pick(double u) { return SpectralPath(u < 1.0 / 3 ? 0 : u < 2.0 / 3 ? 1 : 2); }

    RGB weight() const { return beta / average(r); }
    // The flight passed a stretch with transmittance tr without an interaction.
    void pass(const RGB& tr) {
        const RGB ratio = tr / tr[hero];
        beta *= ratio;
        r *= ratio;
    }
    // An interaction after transmittance tr, where the extinction (sigma_t times density) is
    // sigmaT; the caller then multiplies beta by what happens there (scattering coefficient).
    void interact(const RGB& tr, const RGB& sigmaT) {
        const RGB pdf = sigmaT * tr;
        beta *= tr / pdf[hero];
        r *= pdf / pdf[hero];
    }
    // The path is cut: emission collected at the event uses these factors; so does roulette.
    bool alive() const { return !isBlack(beta); }
};

}  // namespace tetglow
