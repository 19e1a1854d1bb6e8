#include "scene/LightFocus.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace tetglow {

bool LightCone::contains(const glm::dvec3& p) const {
    const glm::dvec3 v = p - apex;
    const double along = glm::dot(v, axis);
    return along >= 0 && along * along >= cosAngle * cosAngle * glm::dot(v, v);
}

std::optional<std::pair<double, double>> LightCone::clip(const Ray& ray, double a, double b) const {
    if (!(b > a)) return std::nullopt;
    // The line meets the cone's surface (both nappes: the quadratic below) and the apex's plane
    // at most at four points; between them it is either inside the forward nappe or not.
    const glm::dvec3 v0 = ray.o - apex;
    const double dw = glm::dot(ray.d, axis), vw = glm::dot(v0, axis), c2 = cosAngle * cosAngle;
    const double qa = dw * dw - c2 * glm::dot(ray.d, ray.d), qb = 2 * (vw * dw - c2 * glm::dot(v0, ray.d)),
                 qc = vw * vw - c2 * glm::dot(v0, v0);
    double cuts[5] = {a, b};
    int n = 2;
    auto cut = [&](double t) {
        if (t > a && t < b) cuts[n++] = t;
    };
    if (std::abs(qa) > 1e-12 * (std::abs(qb) + std::abs(qc))) {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc >= 0) {
            const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            cut(q / qa);
            if (q != 0) cut(qc / q);
        }
    } else if (qb != 0) {
        cut(-qc / qb);
    }
    if (dw != 0) cut(-vw / dw);
    for (int i = 1; i < n; ++i)  // insertion sort of at most five
        for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i + 1 < n; ++i)
        if (cuts[i + 1] > cuts[i] && contains(ray.at(0.5 * (cuts[i] + cuts[i + 1])))) {
            lo = std::min(lo, cuts[i]);
            hi = std::max(hi, cuts[i + 1]);
        }
    if (!(hi > lo)) return std::nullopt;
    return std::make_pair(lo, hi);
}

}  // namespace tetglow
