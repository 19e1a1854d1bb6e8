// The photon integrator's eye path: specular chains, the media's estimates along each stretch,
// and a diffuse surface's direct light and caustics.
#include <algorithm>

#include "integrators/DirectLighting.h"
#include "integrators/PathStep.h"
#include "media/Roulette.h"
#include "photon/PhotonIntegrator.h"
#include "scene/Material.h"

namespace tetglow {

RGB PhotonIntegrator::eyePath(const Ray& cameraRay, Rng& rng, int walkedToo, char* met, EyeLight light) const {
    EyeBranch camera;
    camera.ray = cameraRay;
    camera.state = cameraMedium_;
    camera.light = light;
    return eyePath(camera, rng, walkedToo, met);
}

RGB PhotonIntegrator::eyePath(EyeBranch b, Rng& rng, int walkedToo, char* met) const {
    RGB L(0);
    Ray& ray = b.ray;
    VolumeState& state = b.state;
    RGB& beta = b.beta;
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        auto hit = scene_.intersect(ray, state);
        WalkExit exit;
        // Whether light that reaches the eye here (emitted along the stretch, or from an emitter
        // it ends on) came along a specular chain, and whether this path gathers such light. A
        // glowing medium seen along a chain is chain light too: the lure, seen by total internal
        // reflection in the fish's skin, is a rare and bright sample.
        const bool chain = b.depth > 0 && !b.gathering;
        const bool gathersEmission = b.light == EyeLight::All || (b.light == EyeLight::ChainLight) == chain;
        if (state.inside() && b.light == EyeLight::ChainLight && !walksAny_) {
            const ChainStretch s =
                chainStretch(state.volume, ray, state.start, hit ? hit->t : INFINITY, gathersEmission);
            L += beta * s.emitted;
            beta *= s.transmittance;
            if (isBlack(beta)) break;
            exit = s.exit;
        } else if (state.inside()) {
            const double tMax = hit ? hit->t : INFINITY;
            const Volume& volume = *scene_.volumes()[state.volume].volume;
            const ColumnProfile column(volume, ray, state.start, tMax);
            // A walked domain on the stretch: walk the stretch (and all after) as volpath does, from
            // its start. Restarted where the domain begins, on a tet's face, the walk would follow
            // the rounded line from there, which can miss a tet the stretch only touches.
            const auto& pieces = column.pieces();
            if (std::any_of(pieces.begin(), pieces.end(), [&](const auto& p) {
                    const int d = domainOf(state.volume, p.tet);
                    return media_[size_t(d)].walked || d == walkedToo;
                })) {
                if (b.light != EyeLight::ChainLight)
                    L += beta * volpath_.continuePath(ray, state, b.depth, !b.gathering, rng);
                break;
            }
            if (met)
                for (const auto& p : pieces) met[domainOf(state.volume, p.tet)] = 1;
            if (gathersEmission) L += beta * emittedAlong(state.volume, column);
            if (b.light != EyeLight::ChainLight) L += beta * scatteredAlong(state.volume, ray, column, rng);
            beta *= exp(-column.depth());
            if (isBlack(beta)) break;
            exit = column.exit();
        }
        const StretchEnd end = endStretch(scene_, hit, exit, ray, state);
        if (end == StretchEnd::Crossed) continue;
        if (end != StretchEnd::Surface) {
            // Emitters the final gather's bounce reaches were counted by next-event estimation.
            if (!b.gathering && gathersEmission) L += beta * scene_.emitted(ray, hit ? &*hit : nullptr);
            break;
        }
        const MaterialDesc& material = scene_.material(*hit);
        if (!isSpecular(material)) {
            if (b.light == EyeLight::ChainLight) break;
            const VolumeState here = scene_.afterHit(*hit, ray.d, state);
            L += beta * sampleDirect(
                            scene_, hit->p, rng, false,
                            [&](const glm::dvec3& wi) {
                                return Scattering{evaluateMaterial(material, ray.d, hit->n, wi), 0};
                            },
                            shadowRays(scene_, here, rng));
            if (b.gathering || !desc_.finalGather) {
                L += beta * caustics(surface_.get(), *hit, ray.d, material);
                break;
            }
            L += beta * caustics(caustic_.get(), *hit, ray.d, material);
            b.gathering = true;
        }
        if (++b.depth >= desc_.maxDepth) break;
        if (material.type == MaterialType::Dielectric && b.splits > 0) {
            // Both branches, weighted by the Fresnel reflectance, in place of a choice between
            // them: a small bright light seen in the glass or through it is otherwise a sample
            // of its full radiance in a few percent of the samples (the variance of the pixels
            // that see it dominated the image's error).
            const DielectricBranches branches = dielectricBranches(material.ior, ray.d, hit->n);
            if (branches.reflectance < 1) {  // else totally reflected: nothing to choose
                --b.splits;
                EyeBranch reflected = b;
                reflected.beta *= branches.reflectance;
                leaveSurface(scene_, *hit, branches.reflected, reflected.ray, reflected.state);
                if (branches.reflectance > 0) L += eyePath(reflected, rng, walkedToo, met);
                beta *= (1 - branches.reflectance) * branches.radianceScale;
                leaveSurface(scene_, *hit, branches.transmitted, ray, state);
                continue;
            }
        }
        const double u0 = rng.uniform(), u1 = rng.uniform();
        const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1});
        beta *= bs.weight;
        leaveSurface(scene_, *hit, bs.direction, ray, state);
        const double keep = eyePathSurvival(beta, b.depth, rng);  // on long specular chains
        if (keep == 0) break;
        beta /= keep;
    }
    return L;
}

}  // namespace tetglow
