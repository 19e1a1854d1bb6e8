#include "integrators/SingleScatterIntegrator.h"

#include <algorithm>
#include <cmath>

#include "integrators/DirectLighting.h"
#include "integrators/PathStep.h"
#include "scene/Material.h"
#include "scene/UnsampledLight.h"
#include "tet/InteriorRepair.h"

namespace tetglow {

SingleScatterIntegrator::SingleScatterIntegrator(const Scene& scene, const IntegratorDesc& desc)
    : scene_(scene),
      mode_(desc.boundary),
      step_(desc.stepSize),
      parityRays_(desc.parityRays),
      maxDepth_(desc.maxDepth) {
    for (const SceneVolume& v : scene.volumes()) {
        if (mode_ != BoundaryMode::Tet && !v.volume->homogeneous())
            throw InputError(v.name +
                             ": the parity and bbox boundary modes need a homogeneous medium (no per-vertex density)");
        boxes_.push_back(v.volume->traversal().bounds());
        const TetMesh& mesh = v.volume->mesh();
        std::vector<int> depth(v.regionMedium.size(), 0);
        for (size_t r = 0; r < depth.size(); ++r)
            for (int32_t p = mesh.regionParent[r]; p >= 0; p = mesh.regionParent[size_t(p)]) ++depth[r];
        std::vector<int> order(v.regionMedium.begin(), v.regionMedium.end());
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return depth[size_t(scene.media()[a].region)] > depth[size_t(scene.media()[b].region)];
        });
        innermostFirst_.push_back(std::move(order));
    }
    if (mode_ == BoundaryMode::Tet) return;
    for (const MediumDesc& m : scene.desc().media) {
        TriangleMesh own = m.boundary;
        prepareSurface(own, m.tetOptions.strict);  // the mesh as its tets have it (repaired where broken)
        mediumBoxes_.push_back(bounds(own));
        parity_.push_back(mode_ == BoundaryMode::Parity ? std::make_unique<SurfaceBVH>(own.positions, own.triangles)
                                                        : nullptr);
    }
}

SingleScatterIntegrator::~SingleScatterIntegrator() = default;

int SingleScatterIntegrator::pick(size_t v, const glm::dvec3& p) const {
    for (int m : innermostFirst_[v]) {
        if (mode_ == BoundaryMode::Bbox ? mediumBoxes_[m].contains(p) : insideByParity(*parity_[m], p, parityRays_))
            return m;
    }
    return -1;
}

RGB SingleScatterIntegrator::visibility(const Ray& ray, double tMax, Rng& rng) const {
    if (mode_ == BoundaryMode::Tet) return transmittance(scene_, ray, tMax, scene_.volumeAt(ray.o));
    if (!scene_.unoccluded(ray, tMax)) return RGB(0);
    // The parity baseline's shadow ray: march through each volume's box, asking the boundary test per step.
    RGB tau(0);
    for (size_t v = 0; v < boxes_.size(); ++v) {
        double t0 = 0, t1 = tMax;
        if (!clip(boxes_[v], ray, t0, t1)) continue;
        if (mode_ == BoundaryMode::Bbox) {
            // Exactly: between consecutive box faces along the ray, one medium is picked.
            std::vector<double> cuts{t0, t1};
            for (int m : innermostFirst_[v]) {
                double a = t0, b = t1;
                if (clip(mediumBoxes_[m], ray, a, b)) {
                    cuts.push_back(a);
                    cuts.push_back(b);
                }
            }
            std::sort(cuts.begin(), cuts.end());
            for (size_t i = 0; i + 1 < cuts.size(); ++i)
                if (const int m = pick(v, ray.at(0.5 * (cuts[i] + cuts[i + 1]))); m >= 0)
                    tau +=
                        scene_.volumes()[v].volume->region(scene_.media()[m].region).sigmaT * (cuts[i + 1] - cuts[i]);
            continue;
        }
        for (double t = t0 + rng.uniform() * step_; t < t1; t += step_)
            if (const int m = pick(v, ray.at(t)); m >= 0)
                tau += scene_.volumes()[v].volume->region(scene_.media()[m].region).sigmaT * step_;
    }
    return exp(-tau);
}

RGB SingleScatterIntegrator::inScattered(size_t v, const Medium& medium, const glm::dvec3& p, const glm::dvec3& d,
                                         int64_t tet, Rng& rng) const {
    // Exact transmittance: the parity baseline's march is the baseline, compared mode against mode.
    if (mode_ == BoundaryMode::Tet) return directInMedium(scene_, int(v), p, d, uint32_t(tet), rng, false);
    return sampleDirect(scene_, p, rng, false, phaseScattering(medium.phase, d),
                        [&](const Ray& r, double t) { return visibility(r, t, rng); });
}

RGB SingleScatterIntegrator::marchTets(size_t v, const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const {
    const Volume& volume = *scene_.volumes()[v].volume;
    // One sample every step_ of the volume's own length along the ray (random offset), across
    // tet faces and interfaces: as many samples as the parity march takes inside, each with the
    // exact transmittance up to it. Each sample stands for step_, an unbiased estimate of the integral.
    double next = rng.uniform() * step_, walked = 0;  // length in the volume: of the next sample, before this segment
    RGB tr(1);
    volume.traversal().traverse(ray, 0, tMax, [&](const WalkSegment& s) {
        const Medium& medium = volume.at(s.tet);
        const double length = s.tOut - s.tIn;
        for (; next < walked + length; next += step_) {
            const double t = s.tIn + (next - walked);
            const glm::dvec3 p = ray.at(t);
            const RGB trHere = tr * exp(-medium.sigmaT * volume.densityIntegral(s.tet, ray, s.tIn, t));
            L += beta * trHere * (step_ * volume.density(s.tet, p)) *
                 (medium.params.sigmaS * inScattered(v, medium, p, ray.d, s.tet, rng) + medium.params.emission);
        }
        walked += length;
        tr *= exp(-medium.sigmaT * volume.densityIntegral(s.tet, ray, s.tIn, s.tOut));
        return true;
    });
    return tr;
}

RGB SingleScatterIntegrator::marchSteps(size_t v, const Ray& ray, double tMax, const RGB& beta, Rng& rng,
                                        RGB& L) const {
    double t0 = 0, t1 = tMax;
    if (!clip(boxes_[v], ray, t0, t1)) return RGB(1);
    const Volume& volume = *scene_.volumes()[v].volume;
    RGB tau(0);
    // pbrt-v2's march: each step's sample stands for the whole step.
    for (double t = t0 + rng.uniform() * step_; t < t1; t += step_) {
        const glm::dvec3 p = ray.at(t);
        const int m = pick(v, p);
        if (m < 0) continue;
        const Medium& medium = volume.region(scene_.media()[m].region);
        tau += medium.sigmaT * step_;
        L += beta * exp(-tau) * step_ *
             (medium.params.sigmaS * inScattered(v, medium, p, ray.d, -1, rng) + medium.params.emission);
    }
    return exp(-tau);
}

RGB SingleScatterIntegrator::march(const Ray& ray, double tMax, const RGB& beta, Rng& rng, RGB& L) const {
    RGB tr(1);
    for (size_t v = 0; v < boxes_.size(); ++v)
        tr *= mode_ == BoundaryMode::Tet ? marchTets(v, ray, tMax, beta * tr, rng, L)
                                         : marchSteps(v, ray, tMax, beta * tr, rng, L);
    return tr;
}

std::vector<std::string> SingleScatterIntegrator::warnings() const {
    return unsampledLightWarnings(scene_, IntegratorType::Single);
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
            L += beta * sampleDirect(
                            scene_, hit->p, rng, false,
                            [&](const glm::dvec3& wi) {
                                return Scattering{evaluateMaterial(material, ray.d, hit->n, wi), 0};
                            },
                            [&](const Ray& r, double t) { return visibility(r, t, rng); });
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
