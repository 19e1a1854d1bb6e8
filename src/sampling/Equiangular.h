// Equiangular sampling (Kulla and Fajardo 2012): a distance along a ray with pdf proportional to
// 1 / (h^2 + (t - t0)^2), the inverse squared distance to a point at height h above the ray's
// foot t0, so that single scattering from a small light needs no luck to land near it.
#pragma once
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

class Equiangular {
public:
    // Over [a, b] (a < b) of the ray o + t d (unit d), towards `centre`.
    Equiangular(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& centre, double a, double b)
        : t0_(glm::dot(centre - o, d)) {
        // A ray through the centre has h = 0 and a pdf that does not integrate: keep h off 0 by
        // a sliver of the segment, which changes the pdf nowhere the segment stays away from it.
        h_ = std::max({glm::length(o + t0_ * d - centre), 1e-7 * (std::abs(t0_) + b - a), 1e-30});
        thetaA_ = std::atan((a - t0_) / h_);
        thetaB_ = std::atan((b - t0_) / h_);
        a_ = a;
        b_ = b;
    }
    double sample(double u) const { return std::clamp(t0_ + h_ * std::tan(thetaA_ + u * (thetaB_ - thetaA_)), a_, b_); }
    double pdf(double t) const {
        if (t < a_ || t > b_ || !(thetaB_ > thetaA_)) return 0;
        const double x = t - t0_;
        return h_ / ((thetaB_ - thetaA_) * (h_ * h_ + x * x));
    }

private:
    double t0_, h_ = 0, thetaA_ = 0, thetaB_ = 0, a_ = 0, b_ = 0;
};

}  // namespace tetglow
