#include "render/PointLightScattering.h"

#include "render/LightSelection.h"

namespace tetglow {

PointLightScattering::PointLightScattering(const Scene& scene, const MediumState& state, const Ray& ray, double tEnd,
                                           const RGB& rPrefix, Rng& rng)
    : scene_(scene), state_(state), ray_(ray), rPrefix_(rPrefix) {
    size_t count = 0;
    for (const auto& light : scene.lights()) count += light->position().has_value();
    if (count == 0 || !std::isfinite(tEnd)) return;
    auto pick = std::min(count - 1, size_t(rng.uniform() * count));
    for (const auto& light : scene.lights())
        if (light->position() && pick-- == 0) light_ = light.get();
    lightChoice_ = 1.0 / count;
    distance_.emplace(ray, *light_->position(), tEnd);
}

// The density of a free-flight collision at t, averaged over the channels as the path's
// one-sample spectral MIS averages it (SpectralPath).
double PointLightScattering::freeFlightPdf(const RGB& tr, double density) const {
    const Medium& medium = *scene_.media()[state_.medium].medium;
    return average(rPrefix_ * medium.sigmaT() * density * tr) / average(rPrefix_);
}

double PointLightScattering::freeFlightWeight(const Light& light, double choicePmf, double t, const RGB& tr, double density) const {
    if (&light != light_) return 1;
    return powerHeuristic(choicePmf * freeFlightPdf(tr, density), lightChoice_ * distance_->pdf(t));
}

RGB PointLightScattering::estimate(Rng& rng) const {
    const double t = distance_->sample(rng.uniform());
    const Medium& medium = *scene_.media()[state_.medium].medium;
    const FreeFlight at = medium.sampleFlight(ray_, state_.start, t, 0, 1.0);  // u = 1: no collision, up to t
    if (at.left) return RGB(0);
    const glm::dvec3 p = ray_.at(t);
    const LightSample ls = light_->sample(p, {});
    if (isBlack(ls.L)) return RGB(0);
    const double density = medium.density(at.tet, p);
    const double pdf = lightChoice_ * distance_->pdf(t);
    const double weight = powerHeuristic(pdf, choicePmf(scene_.lights(), *light_, p, true) * freeFlightPdf(at.transmittance, density));
    const RGB tr = scene_.transmittance(Ray{p, ls.wi}, ls.distance - scene_.rayEpsilon(), {state_.medium, WalkStart::inside(at.tet)});
    const double phase = medium.phase().eval(glm::dot(ray_.d, ls.wi));
    return at.transmittance * medium.params().sigmaS * density * phase * ls.L * tr * (weight / pdf);
}

}  // namespace tetglow
