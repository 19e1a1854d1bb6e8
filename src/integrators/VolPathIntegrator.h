// The reference: an unbiased volumetric path tracer. Free flights are sampled exactly through
// the tets (spectral MIS over the RGB channels), next-event estimation sends shadow rays that
// walk the tets inside media and use Embree outside, and area and environment lights are
// combined with phase/BSDF sampling by multiple importance sampling. Russian roulette ends paths.
#pragma once
#include "integrators/Integrator.h"

namespace tetglow {

class VolPathIntegrator : public Integrator {
public:
    VolPathIntegrator(const Scene& scene, int maxDepth);
    RGB radiance(const Ray& ray, Rng& rng) const override;
    std::vector<std::string> warnings() const override;
    // The path from ray (in `state`, after `depth` events) on. With emittersSeen false, an
    // emitter that ray reaches before the path scatters adds nothing: the caller's next-event
    // estimation counted it.
    RGB continuePath(const Ray& ray, VolumeState state, int depth, bool emittersSeen, Rng& rng) const;

private:
    const Scene& scene_;
    int maxDepth_;
    VolumeState cameraMedium_;
};

}  // namespace tetglow
