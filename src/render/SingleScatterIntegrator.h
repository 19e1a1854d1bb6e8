// The seed's baseline: single scattering by ray marching with a fixed step. Where the medium
// is comes from the boundary mode: `tet` samples every step of the tet walk's exact segments
// (shadow rays get the exact transmittance), `parity` asks the parity test at every step
// (shadow rays march too), `bbox` fills the mesh's bounding box with the medium. Surfaces:
// specular chains are followed, diffuse surfaces get direct light only.
#pragma once
#include <vector>

#include "render/Integrator.h"

namespace tetglow {

class SingleScatterIntegrator : public Integrator {
public:
    SingleScatterIntegrator(const Scene& scene, const IntegratorDesc& desc);
    RGB radiance(const Ray& ray, Rng& rng) const override;

private:
    // Adds the light scattered and emitted towards ray.o from media along [0, tMax] to L
    // (already weighted by beta) and returns the transmittance of that stretch.
    RGB march(const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    RGB marchTets(size_t m, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    RGB marchSteps(size_t m, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    // Light from one light sample scattered at p towards -d, by the mode's visibility.
    RGB inScattered(size_t m, const glm::dvec3& p, const glm::dvec3& d, int64_t tet, Rng& rng) const;
    RGB visibility(const Ray& ray, double tMax, Rng& rng) const;
    bool inside(size_t m, const glm::dvec3& p) const;  // parity or bbox

    const Scene& scene_;
    BoundaryMode mode_;
    double step_;
    int parityRays_, maxDepth_;
    std::vector<Bounds3> boxes_;  // per medium
};

}  // namespace tetglow
