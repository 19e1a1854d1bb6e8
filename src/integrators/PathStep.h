// The events every path loop shares: the volpath integrator's path, the photon integrator's
// eye path, the photon tracer's light path and shadow rays (transmittance, below). Each loop
// walks the medium of a straight stretch its own way (free flights, the column profile, the
// photon walk, the transmittance), then ends the stretch here: the walk's exact exit face
// replaces Embree's float hit, index-matched boundaries are crossed, and what is left is an
// escape, an emitter or a surface event. After a surface event the path leaves the surface
// here; Russian roulette is one of media/Roulette.h's two rules.
#pragma once
#include <optional>

#include "media/ShadowRay.h"
#include "sampling/Rng.h"
#include "scene/Scene.h"

namespace tetglow {

// Index-matched boundaries do not count as events; this cap on the straight stretches of one
// path only guards against rays that graze a boundary forever.
inline constexpr int kMaxCrossings = 100000;

// How a straight stretch of a path ends.
enum class StretchEnd {
    Escaped,  // no hit: the environment, if any, is what the path sees
    Emitter,  // an area light, which absorbs
    Crossed,  // an index-matched boundary: ray and state now go on beyond it
    Surface,  // a material event at *hit
};

// Ends a stretch that began in `state`: where the walk through the medium left the volume or
// stopped at a dielectric interface (exit.left; a default exit outside media), the walk's exit face is the surface, not
// the float hit. On Crossed, ray and state are the ones beyond the boundary. *moved receives how far along the old ray
// the new one starts (0 when it keeps its origin).
StretchEnd endStretch(const Scene& scene, std::optional<Intersection>& hit, const WalkExit& exit, Ray& ray,
                      VolumeState& state, double* moved = nullptr);

// The path leaves a surface hit in direction d: its new ray starts at the hit, in the medium
// on that side.
void leaveSurface(const Scene& scene, const Intersection& hit, const glm::dvec3& d, Ray& ray, VolumeState& state);

// A shadow ray's loop: the transmittance along ray (unit direction) up to tMax, starting in
// `state`. Index-matched boundaries and media pass light; anything else blocks it. With
// `roulette`, walks through media end early by Russian roulette (shadowFlight): the same
// expectation for less work, as next-event estimation wants.
RGB transmittance(const Scene& scene, Ray ray, double tMax, VolumeState state, Rng* roulette = nullptr);

}  // namespace tetglow
