// Single scattering from point and spot lights along one stretch of a path in a medium, at a
// distance sampled equiangularly (Kulla and Fajardo 2012), combined with free-flight
// sampling's next-event estimate of the same light by the power heuristic over the distance:
// near a small light the equiangular sample wins, where the medium is dense free flight does.
// Both strategies weigh the same distance with the same pdfs, so the sum stays unbiased.
#pragma once
#include <optional>

#include "photon/Rng.h"
#include "render/Equiangular.h"
#include "render/Scene.h"

namespace tetglow {

class PointLightScattering {
public:
    // For the ray's stretch [0, tEnd] in the state's medium, one of the scene's point lights
    // chosen uniformly; inactive where the scene has none. rPrefix: the path's SpectralPath::r
    // before this stretch (its free-flight pdf is averaged over channels with those weights).
    PointLightScattering(const Scene& scene, const MediumState& state, const Ray& ray, double tEnd, const RGB& rPrefix, Rng& rng);
    bool active() const { return light_ != nullptr; }
    // The weight of free-flight sampling's estimate of `light`, chosen with choicePmf at the
    // collision at t (transmittance tr from the stretch's start, density there).
    double freeFlightWeight(const Light& light, double choicePmf, double t, const RGB& tr, double density) const;
    // The equiangular estimate: light scattered towards -ray.d, to be multiplied by the path's
    // weight at the stretch's start.
    RGB estimate(Rng& rng) const;

private:
    double freeFlightPdf(const RGB& tr, double density) const;

    const Scene& scene_;
    MediumState state_;
    Ray ray_;
    RGB rPrefix_;
    const Light* light_ = nullptr;
    double lightChoice_ = 0;  // the probability of choosing light_
    std::optional<Equiangular> distance_;
};

}  // namespace tetglow
