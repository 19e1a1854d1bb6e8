// An integrator estimates the radiance arriving at the camera along a ray.
#pragma once
#include <memory>

#include "photon/Rng.h"
#include "render/Scene.h"

namespace tetglow {

class Integrator {
public:
    virtual ~Integrator() = default;
    // Called before each pass of one sample per pixel, outside radiance() calls (photon
    // mapping traces a fresh photon set here).
    virtual void beginPass(uint64_t /*pass*/) {}
    // One sample of the radiance arriving at the camera along `ray` (unit direction).
    virtual RGB radiance(const Ray& ray, Rng& rng) const = 0;
};

std::unique_ptr<Integrator> makeIntegrator(const Scene& scene, const IntegratorDesc& desc);

}  // namespace tetglow
