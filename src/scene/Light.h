// Light sources: point, spot and distant (delta), area emitters on triangles (quads, meshes,
// and spot lights with a radius), and a constant environment. Each can also emit photons.
#pragma once
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "base/Ray.h"
#include "base/Spectrum.h"
#include "scene/LightFocus.h"
#include "scene/SceneDescription.h"

namespace tetglow {

struct LightSample {
    RGB L{0};             // radiance arriving along -wi (delta lights: intensity / distance^2)
    glm::dvec3 wi{0};     // unit, from the receiving point towards the light
    double distance = 0;  // to the sampled point on the light (infinite for the environment)
    double pdf = 0;       // solid angle; 1 for delta lights
    bool delta = false;
};

// A photon leaving a light: where, which way, and the flux it carries (Le |cos| / pdf).
struct PhotonEmission {
    Ray ray;  // unit direction
    RGB flux{0};
};

class Light {
public:
    virtual ~Light() = default;
    // A direction towards the light as seen from p.
    virtual LightSample sample(const glm::dvec3& p, const glm::dvec2& u) const = 0;
    // The solid-angle pdf of sample() for a ray from p that reached the light (area lights: at
    // `point` on `triangle`; the environment: escaped along wi). 0 for delta lights.
    virtual double pdf(const glm::dvec3& p, const glm::dvec3& wi, const glm::dvec3& point, uint32_t triangle) const = 0;
    // Radiance leaving the light towards -wi, for a ray along wi that reached it.
    virtual RGB emitted(const glm::dvec3& wi, uint32_t triangle) const = 0;
    // A photon drawn from the light's emission (position from uPos, direction from uDir); the
    // mean of flux over draws is power().
    virtual PhotonEmission emitPhoton(const glm::dvec2& uPos, const glm::dvec2& uDir) const = 0;
    // What the light sends to p, as radiance integrated over directions (averaged over RGB),
    // ignoring occlusion and roughly: for choosing which light to sample at p, so it must be
    // > 0 wherever the light can reach p.
    virtual double importance(const glm::dvec3& p) const = 0;
    // Total emitted power, per channel.
    virtual RGB power() const = 0;
    // Where a small light's emission comes from (point and spot lights), for sampling points
    // along rays near it; null for the others.
    virtual std::optional<LightFocus> focus() const { return std::nullopt; }
    virtual bool isDelta() const { return false; }
    virtual bool isEnvironment() const { return false; }
    // Emitting triangles, placed in the scene so that rays can hit them (empty for the others).
    virtual const TriangleMesh* shape() const { return nullptr; }
};

// pbrt-v3's spot profile: 1 inside the inner cone, 0 outside the outer, ((cos - cosTotal) /
// (cosStart - cosTotal))^4 between.
struct SpotProfile {
    glm::dvec3 axis;  // unit
    double cosTotal, cosStart;
    SpotProfile(const glm::dvec3& axis, double coneAngleDeg, double coneDeltaDeg);
    double falloff(const glm::dvec3& w) const;  // w: unit direction leaving the light
    // A direction uniform within the outer cone, its pdf, and the integral of falloff over
    // the sphere.
    glm::dvec3 sampleCone(const glm::dvec2& u) const;
    double conePdf() const;
    double solidAngle() const;
    // The cone that holds every point lit from a disk of `radius` at `centre` facing the axis
    // (the point light's own cone for 0); null where the cone is too wide to be convex.
    std::optional<LightCone> litCone(const glm::dvec3& centre, double radius) const;
};

// Lights at infinity (distant, environment) emit photons over a disk that covers the sphere
// bounding the scene's geometry, `sceneBounds`.
std::unique_ptr<Light> makeLight(const LightDesc& desc, const Bounds3& sceneBounds);

}  // namespace tetglow
