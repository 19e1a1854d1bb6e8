#include "integrators/PathStep.h"
#include "media/ShadowRay.h"

namespace tetglow {

StretchEnd endStretch(const Scene& scene, std::optional<Intersection>& hit, const WalkExit& exit, Ray& ray,
                      VolumeState& state, double* moved) {
    if (moved) *moved = 0;
    if (exit.left) hit = scene.boundaryHit(state.volume, ray, exit);
    if (!hit) return StretchEnd::Escaped;
    if (hit->kind == HitKind::Light) return StretchEnd::Emitter;
    if (scene.crossInterface(*hit, ray, state, moved)) return StretchEnd::Crossed;
    return StretchEnd::Surface;
}

void leaveSurface(const Scene& scene, const Intersection& hit, const glm::dvec3& d, Ray& ray, VolumeState& state) {
    state = scene.afterHit(hit, d, state);
    ray = {hit.p, d};
}

namespace {

// Decides the roulette tests a shadow ray from inside `state`'s volume surely reaches (sureDepth);
// false where one ended it.
bool surelyReached(const Volume& volume, const Ray& ray, double tMax, const VolumeState& state, Rng& rng,
                   ShadowRoulette& roulette) {
    return !volume.deepShadows() || roulette.reach(sureDepth(volume, state.start, ray.o, tMax), rng);
}

}  // namespace

RGB transmittance(const Scene& scene, Ray ray, double tMax, VolumeState state, Rng* roulette) {
    RGB tr(1);
    // Deep in a dense region the roulette's first tests surely come: decided before any query,
    // they spare most such rays the surface query and the walk.
    ShadowRoulette first;
    if (roulette && state.inside() &&
        !surelyReached(*scene.volumes()[state.volume].volume, ray, tMax, state, *roulette, first))
        return RGB(0);
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        auto hit = scene.intersect(ray, state, tMax);
        // An opaque or specular surface blocks the ray whatever lies before it: no walk needed.
        if (hit && !scene.indexMatched(*hit)) return RGB(0);
        WalkExit exit;
        if (state.inside()) {
            const Volume& volume = *scene.volumes()[state.volume].volume;
            const double end = hit ? hit->t : tMax;
            const FreeFlight f = roulette ? shadowFlight(volume, ray, state.start, end, *roulette,
                                                         crossings == 0 ? first : ShadowRoulette{})
                                          : sampleFlight(volume, ray, state.start, end, 0, 1.0);
            tr *= f.transmittance;
            if (isBlack(tr)) return tr;
            exit = f.exit;
        }
        double moved = 0;
        // The walk's exit face may be a dielectric interface, which blocks.
        switch (endStretch(scene, hit, exit, ray, state, &moved)) {
            case StretchEnd::Escaped: return tr;
            case StretchEnd::Crossed: tMax -= moved; break;
            default: return RGB(0);
        }
    }
    return RGB(0);
}

}  // namespace tetglow
