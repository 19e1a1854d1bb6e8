// Small scenes the render tests build: a sphere of medium in front of the camera.
#pragma once
#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include "integrators/Integrator.h"
#include "scene/SceneDescription.h"

namespace tetglow::test {

// A unit icosphere medium at the origin (vertices rounded to float, as the loader does).
MediumDesc sphereMedium(const RGB& sigmaA, const RGB& sigmaS, double g = 0, int subdivisions = 3);
// The camera looks at the origin from z = 4 over a square image.
SceneDesc sceneWith(const MediumDesc& medium, int resolution);
LightDesc environment(double radiance);
LightDesc pointLight(const glm::dvec3& position, const RGB& intensity);
// pbrt-v3's spot light, its angles in degrees; with a radius, a disk facing lookAt.
LightDesc spotLight(const glm::dvec3& position, const glm::dvec3& lookAt, const RGB& intensity, double coneAngle,
                    double coneDelta, double radius = 0);
// A one-sided rectangle light: its front faces along cross(edge0, edge1).
LightDesc quadLight(const glm::dvec3& corner, const glm::dvec3& edge0, const glm::dvec3& edge1, const RGB& radiance);
// A glowing, scattering, absorbing sphere (chromatic) under a quad light in a sky: every kind of
// light an integrator handles, for tests of determinism and of unchanged means.
SceneDesc glowingSphereUnderQuad(int resolution);

// The mean over the pixels of an image rendered with `spp` samples (or passes) per pixel.
RGB meanImage(const Scene& scene, Integrator&& integrator, int spp);

// Mean and standard error of n estimates sample(i), i = 0 .. n - 1, and how many were black.
struct Estimate {
    RGB mean{0}, stdError{0};
    int black = 0;
};
template <class Sample>
Estimate estimateMean(int n, Sample&& sample) {
    RGB sum(0), sum2(0);
    Estimate e;
    for (int i = 0; i < n; ++i) {
        const RGB x = sample(i);
        sum += x;
        sum2 += x * x;
        e.black += isBlack(x);
    }
    e.mean = sum / double(n);
    e.stdError = glm::sqrt(glm::max(RGB(0), sum2 / double(n) - e.mean * e.mean) / double(n - 1));
    return e;
}

}  // namespace tetglow::test
