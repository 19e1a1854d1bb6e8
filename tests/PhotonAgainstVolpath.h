// Photon mapping against volpath on one scene: whether its image keeps volpath's mean, and how
// its noise compares, from independent renders of each.
#pragma once
#include <cstdint>

#include "render/Image.h"
#include "scene/Scene.h"

namespace tetglow::test {

// `integrator` with `photons` paths per pass, `spp` samples or passes, `seed`, on `threads` (0: all).
Image renderImage(const Scene& scene, IntegratorType integrator, uint64_t seed, int spp, uint64_t photons,
                  int threads = 0);
double imageMean(const Image& image);  // over pixels, of the channels' average
// The mean squared difference of two independent renders: twice the per-pixel variance.
double spread(const Image& a, const Image& b);

struct PhotonAgainstVolpath {
    double reference;      // volpath's image mean at the reference's spp (seed 1)
    double photonMean;     // the mean of two photon renders (seeds 2 and 3)
    double photonSpread;   // spread of those two
    double volpathSpread;  // spread of two volpath renders at the same spp (seeds 4 and 5)
    double sigma;          // standard error of photonMean - reference
};
// Printed as it is measured, for the test's log.
PhotonAgainstVolpath photonAgainstVolpath(const Scene& scene, int referenceSpp, int spp, uint64_t photons);

}  // namespace tetglow::test
