// Progressive photon beams (Jarosz et al. 2011), beam x beam with a 1D kernel: each pass traces
// photon paths and keeps every straight flight inside a medium after the light's first event
// (a short beam, to the next event or where the flight left); eye rays never scatter in media:
// along each stretch they add single scattering by next-event estimation at a point of the
// stretch and multiple scattering from every beam within the kernel's radius of the stretch.
#pragma once
#include <memory>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "integrators/Integrator.h"
#include "integrators/photon/PhotonTracer.h"

namespace tetglow {

class PhotonBeamIntegrator : public Integrator {
public:
    PhotonBeamIntegrator(const Scene& scene, const IntegratorDesc& desc);
    ~PhotonBeamIntegrator() override;
    void beginPass(uint64_t pass, const std::atomic<bool>* cancel = nullptr) override;
    RGB radiance(const Ray& ray, Rng& rng) const override;

    struct Beam {
        glm::dvec3 o, d;
        double length;
        RGB betaFlux, ratios;  // the photon path's beta x flux and spectral ratios at o
        int hero;
        int volume;
    };

private:
    void tracePath(uint64_t index, uint64_t pass, std::vector<Beam>& beams) const;
    RGB beamsAlong(const Ray& ray, double tStart, double tEnd, const RegionOptics& optics) const;
    RGB singleAlong(const Ray& ray, const VolumeState& state, double tMax, const RegionOptics& optics, Rng& rng) const;

    const Scene& scene_;
    IntegratorDesc desc_;
    VolumeState cameraMedium_;
    PhotonSource source_;
    double radius_ = 0;
    std::vector<Beam> beams_;
    RTCScene bvh_ = nullptr;
};

}  // namespace tetglow
