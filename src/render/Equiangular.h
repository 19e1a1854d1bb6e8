// Equiangular distance sampling (Kulla and Fajardo 2012, "Importance sampling techniques for
// path tracing in participating media"): distances t in [0, tEnd] along a ray with pdf
// proportional to 1 / |ray.at(t) - light|^2, the factor of single scattering from a point light
// that free-flight sampling ignores, and which dominates near the light.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "tet/Ray.h"

namespace tetglow {

class Equiangular {
public:
    // `ray` has a unit direction; tEnd is finite.
    Equiangular(const Ray& ray, const glm::dvec3& light, double tEnd) : tEnd_(tEnd) {
        delta_ = glm::dot(light - ray.o, ray.d);
        // The light's distance from the line; a light on the line itself has a non-integrable
        // 1 / r^2 there, and is kept just off it.
        const glm::dvec3 foot = ray.o + delta_ * ray.d;
        h_ = std::max(glm::length(light - foot), 1e-9 * std::max(1.0, std::abs(delta_)));
        thetaA_ = std::atan2(-delta_, h_), thetaB_ = std::atan2(tEnd - delta_, h_);
    }
    double sample(double u) const { return std::clamp(delta_ + h_ * std::tan(thetaA_ + u * (thetaB_ - thetaA_)), 0.0, tEnd_); }
    double pdf(double t) const {
        const double x = t - delta_;
        return h_ / ((thetaB_ - thetaA_) * (h_ * h_ + x * x));
    }

private:
    double tEnd_;
    double delta_, h_, thetaA_, thetaB_;  // the foot of the light on the ray, its distance, the angles of 0 and tEnd
};

}  // namespace tetglow
