// Surface scattering: Lambertian, smooth dielectric, and the index-matched interface.
#pragma once
#include <glm/vec2.hpp>

#include "base/Spectrum.h"
#include "scene/SceneDescription.h"

namespace tetglow {

// Which way the importance flows: radiance for camera paths, power for photons. Refraction
// scales radiance by (n_from / n_to)^2 but leaves a photon's power unchanged.
enum class TransportMode { Radiance, Importance };

struct BsdfSample {
    glm::dvec3 direction{0};  // unit direction of travel after the event
    RGB weight{0};            // f * |cos| / pdf
    double pdf = 0;           // solid angle; 0 for specular events
    bool specular = false;
    bool transmitted = false;  // crossed to the other side of the surface
};

// `d` is the unit direction of travel arriving at the surface, `n` the unit geometric normal
// (either side). u: two uniform numbers.
BsdfSample sampleMaterial(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec2& u,
                          TransportMode mode = TransportMode::Radiance);
// f * |cos(wi, n)| for an arrival along d scattered to wi (0 for specular materials).
RGB evaluateMaterial(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& wi);
double materialPdf(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& wi);
inline bool isSpecular(const MaterialDesc& m) { return m.type != MaterialType::Diffuse; }

// Both ways a smooth dielectric sends a ray arriving along unit d at unit normal n (either
// side): reflected with probability `reflectance` (1 under total internal reflection, where
// `transmitted` is meaningless), else refracted, the radiance scaled by (n_from / n_to)^2.
struct DielectricBranches {
    double reflectance = 1;
    glm::dvec3 reflected{0}, transmitted{0};
    double radianceScale = 1;
};
DielectricBranches dielectricBranches(double ior, const glm::dvec3& d, const glm::dvec3& n);

// Unpolarized Fresnel reflectance for light arriving at cosine cosI (> 0) from the side with
// index etaI into the side with etaT.
double fresnelDielectric(double cosI, double etaI, double etaT);

}  // namespace tetglow
