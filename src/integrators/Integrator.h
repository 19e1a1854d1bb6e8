// An integrator estimates the radiance arriving at the camera along a ray.
#pragma once
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "render/Scene.h"
#include "sampling/Rng.h"

namespace tetglow {

class Integrator {
public:
    virtual ~Integrator() = default;
    // Called before each pass of one sample per pixel, outside radiance() calls (photon
    // mapping traces a fresh photon set here, and stops early once *cancel is set: the pass's
    // image will be thrown away).
    virtual void beginPass(uint64_t /*pass*/, const std::atomic<bool>* /*cancel*/ = nullptr) {}
    // One sample of the radiance arriving at the camera along `ray` (unit direction).
    virtual RGB radiance(const Ray& ray, Rng& rng) const = 0;
    // Light this integrator cannot carry to some medium of the scene, one line per medium
    // (render/UnsampledLight.h), for the user to be told before the render.
    virtual std::vector<std::string> warnings() const { return {}; }
};

std::unique_ptr<Integrator> makeIntegrator(const Scene& scene, const IntegratorDesc& desc);

}  // namespace tetglow
