// An integrator estimates the radiance arriving at the camera along a ray.
#pragma once
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "sampling/Rng.h"
#include "scene/Scene.h"

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
    // (scene/UnsampledLight.h), for the user to be told before the render.
    virtual std::vector<std::string> warnings() const { return {}; }
};

}  // namespace tetglow
