#include "render/SingleScatterIntegrator.h"

#include <cmath>

#include "render/DirectLighting.h"
#include "render/Material.h"

namespace tetglow {

SingleScatterIntegrator::SingleScatterIntegrator(const Scene& scene, const IntegratorDesc& desc)
    : scene_(scene), mode_(desc.boundary), step_(desc.stepSize), parityRays_(desc.parityRays), maxDepth_(desc.maxDepth) {
    for (const auto& m : scene.media()) {
        if (mode_ != BoundaryMode::Tet && !m.medium->homogeneous())
            throw InputError(m.name + ": the parity and bbox boundary modes need a homogeneous medium (no per-vertex density)");
        boxes_.push_back(m.medium->volume().bounds());
    }
}

bool SingleScatterIntegrator::inside(size_t m, const glm::dvec3& p) const {
    if (mode_ == BoundaryMode::Bbox) return true;  // the march already stays within the box
    return insideByParity(scene_.media()[m].medium->volume().bvh(), p, parityRays_);
}

RGB SingleScatterIntegrator::visibility(const Ray& ray, double tMax, Rng& rng) const {
    if (mode_ == BoundaryMode::Tet) return scene_.transmittance(ray, tMax, scene_.mediumAt(ray.o));
    if (!scene_.unoccluded(ray, tMax)) return RGB(0);
    // The seed's shadow ray: march through each medium's box, asking the boundary test per step.
    RGB tau(0);
    for (size_t m = 0; m < boxes_.size(); ++m) {
        double t0 = 0, t1 = tMax;
        if (!clip(boxes_[m], ray, t0, t1)) continue;
        const RGB sigmaT = scene_.media()[m].medium->sigmaT();
        if (mode_ == BoundaryMode::Bbox) {
            tau += sigmaT * (t1 - t0);
            continue;
        }
        for (double t = t0 + rng.uniform() * step_; t < t1; t += step_)
            if (inside(m, ray.at(t))) tau += sigmaT * step_;
    }
    return exp(-tau);
}

RGB SingleScatterIntegrator::inScattered(size_t m, const glm::dvec3& p, const glm::dvec3& d, int64_t tet, Rng& rng) const {
    if (mode_ == BoundaryMode::Tet) return directInMedium(scene_, int(m), p, d, uint32_t(tet), rng);
    return sampleDirect(scene_, p, rng, false, phaseScattering(scene_.media()[m].medium->phase(), d),
                        [&](const Ray& r, double t) { return visibility(r, t, rng); });
}

RGB SingleScatterIntegrator::marchTets(size_t m, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const {
    const Medium& medium = *scene_.media()[m].medium;
    const MediumParams& params = medium.params();
    // One sample every step_ of the medium's own length along the ray (random offset), across
    // tet faces: as many samples as the parity march takes inside, each with the exact
    // transmittance up to it. Each sample stands for step_, an unbiased estimate of the integral.
    double next = rng.uniform() * step_, walked = 0;  // medium length: of the next sample, before this segment
    RGB tr(1);
    medium.volume().traverse(ray, 0, tMax, [&](const WalkSegment& s) {
        const double length = s.tOut - s.tIn;
        for (; next < walked + length; next += step_) {
            const double t = s.tIn + (next - walked);
            const glm::dvec3 p = ray.at(t);
            const RGB trHere = tr * exp(-medium.sigmaT() * medium.densityIntegral(s.tet, ray, s.tIn, t));
            L += beta * trHere * (step_ * medium.density(s.tet, p)) * (params.sigmaS * inScattered(m, p, ray.d, s.tet, rng) + params.emission);
        }
        walked += length;
        tr *= exp(-medium.sigmaT() * medium.densityIntegral(s.tet, ray, s.tIn, s.tOut));
        return true;
    });
    return tr;
}

RGB SingleScatterIntegrator::marchSteps(size_t m, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const {
    double t0 = 0, t1 = tMax;
    if (!clip(boxes_[m], ray, t0, t1)) return RGB(1);
    const MediumParams& params = scene_.media()[m].medium->params();
    const RGB sigmaT = params.sigmaA + params.sigmaS;
    RGB tau(0);
    // pbrt-v2's march: each step's sample stands for the whole step.
    for (double t = t0 + rng.uniform() * step_; t < t1; t += step_) {
        const glm::dvec3 p = ray.at(t);
        if (!inside(m, p)) continue;
        tau += sigmaT * step_;
        L += beta * exp(-tau) * step_ * (params.sigmaS * inScattered(m, p, ray.d, -1, rng) + params.emission);
    }
    return exp(-tau);
}

RGB SingleScatterIntegrator::march(const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const {
    RGB tr(1);
    for (size_t m = 0; m < boxes_.size(); ++m)
        tr *= mode_ == BoundaryMode::Tet ? marchTets(m, ray, tMax, beta * tr, rng, L) : marchSteps(m, ray, tMax, beta * tr, rng, L);
    return tr;
}

RGB SingleScatterIntegrator::radiance(const Ray& cameraRay, Rng& rng) const {
    RGB L(0), beta(1);
    Ray ray = cameraRay;
    for (int depth = 0; depth < maxDepth_; ++depth) {
        const auto hit = scene_.intersectOpaque(ray);
        beta *= march(ray, hit ? hit->t : INFINITY, beta, rng, L);
        if (!hit || hit->kind == HitKind::Light) {
            L += beta * scene_.emitted(ray, hit ? &*hit : nullptr);
            break;
        }
        const MaterialDesc& material = scene_.material(*hit);
        if (!isSpecular(material)) {
            L += beta * sampleDirect(scene_, hit->p, rng, false, [&](const glm::dvec3& wi) {
                return Scattering{evaluateMaterial(material, ray.d, hit->n, wi), 0};
            }, [&](const Ray& r, double t) { return visibility(r, t, rng); });
            break;
        }
        const double u0 = rng.uniform(), u1 = rng.uniform();
        const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1});
        beta *= bs.weight;
        ray = {hit->p, bs.direction};
    }
    return L;
}

}  // namespace tetglow
