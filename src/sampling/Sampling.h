// Direction and point sampling shared by the light transport code.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tetglow {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInv4Pi = 1 / (4 * std::numbers::pi);

// An orthonormal basis around unit n (Duff et al. 2017, branchless).
struct Frame {
    glm::dvec3 s, t, n;
    explicit Frame(const glm::dvec3& normal) : n(normal) {
        const double sign = std::copysign(1.0, n.z), a = -1 / (sign + n.z), b = n.x * n.y * a;
        s = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
        t = {b, sign + n.y * n.y * a, -n.y};
    }
    glm::dvec3 toWorld(const glm::dvec3& v) const { return v.x * s + v.y * t + v.z * n; }
    glm::dvec3 toWorld(double cosTheta, double phi) const {
        const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
        return toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
    }
};

inline glm::dvec3 sampleUniformSphere(const glm::dvec2& u) {
    const double z = 1 - 2 * u.x, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Cosine-weighted about n; pdf = cos / pi.
inline glm::dvec3 sampleCosineHemisphere(const glm::dvec3& n, const glm::dvec2& u) {
    return Frame(n).toWorld(std::sqrt(1 - u.x), 2 * kPi * u.y);
}

// A point uniform on the unit disk (concentric mapping, Shirley and Chiu 1997).
inline glm::dvec2 sampleUniformDisk(const glm::dvec2& u) {
    const double a = 2 * u.x - 1, b = 2 * u.y - 1;
    if (a == 0 && b == 0) return {0, 0};
    const double r = std::abs(a) > std::abs(b) ? a : b;
    const double phi = std::abs(a) > std::abs(b) ? kPi / 4 * (b / a) : kPi / 2 - kPi / 4 * (a / b);
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Barycentric weights (b0, b1) of a point uniform on a triangle.
inline glm::dvec2 sampleUniformTriangle(const glm::dvec2& u) {
    const double su = std::sqrt(u.x);
    return {1 - su, u.y * su};
}

// Weights (s, t, u) of edges v1 - v0, v2 - v0, v3 - v0 for a point uniform in a tetrahedron
// (Rocchini and Cignoni 2000: fold the unit cube onto the tet).
inline glm::dvec3 sampleUniformTetrahedron(glm::dvec3 u) {
    if (u.x + u.y > 1) {
        u.x = 1 - u.x;
        u.y = 1 - u.y;
    }
    if (u.y + u.z > 1) {
        const double z = u.z;
        u.z = 1 - u.x - u.y;
        u.y = 1 - z;
    } else if (u.x + u.y + u.z > 1) {
        const double z = u.z;
        u.z = u.x + u.y + u.z - 1;
        u.x = 1 - u.y - z;
    }
    return u;
}

// Veach's power heuristic (beta = 2) for one sample of each strategy.
// The index i with cdf[i - 1] <= u * cdf.back() < cdf[i], for a running sum `cdf` of weights:
// each index with probability weight / total.
inline size_t sampleCdf(const std::vector<double>& cdf, double u) {
    const auto i = size_t(std::upper_bound(cdf.begin(), cdf.end(), u * cdf.back()) - cdf.begin());
    return std::min(i, cdf.size() - 1);
}

inline double powerHeuristic(double pdfA, double pdfB) {
    const double a = pdfA * pdfA, b = pdfB * pdfB;
    return a + b > 0 ? a / (a + b) : 0;
}

}  // namespace tetglow
