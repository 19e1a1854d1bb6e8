// The parity baseline: single scattering by ray marching with a fixed step. Where the medium
// is comes from the boundary mode: `tet` samples every step of the tet walk's exact segments,
// region by region (shadow rays get the exact transmittance), `parity` asks the parity test at
// every step (shadow rays march too), `bbox` fills the mesh's bounding box with the medium.
// Where media nest, parity and bbox pick the innermost medium whose own mesh (or box) holds the
// point, as the parity baseline's test would. Surfaces: specular chains are followed, diffuse surfaces get
// direct light only.
#pragma once
#include <memory>
#include <vector>

#include "integrators/Integrator.h"
#include "tet/SurfaceBVH.h"

namespace tetglow {

class SingleScatterIntegrator : public Integrator {
public:
    SingleScatterIntegrator(const Scene& scene, const IntegratorDesc& desc);
    ~SingleScatterIntegrator() override;
    RGB radiance(const Ray& ray, Rng& rng) const override;
    std::vector<std::string> warnings() const override;

    // Parity and bbox: the scene medium (a region of volume v) the mode would pick at p, or -1.
    int pick(size_t v, const glm::dvec3& p) const;

private:
    // Adds the light scattered and emitted towards ray.o from media along [0, tMax] to L
    // (already weighted by beta) and returns the transmittance of that stretch.
    RGB march(const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    RGB marchTets(size_t v, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    RGB marchSteps(size_t v, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const;
    // Light from one light sample scattered at p towards -d, by the mode's visibility.
    RGB inScattered(size_t v, const Medium& medium, const glm::dvec3& p, const glm::dvec3& d, int64_t tet,
                    Rng& rng) const;
    RGB visibility(const Ray& ray, double tMax, Rng& rng) const;

    const Scene& scene_;
    BoundaryMode mode_;
    double step_;
    int parityRays_, maxDepth_;
    std::vector<Bounds3> boxes_;                       // per volume
    std::vector<Bounds3> mediumBoxes_;                 // per scene medium: its own mesh's box
    std::vector<std::unique_ptr<SurfaceBVH>> parity_;  // per scene medium: its own mesh (parity)
    std::vector<std::vector<int>> innermostFirst_;     // per volume: its media, deepest first
};

}  // namespace tetglow
