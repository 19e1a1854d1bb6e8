// The reference: an unbiased volumetric path tracer. Free flights are sampled exactly through
// the tets (spectral MIS over the RGB channels), next-event estimation sends shadow rays that
// walk the tets inside media and use Embree outside, and area and environment lights are
// combined with phase/BSDF sampling by multiple importance sampling. In homogeneous regions
// every stretch that is not optically deep is lit at a point of its own (StretchSampling.h), not
// only where its free flight interacts. Russian roulette ends paths.
#pragma once
#include <optional>

#include "integrators/Integrator.h"
#include "media/RegionMedia.h"
#include "media/SpectralPath.h"

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
    // Direct light at a point of a stretch, and how much likelier its conditioned free-flight pdf
    // chose that point than the free flight would: the factor of the MIS weight of an emitter
    // that phase sampling reaches after the flight interacts on the stretch.
    struct StretchLight {
        RGB radiance;
        double scale;
    };
    // Direct light scattered towards -ray.d at a point of `stretch` (in `volume`) sampled by
    // its conditioned free-flight pdf; none where the stretch is not lit at a point of its own.
    std::optional<StretchLight> directWithin(const RegionStretch& stretch, const Ray& ray, const SpectralPath& path,
                                             int volume, Rng& rng) const;

    const Scene& scene_;
    int maxDepth_;
    VolumeState cameraMedium_;
};

}  // namespace tetglow
