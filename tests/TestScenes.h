// Small scenes the render tests build: a sphere of medium in front of the camera.
#pragma once
#include "integrators/Integrator.h"
#include "scene/SceneDescription.h"

namespace tetglow::test {

// A unit icosphere medium at the origin (vertices rounded to float, as the loader does).
MediumDesc sphereMedium(const RGB& sigmaA, const RGB& sigmaS, double g = 0, int subdivisions = 3);
// The camera looks at the origin from z = 4 over a square image.
SceneDesc sceneWith(const MediumDesc& medium, int resolution);
LightDesc environment(double radiance);
LightDesc pointLight(const glm::dvec3& position, const RGB& intensity);
// A glowing, scattering, absorbing sphere (chromatic) under a quad light in a sky: every kind of
// light an integrator handles, for tests of determinism and of unchanged means.
SceneDesc glowingSphereUnderQuad(int resolution);

// The mean over the pixels of an image rendered with `spp` samples (or passes) per pixel.
RGB meanImage(const Scene& scene, Integrator&& integrator, int spp);

}  // namespace tetglow::test
