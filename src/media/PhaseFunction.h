// Henyey-Greenstein phase function. Directions are directions of travel: cosTheta is the cosine
// between the direction before scattering and the one after, so g > 0 scatters forward. Along a
// camera path (which travels against the light) the same formula holds by reciprocity.
#pragma once
#include <algorithm>
#include <cmath>

#include "sampling/Sampling.h"

namespace tetglow {

class HenyeyGreenstein {
public:
    // Below |g| = 1e-5 the sampling formula loses precision; the phase is isotropic to 3e-5 there.
    explicit HenyeyGreenstein(double g = 0) : g_(std::abs(g) < 1e-5 ? 0 : g) {}
    double g() const { return g_; }

    double eval(double cosTheta) const {
        const double denom = 1 + g_ * g_ - 2 * g_ * cosTheta;
        return kInv4Pi * (1 - g_ * g_) / (denom * std::sqrt(denom));
    }
    // A direction of travel after scattering, for travel direction d (unit); its pdf is eval().
    glm::dvec3 sample(const glm::dvec3& d, const glm::dvec2& u) const {
        double cosTheta;
        if (g_ == 0) {
            cosTheta = 1 - 2 * u.x;
        } else {
            const double sq = (1 - g_ * g_) / (1 - g_ + 2 * g_ * u.x);
            cosTheta = (1 + g_ * g_ - sq * sq) / (2 * g_);
        }
        return Frame(d).toWorld(std::clamp(cosTheta, -1.0, 1.0), 2 * kPi * u.y);
    }

private:
    double g_;
};

}  // namespace tetglow
