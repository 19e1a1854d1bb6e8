// An integrator estimates the radiance arriving at the camera along a ray.
#pragma once
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "sampling/Rng.h"
#include "scene/Scene.h"

namespace tetglow {

// What an integrator has to report of a render besides its image.
struct IntegratorStats {
    bool biased = false;             // the noise estimate leaves out a bias (a photon kernel's blur)
    double tracingSeconds = 0;       // light tracing before the eye paths (photon mapping), all passes
    std::vector<std::string> lines;  // for the user after the render, one line each
};

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
    // So far: after the render, of all its passes; before it, whether it is biased.
    virtual IntegratorStats stats() const { return {}; }
};

}  // namespace tetglow
