// Shadow rays through a volume: the transmittance to a light with Russian roulette, and the optical
// depth a ray surely gathers in a clear ball, which decides roulette's first tests before any walk.
#pragma once
#include "media/FreeFlight.h"
#include "media/Roulette.h"

namespace tetglow {

// The transmittance (see transmittance()) for a shadow ray, with Russian roulette once it has fallen below
// 1/20 (as pbrt-v4's ratio tracking does): the walk stops there with probability 3/4 (a
// transmittance of 0, no exit) and a survivor counts 4 times, tested again whenever its
// weighted transmittance is below 1/20 (ShadowRoulette; `roulette` may hold tests decided
// before, by sureDepth). Unbiased; deep in a dense medium a shadow ray walks a few tets, not
// all to the boundary.
FreeFlight shadowFlight(const Volume& volume, const Ray& ray, WalkStart start, double tMax, Rng& rng,
                        ShadowRoulette roulette = {});
// An optical depth (its smallest channel's) that a ray from `origin`, in the region of
// `start`'s tet, surely gathers before tMax: in a region of constant density, along the ball
// around `origin` that holds no boundary (ClearanceGrid). 0 where the density varies, the ray
// starts on the surface, or no such ball is deep enough for the shadow roulette's first test.
double sureDepth(const Volume& volume, WalkStart start, const glm::dvec3& origin, double tMax);

}  // namespace tetglow
