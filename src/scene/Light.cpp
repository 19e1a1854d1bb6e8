#include "scene/Light.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

#include <glm/geometric.hpp>

#include "sampling/Sampling.h"
#include "scene/SphericalRectangle.h"
#include "tet/Shapes.h"

namespace tetglow {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

LightSample towards(const glm::dvec3& p, const glm::dvec3& q, const RGB& intensity) {
    const glm::dvec3 v = q - p;
    const double d2 = glm::dot(v, v), d = std::sqrt(d2);
    return {intensity / d2, v / d, d, 1, true};
}

// A disk that covers the scene's bounding sphere, facing any direction: where photons from
// lights at infinity start (pbrt's infinite and distant lights).
struct SceneDisk {
    glm::dvec3 centre;
    double radius;
    explicit SceneDisk(const Bounds3& sceneBounds)
        : centre(0.5 * (sceneBounds.lo + sceneBounds.hi)), radius(std::max(0.5 * sceneBounds.diagonal(), 1e-6)) {}
    double area() const { return kPi * radius * radius; }
    // A uniform point on the disk facing d, just outside the bounding sphere, upstream of d.
    glm::dvec3 sample(const glm::dvec3& d, const Frame& frame, const glm::dvec2& u) const {
        const glm::dvec2 q = sampleUniformDisk(u) * radius;
        return centre - radius * d + q.x * frame.s + q.y * frame.t;
    }
};

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
    PhotonEmission emitPhoton(const glm::dvec2&, const glm::dvec2& u) const override {
        if (!spot_) return {{position_, sampleUniformSphere(u)}, intensity_ * (4 * kPi)};
        const glm::dvec3 w = spot_->sampleCone(u);
        return {{position_, w}, intensity_ * (spot_->falloff(w) / spot_->conePdf())};
    }
    double importance(const glm::dvec3& p) const override { return average(sample(p, {}).L); }
    RGB power() const override { return intensity_ * (spot_ ? spot_->solidAngle() : 4 * kPi); }
    std::optional<LightFocus> focus() const override {
        return LightFocus{position_, spot_ ? spot_->litCone(position_, 0) : std::nullopt};
    }
    bool isDelta() const override { return true; }

private:
    glm::dvec3 position_;
    RGB intensity_;
    std::optional<SpotProfile> spot_;
};

// Parallel light from direction -direction_ with irradiance E on a surface facing it.
class DistantLight : public Light {
public:
    DistantLight(const glm::dvec3& direction, const RGB& irradiance, const Bounds3& sceneBounds)
        : direction_(glm::normalize(direction)), irradiance_(irradiance), frame_(direction_), disk_(sceneBounds) {}
    LightSample sample(const glm::dvec3&, const glm::dvec2&) const override {
        return {irradiance_, -direction_, INFINITY, 1, true};
    }
    double pdf(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, uint32_t) const override { return 0; }
    RGB emitted(const glm::dvec3&, uint32_t) const override { return RGB(0); }
    PhotonEmission emitPhoton(const glm::dvec2& u, const glm::dvec2&) const override {
        return {{disk_.sample(direction_, frame_, u), direction_}, power()};
    }
    double importance(const glm::dvec3&) const override { return average(irradiance_); }
    RGB power() const override { return irradiance_ * disk_.area(); }
    bool isDelta() const override { return true; }

private:
    glm::dvec3 direction_;  // of travel
    RGB irradiance_;
    Frame frame_;
    SceneDisk disk_;
};

// Triangles emitting radiance, uniform over area; or, with a spot profile, radiance
// I * falloff / (area * cos) so that the whole emitter has the spot light's intensity.
// Sampled by area, or a rectangle by solid angle (SphericalRectangle) where that is well
// conditioned.
class AreaLight : public Light {
public:
    AreaLight(TriangleMesh mesh, const RGB& radiance, bool twoSided)
        : mesh_(std::move(mesh)), radiance_(radiance), twoSided_(twoSided) {
        // Float-exact, as Embree sees them, so sampled points lie on the triangles rays hit.
        for (auto& p : mesh_.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
        double total = 0;
        for (uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
            const glm::dvec3 n =
                glm::cross(mesh_.corner(t, 1) - mesh_.corner(t, 0), mesh_.corner(t, 2) - mesh_.corner(t, 0));
            normals_.push_back(glm::normalize(n));
            const double a = 0.5 * glm::length(n);
            cdf_.push_back(total += a);
            centroid_ += a / 3 * (mesh_.corner(t, 0) + mesh_.corner(t, 1) + mesh_.corner(t, 2));
        }
        area_ = total;
        centroid_ /= area_;
    }
    void setSpot(const SpotProfile& profile, const RGB& intensity) {
        spot_ = profile;
        radiance_ = intensity / area_;
    }
    // The mesh is the rectangle positions[0] + a (positions[1] - positions[0]) + b (positions[3]
    // - positions[0]); its edges are made exactly orthogonal (they are to float rounding).
    void setRectangle() {
        const glm::dvec3 corner = mesh_.positions[0], ex = mesh_.positions[1] - corner,
                         ey = mesh_.positions[3] - corner;
        rectangle_ = {corner, ex, ey - glm::dot(ey, ex) / glm::dot(ex, ex) * ex};
    }

    LightSample sample(const glm::dvec3& p, const glm::dvec2& u) const override {
        // The spherical rectangle (four arccosines) is built once, for the point and its pdf.
        const auto r = sphericalRectangle(p);
        uint32_t tri = 0;
        glm::dvec3 q;
        if (r)
            q = r->sample(u);
        else
            std::tie(tri, q) = samplePoint(u);
        LightSample s = towards(p, q, RGB(0));
        s.delta = false;
        s.pdf = r ? 1 / r->solidAngle() : areaPdf(p, s.wi, q, tri);
        s.L = s.pdf > 0 ? emitted(s.wi, tri) : RGB(0);
        return s;
    }
    double pdf(const glm::dvec3& p, const glm::dvec3& wi, const glm::dvec3& point, uint32_t triangle) const override {
        if (const auto r = sphericalRectangle(p)) return 1 / r->solidAngle();
        return areaPdf(p, wi, point, triangle);
    }
    RGB emitted(const glm::dvec3& wi, uint32_t triangle) const override {
        const double cosLight = -glm::dot(wi, normals_[triangle]);  // > 0 on the front
        if (!(cosLight > 0 || (twoSided_ && cosLight < 0))) return RGB(0);
        return spot_ ? radiance_ * spot_->falloff(-wi) / std::abs(cosLight) : radiance_;
    }
    PhotonEmission emitPhoton(const glm::dvec2& uPos, const glm::dvec2& uDir) const override {
        const auto [tri, p] = samplePoint(uPos);
        if (spot_) {
            // Directions uniform in the cone: flux = L cos / (pdfArea pdfDir) = I falloff / pdfDir.
            const glm::dvec3 w = spot_->sampleCone(uDir);
            return {{p, w}, radiance_ * area_ * (spot_->falloff(w) / spot_->conePdf())};
        }
        glm::dvec3 n = normals_[tri];
        glm::dvec2 u = uDir;
        if (twoSided_) {
            // Half of u.x picks the side, the rest is reused for the direction.
            const bool back = u.x < 0.5;
            u.x = back ? 2 * u.x : 2 * u.x - 1;
            if (back) n = -n;
        }
        return {{p, sampleCosineHemisphere(n, u)}, power()};
    }
    // Radiance (at most radiance_) times an estimate of the solid angle the light covers from
    // p: area / distance^2 to its centroid, at most a hemisphere.
    double importance(const glm::dvec3& p) const override {
        const glm::dvec3 v = centroid_ - p;
        return average(radiance_) * std::min(2 * kPi, area_ / glm::dot(v, v));
    }
    RGB power() const override {
        if (spot_) return radiance_ * area_ * spot_->solidAngle();
        return radiance_ * (kPi * area_ * (twoSided_ ? 2 : 1));
    }
    const TriangleMesh* shape() const override { return &mesh_; }
    // A spot light's disk is small and lights a cone; other emitters are focused on nothing.
    std::optional<LightFocus> focus() const override {
        if (!spot_) return std::nullopt;
        double radius = 0;
        for (const auto& p : mesh_.positions) radius = std::max(radius, glm::length(p - centroid_));
        return LightFocus{centroid_, spot_->litCone(centroid_, radius)};
    }

private:
    struct Rectangle {
        glm::dvec3 corner, ex, ey;
    };
    // The rectangle seen from p, unless its solid angle there is below 1e-5 sr: in double
    // precision the mapping's angles then cancel (measured: 1e-7 relative error in the solid
    // angle at 2e-8 sr), and area sampling is uniform in solid angle to within that sliver.
    // From p in its plane it is NaN or 0: area sampling too. (pbrt-v4's float bounds, 3e-4 and
    // 6.22 sr, are not needed: 1e-8 from the plane, in double, the estimate is still exact.)
    std::optional<SphericalRectangle> sphericalRectangle(const glm::dvec3& p) const {
        if (!rectangle_) return std::nullopt;
        const SphericalRectangle r(p, rectangle_->corner, rectangle_->ex, rectangle_->ey);
        if (!(r.solidAngle() >= 1e-5)) return std::nullopt;
        return r;
    }
    // The solid-angle pdf of area sampling.
    double areaPdf(const glm::dvec3& p, const glm::dvec3& wi, const glm::dvec3& point, uint32_t triangle) const {
        const double cosLight = std::abs(glm::dot(wi, normals_[triangle]));
        const glm::dvec3 v = point - p;
        return cosLight > 0 ? glm::dot(v, v) / (cosLight * area_) : 0;
    }
    // A triangle chosen by area with u.x, then a uniform point on it (what is left of u.x is
    // reused).
    std::pair<uint32_t, glm::dvec3> samplePoint(const glm::dvec2& u) const {
        const auto tri = uint32_t(sampleCdf(cdf_, u.x));
        const double lo = tri ? cdf_[tri - 1] : 0,
                     ux = std::clamp((u.x * area_ - lo) / (cdf_[tri] - lo), 0.0, 1.0 - 1e-16);
        const glm::dvec2 b = sampleUniformTriangle({ux, u.y});
        return {tri, b.x * mesh_.corner(tri, 0) + b.y * mesh_.corner(tri, 1) + (1 - b.x - b.y) * mesh_.corner(tri, 2)};
    }

    TriangleMesh mesh_;
    std::vector<glm::dvec3> normals_;
    std::vector<double> cdf_;
    double area_ = 0;
    glm::dvec3 centroid_{0};
    RGB radiance_;
    bool twoSided_;
    std::optional<SpotProfile> spot_;
    std::optional<Rectangle> rectangle_;
};

class EnvironmentLight : public Light {
public:
    EnvironmentLight(const RGB& radiance, const Bounds3& sceneBounds) : radiance_(radiance), disk_(sceneBounds) {}
    LightSample sample(const glm::dvec3&, const glm::dvec2& u) const override {
        return {radiance_, sampleUniformSphere(u), INFINITY, kInv4Pi, false};
    }
    double pdf(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, uint32_t) const override { return kInv4Pi; }
    RGB emitted(const glm::dvec3&, uint32_t) const override { return radiance_; }
    // pbrt's infinite light: a direction uniform on the sphere, then a point on the disk facing
    // it that covers the scene, so flux = L / (pdfDir pdfArea) = L 4 pi pi r^2.
    PhotonEmission emitPhoton(const glm::dvec2& uPos, const glm::dvec2& uDir) const override {
        const glm::dvec3 d = sampleUniformSphere(uDir);
        return {{disk_.sample(d, Frame(d), uPos), d}, power()};
    }
    double importance(const glm::dvec3&) const override { return average(radiance_) * 4 * kPi; }
    RGB power() const override { return radiance_ * (4 * kPi * disk_.area()); }
    bool isEnvironment() const override { return true; }

private:
    RGB radiance_;
    SceneDisk disk_;
};

}  // namespace

SpotProfile::SpotProfile(const glm::dvec3& axis, double coneAngleDeg, double coneDeltaDeg)
    : axis(glm::normalize(axis)),
      cosTotal(std::cos(radians(coneAngleDeg))),
      cosStart(std::cos(radians(coneAngleDeg - coneDeltaDeg))) {}

glm::dvec3 SpotProfile::sampleCone(const glm::dvec2& u) const {
    return Frame(axis).toWorld(1 - u.x * (1 - cosTotal), 2 * kPi * u.y);
}

double SpotProfile::conePdf() const { return 1 / (2 * kPi * (1 - cosTotal)); }

// Full strength out to cosStart, then the integral of delta^4 over the band: (cosStart - cosTotal) / 5.
double SpotProfile::solidAngle() const { return 2 * kPi * ((1 - cosStart) + (cosStart - cosTotal) / 5); }

std::optional<LightCone> SpotProfile::litCone(const glm::dvec3& centre, double radius) const {
    if (!(cosTotal > 0.01)) return std::nullopt;
    // Moved back along the axis until the cone's side passes the disk's rim.
    const double tanAngle = std::sqrt(1 - cosTotal * cosTotal) / cosTotal;
    return LightCone{centre - axis * (radius / tanAngle), axis, cosTotal};
}

double SpotProfile::falloff(const glm::dvec3& w) const {
    const double c = glm::dot(w, axis);
    if (c < cosTotal) return 0;
    if (c >= cosStart) return 1;
    const double delta = (c - cosTotal) / (cosStart - cosTotal);
    return (delta * delta) * (delta * delta);
}

std::unique_ptr<Light> makeLight(const LightDesc& desc, const Bounds3& sceneBounds) {
    switch (desc.type) {
        case LightType::Point: return std::make_unique<PointLight>(desc.position, desc.intensity);
        case LightType::Spot: {
            const SpotProfile profile(desc.lookAt - desc.position, desc.coneAngle, desc.coneDelta);
            if (desc.radius == 0) return std::make_unique<PointLight>(desc.position, desc.intensity, profile);
            auto light = std::make_unique<AreaLight>(disk(desc.position, profile.axis, desc.radius), RGB(0), false);
            light->setSpot(profile, desc.intensity);
            return light;
        }
        case LightType::Quad: {
            auto light =
                std::make_unique<AreaLight>(quad(desc.corner, desc.edge0, desc.edge1), desc.radiance, desc.twoSided);
            const double skew = glm::dot(desc.edge0, desc.edge1),
                         lengths = glm::length(desc.edge0) * glm::length(desc.edge1);
            if (std::abs(skew) <= 1e-9 * lengths) light->setRectangle();
            return light;
        }
        case LightType::Mesh: return std::make_unique<AreaLight>(desc.mesh, desc.radiance, desc.twoSided);
        case LightType::Distant: return std::make_unique<DistantLight>(desc.direction, desc.irradiance, sceneBounds);
        case LightType::Environment: return std::make_unique<EnvironmentLight>(desc.radiance, sceneBounds);
    }
    return nullptr;
}

}  // namespace tetglow
