#include "render/Light.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <numbers>

#include <glm/geometric.hpp>

#include "photon/Sampling.h"
#include "tet/Shapes.h"

namespace tetglow {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

LightSample towards(const glm::dvec3& p, const glm::dvec3& q, const RGB& intensity) {
    const glm::dvec3 v = q - p;
    const double d2 = glm::dot(v, v), d = std::sqrt(d2);
    return {intensity / d2, v / d, d, 1, true};
}

// A point, or with a profile pbrt-v3's spot light.
class PointLight : public Light {
public:
    PointLight(const glm::dvec3& position, const RGB& intensity, std::optional<SpotProfile> spot = std::nullopt)
        : position_(position), intensity_(intensity), spot_(spot) {}
    LightSample sample(const glm::dvec3& p, const glm::dvec2&) const override {
        LightSample s = towards(p, position_, intensity_);
        if (spot_) s.L *= spot_->falloff(-s.wi);
        return s;
    }
    double pdf(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, uint32_t) const override { return 0; }
    RGB emitted(const glm::dvec3&, uint32_t) const override { return RGB(0); }
    bool isDelta() const override { return true; }

private:
    glm::dvec3 position_;
    RGB intensity_;
    std::optional<SpotProfile> spot_;
};

// Triangles emitting radiance, uniform over area; or, with a spot profile, radiance
// I * falloff / (area * cos) so that the whole emitter has the spot light's intensity.
class AreaLight : public Light {
public:
    AreaLight(TriangleMesh mesh, const RGB& radiance, bool twoSided) : mesh_(std::move(mesh)), radiance_(radiance), twoSided_(twoSided) {
        // Float-exact, as Embree sees them, so sampled points lie on the triangles rays hit.
        for (auto& p : mesh_.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
        double total = 0;
        for (uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
            const glm::dvec3 n = glm::cross(mesh_.corner(t, 1) - mesh_.corner(t, 0), mesh_.corner(t, 2) - mesh_.corner(t, 0));
            normals_.push_back(glm::normalize(n));
            cdf_.push_back(total += 0.5 * glm::length(n));
        }
        area_ = total;
    }
    void setSpot(const SpotProfile& profile, const RGB& intensity) { spot_ = profile, radiance_ = intensity / area_; }

    LightSample sample(const glm::dvec3& p, const glm::dvec2& u) const override {
        // Pick a triangle by area with u.x, then reuse what is left of u.x for the point.
        const double target = u.x * area_;
        const auto tri = uint32_t(std::min<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin(), cdf_.size() - 1));
        const double lo = tri ? cdf_[tri - 1] : 0, ux = std::clamp((target - lo) / (cdf_[tri] - lo), 0.0, 1.0 - 1e-16);
        const glm::dvec2 b = sampleUniformTriangle({ux, u.y});
        const glm::dvec3 q = b.x * mesh_.corner(tri, 0) + b.y * mesh_.corner(tri, 1) + (1 - b.x - b.y) * mesh_.corner(tri, 2);
        LightSample s = towards(p, q, RGB(0));
        s.delta = false;
        s.pdf = pdf(p, s.wi, q, tri);
        s.L = s.pdf > 0 ? emitted(s.wi, tri) : RGB(0);
        return s;
    }
    double pdf(const glm::dvec3& p, const glm::dvec3& wi, const glm::dvec3& point, uint32_t triangle) const override {
        const double cosLight = std::abs(glm::dot(wi, normals_[triangle]));
        const glm::dvec3 v = point - p;
        return cosLight > 0 ? glm::dot(v, v) / (cosLight * area_) : 0;
    }
    RGB emitted(const glm::dvec3& wi, uint32_t triangle) const override {
        const double cosLight = -glm::dot(wi, normals_[triangle]);  // > 0 on the front
        if (!(cosLight > 0 || (twoSided_ && cosLight < 0))) return RGB(0);
        return spot_ ? radiance_ * spot_->falloff(-wi) / std::abs(cosLight) : radiance_;
    }
    const TriangleMesh* shape() const override { return &mesh_; }

private:
    TriangleMesh mesh_;
    std::vector<glm::dvec3> normals_;
    std::vector<double> cdf_;
    double area_ = 0;
    RGB radiance_;
    bool twoSided_;
    std::optional<SpotProfile> spot_;
};

class EnvironmentLight : public Light {
public:
    explicit EnvironmentLight(const RGB& radiance) : radiance_(radiance) {}
    LightSample sample(const glm::dvec3&, const glm::dvec2& u) const override {
        return {radiance_, sampleUniformSphere(u), INFINITY, kInv4Pi, false};
    }
    double pdf(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, uint32_t) const override { return kInv4Pi; }
    RGB emitted(const glm::dvec3&, uint32_t) const override { return radiance_; }
    bool isEnvironment() const override { return true; }

private:
    RGB radiance_;
};

}  // namespace

SpotProfile::SpotProfile(const glm::dvec3& axis, double coneAngleDeg, double coneDeltaDeg)
    : axis(glm::normalize(axis)), cosTotal(std::cos(radians(coneAngleDeg))), cosStart(std::cos(radians(coneAngleDeg - coneDeltaDeg))) {}

double SpotProfile::falloff(const glm::dvec3& w) const {
    const double c = glm::dot(w, axis);
    if (c < cosTotal) return 0;
    if (c >= cosStart) return 1;
    const double delta = (c - cosTotal) / (cosStart - cosTotal);
    return (delta * delta) * (delta * delta);
}

std::unique_ptr<Light> makeLight(const LightDesc& desc) {
    switch (desc.type) {
        case LightType::Point:
            return std::make_unique<PointLight>(desc.position, desc.intensity);
        case LightType::Spot: {
            const SpotProfile profile(desc.lookAt - desc.position, desc.coneAngle, desc.coneDelta);
            if (desc.radius == 0) return std::make_unique<PointLight>(desc.position, desc.intensity, profile);
            auto light = std::make_unique<AreaLight>(disk(desc.position, profile.axis, desc.radius), RGB(0), false);
            light->setSpot(profile, desc.intensity);
            return light;
        }
        case LightType::Quad:
            return std::make_unique<AreaLight>(quad(desc.corner, desc.edge0, desc.edge1), desc.radiance, desc.twoSided);
        case LightType::Environment:
            return std::make_unique<EnvironmentLight>(desc.radiance);
    }
    return nullptr;
}

}  // namespace tetglow
