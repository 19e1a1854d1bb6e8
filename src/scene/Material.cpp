#include "scene/Material.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "sampling/Sampling.h"

namespace tetglow {

double fresnelDielectric(double cosI, double etaI, double etaT) {
    const double sinT = etaI / etaT * std::sqrt(std::max(0.0, 1 - cosI * cosI));
    if (sinT >= 1) return 1;  // total internal reflection
    const double cosT = std::sqrt(std::max(0.0, 1 - sinT * sinT));
    const double rs = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    const double rp = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

DielectricBranches dielectricBranches(double ior, const glm::dvec3& d, const glm::dvec3& n) {
    const bool entering = glm::dot(d, n) < 0;
    const glm::dvec3 facing = entering ? n : -n;  // towards the side the ray comes from
    const double etaI = entering ? 1 : ior, etaT = entering ? ior : 1;
    const double cosI = std::min(1.0, -glm::dot(d, facing));
    DielectricBranches b;
    b.reflectance = fresnelDielectric(cosI, etaI, etaT);
    b.reflected = glm::normalize(d + 2 * cosI * facing);
    const double eta = etaI / etaT, cosT = std::sqrt(std::max(0.0, 1 - eta * eta * (1 - cosI * cosI)));
    b.transmitted = glm::normalize(eta * d + (eta * cosI - cosT) * facing);
    b.radianceScale = eta * eta;
    return b;
}

namespace {

BsdfSample sampleDielectric(double ior, const glm::dvec3& d, const glm::dvec3& n, double u, TransportMode mode) {
    const DielectricBranches b = dielectricBranches(ior, d, n);
    BsdfSample s;
    s.specular = true;
    s.weight = RGB(1);
    if (u < b.reflectance) {
        s.direction = b.reflected;
        return s;
    }
    s.direction = b.transmitted;
    s.transmitted = true;
    if (mode == TransportMode::Radiance) s.weight = RGB(b.radianceScale);
    return s;
}

}  // namespace

BsdfSample sampleMaterial(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec2& u,
                          TransportMode mode) {
    switch (m.type) {
        case MaterialType::Interface: return {d, RGB(1), 0, true, true};
        case MaterialType::Dielectric: return sampleDielectric(m.ior, d, n, u.x, mode);
        case MaterialType::Diffuse: {
            const glm::dvec3 facing = glm::dot(d, n) < 0 ? n : -n;
            const glm::dvec3 wi = sampleCosineHemisphere(facing, u);
            const double cosine = glm::dot(wi, facing);
            return {wi, m.reflectance, cosine / kPi, false, false};
        }
    }
    return {};
}

RGB evaluateMaterial(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& wi) {
    if (m.type != MaterialType::Diffuse) return RGB(0);
    const double side = glm::dot(d, n), cosine = glm::dot(wi, n);
    // Reflection only: wi leaves on the side d arrived from.
    return side * cosine < 0 ? m.reflectance * (std::abs(cosine) / kPi) : RGB(0);
}

double materialPdf(const MaterialDesc& m, const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& wi) {
    if (m.type != MaterialType::Diffuse) return 0;
    const double side = glm::dot(d, n), cosine = glm::dot(wi, n);
    return side * cosine < 0 ? std::abs(cosine) / kPi : 0;
}

}  // namespace tetglow
