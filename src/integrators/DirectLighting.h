// Next-event estimation: one light, chosen by its importance at the point (LightSelection.h),
// sampled towards the point.
#pragma once
#include "integrators/PathStep.h"
#include "sampling/Rng.h"
#include "sampling/Sampling.h"
#include "scene/LightSelection.h"
#include "scene/Scene.h"

namespace tetglow {

struct Scattering {
    RGB f{0};        // phase function, or BSDF times |cos|
    double pdf = 0;  // of sampling that direction by the phase function or BSDF (for MIS)
};

// `scatter(wi)` gives the Scattering towards wi; `visibility(ray, tMax)` the transmittance.
// With `mis`, area light samples are weighted by the power heuristic against phase/BSDF
// sampling, which must then count emitters it hits with lightPdf() (the constant environment,
// never chosen then, with weight 1); without it, phase/BSDF rays must not count them at all.
// `lightScale`: how much likelier p was to be chosen than by the phase/BSDF path's own sampling
// (StretchSampling.h), a factor of the light sample's pdf in the weight.
template <class ScatterFn, class VisibilityFn>
RGB sampleDirect(const Scene& scene, const glm::dvec3& p, Rng& rng, bool mis, ScatterFn&& scatter,
                 VisibilityFn&& visibility, double lightScale = 1) {
    if (scene.lights().empty()) return RGB(0);
    const LightChoice choice = chooseLight(scene.lights(), p, mis, rng.uniform());
    const double u0 = rng.uniform(), u1 = rng.uniform();
    if (!choice.light) return RGB(0);
    const LightSample ls = choice.light->sample(p, {u0, u1});
    if (ls.pdf <= 0 || isBlack(ls.L)) return RGB(0);
    const Scattering s = scatter(ls.wi);
    if (isBlack(s.f)) return RGB(0);
    const double tMax = std::isfinite(ls.distance) ? ls.distance - scene.rayEpsilon() : INFINITY;
    const RGB tr = visibility(Ray{p, ls.wi}, tMax);
    if (isBlack(tr)) return RGB(0);
    const double pdf = ls.pdf * choice.pmf;
    const double weight = ls.delta || !mis ? 1 : powerHeuristic(lightScale * pdf, s.pdf);
    return s.f * tr * ls.L * (weight / pdf);
}

// The visibility sampleDirect wants for shadow rays from `from`: their transmittance, with
// Russian roulette (transmittance, PathStep.h).
inline auto shadowRays(const Scene& scene, const VolumeState& from, Rng& rng) {
    return [&scene, from, &rng](const Ray& r, double tMax) { return transmittance(scene, r, tMax, from, &rng); };
}

// The Scattering towards wi of a medium's phase function, for a path travelling along d.
inline auto phaseScattering(const HenyeyGreenstein& phase, const glm::dvec3& d) {
    return [&phase, d](const glm::dvec3& wi) {
        const double f = phase.eval(glm::dot(d, wi));
        return Scattering{RGB(f), f};
    };
}

// Light scattered at p, inside tet `tet` of volume v, into the direction -d: one light
// sample without MIS, its shadow ray walking the tets (transmittance in PathStep.h, with
// roulette unless the caller wants the exact transmittance).
inline RGB directInMedium(const Scene& scene, int v, const glm::dvec3& p, const glm::dvec3& d, uint32_t tet, Rng& rng,
                          bool roulette = true) {
    if (scene.sealed(v)) return RGB(0);  // no shadow ray from inside reaches a light
    const VolumeState here{v, WalkStart::inside(tet)};
    return sampleDirect(
        scene, p, rng, false, phaseScattering(scene.volumes()[v].volume->at(tet).phase, d),
        [&](const Ray& r, double t) { return transmittance(scene, r, t, here, roulette ? &rng : nullptr); });
}

// The pdf with which sampleDirect would have chosen the point a phase/BSDF ray reached on a
// light (for the MIS weight of emitters hit by those rays).
inline double lightPdf(const Scene& scene, const Light& light, const glm::dvec3& from, const glm::dvec3& wi,
                       const glm::dvec3& point, uint32_t triangle) {
    return light.pdf(from, wi, point, triangle) * choicePmf(scene.lights(), light, from, true);
}

}  // namespace tetglow
