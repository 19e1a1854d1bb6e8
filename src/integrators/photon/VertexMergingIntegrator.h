// Path tracing combined with photon points by multiple importance sampling: vertex merging
// (Georgiev et al. 2012) in media (Krivanek et al. 2014), without vertex connections beyond
// next-event estimation. Each pass traces photon paths from the scene's area light and keeps
// every scattering event after the first; the eye path is a volumetric path tracer's that also
// merges, at each of its vertices in a medium, the photons within a radius. A path of light ->
// x1 -> ... -> x(k-1) -> camera, all in media, can be sampled by next-event estimation at x1 (or
// by phase sampling into the light, weighted against it as volpath does) and by merging at any
// xi, i >= 2; the balance heuristic weighs them. Weights use gray pdfs (mean extinction) in
// homogeneous regions, where every ratio telescopes to
//     p_merge(i) / p_nee = N V l sigma(xi) / phase(xi),   l = T(x0, x1) phase(x1) / (A pi p_nee(x1 -> x0)),
// with N photon paths, V the kernel's volume, A the light's area and T the mean optical depth's
// transmittance. Paths with a surface vertex, or from other lights, are volpath's alone.
#pragma once
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "integrators/Integrator.h"
#include "integrators/photon/PhotonMap.h"

namespace tetglow {

class VertexMergingIntegrator : public Integrator {
public:
    VertexMergingIntegrator(const Scene& scene, const IntegratorDesc& desc);
    ~VertexMergingIntegrator() override;
    void beginPass(uint64_t pass, const std::atomic<bool>* cancel = nullptr) override;
    RGB radiance(const Ray& ray, Rng& rng) const override;

private:
    struct LightEnd {        // per stored photon
        float l = 0;         // the light end's factor l above
        float interior = 0;  // sum of sigma / phase over the photon's vertices x2 .. x(i-1)
    };
    // Traces one photon path, appending its photons from x2 on.
    void tracePhoton(uint64_t index, uint64_t pass, std::vector<Photon>& photons, std::vector<LightEnd>& ends) const;
    // l for the light end at x0 on the merged light, x1 in a medium (state), phase value at x1.
    double lightEnd(const glm::dvec3& x1, const VolumeState& at, const glm::dvec3& x0, double phase) const;
    // Next-event estimation at p (eye travelling along d), weighted against the merges of a
    // path whose interior vertices sum to `interior` (negative: no merges).
    RGB direct(const glm::dvec3& p, const glm::dvec3& d, const HenyeyGreenstein& phase, const VolumeState& here,
               double interior, Rng& rng) const;
    // Weighted merges at eye vertex p (travelling along d) with extinction mean sigma.
    RGB merge(const glm::dvec3& p, const glm::dvec3& d, const HenyeyGreenstein& phase, double sigma,
              double interior) const;

    const Scene& scene_;
    IntegratorDesc desc_;
    VolumeState cameraMedium_;
    const Light* light_ = nullptr;  // the area light whose photons are merged
    double area_ = 0;
    bool merging_ = true;
    double radius_ = 0, volume_ = 0;  // this pass's
    std::unique_ptr<PhotonMap> map_;
    std::vector<LightEnd> ends_;
};

}  // namespace tetglow
