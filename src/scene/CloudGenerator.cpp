#include "scene/CloudGenerator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "tet/Shapes.h"

namespace tetglow {
namespace {

// Why no seed or resolution can self-intersect: each vertex of the icosphere stays on its ray
// from the origin, at the radius r > 0 of that direction. A triangle with positive orientation
// seen from the origin (true of the icosphere's, and kept because positive radii only scale the
// corners along their rays) lies inside the cone its corners span, and those cones tile space,
// meeting only along the rays and faces that neighbouring triangles share. Keeping r smooth and
// its slope moderate keeps the triangles well shaped, so rounding to float cannot flip one.

constexpr double kPi = std::numbers::pi;

// splitmix64 (Steele, Lea and Flood 2014): the same numbers on every platform, which the
// standard library's distributions do not promise.
class SplitMix {
public:
    explicit SplitMix(uint64_t seed) : state_(seed) {}

    double uniform(double lo, double hi) {
        uint64_t z = state_ += 0x9e3779b97f4a7c15ull;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return lo + (hi - lo) * double(z >> 11) * 0x1.0p-53;
    }

private:
    uint64_t state_;
};

// Relative height added around `axis`: a Gaussian in the angle from it, with angular standard
// deviation `width` (radians), so its slope is at most 0.61 * height / width per radian.
struct Bump {
    glm::dvec3 axis;
    double height, width;

    double at(const glm::dvec3& d) const { return height * std::exp((glm::dot(d, axis) - 1) / (width * width)); }
};

// The unit vector with this y component and azimuth (radians) around the y axis.
glm::dvec3 direction(double y, double azimuth) {
    const double across = std::sqrt(1 - y * y);
    return {across * std::cos(azimuth), y, across * std::sin(azimuth)};
}

// A crown near the top, the other large puffs spread around y (one per sector, so they cannot
// all crowd to one side), then small puffs anywhere; the flat base clips those that face down.
std::vector<Bump> puffs(const CloudParams& p) {
    // One draw per statement or braced element: the order of function arguments is unspecified.
    SplitMix rng(p.seed);
    double y = rng.uniform(0.9, 0.98);
    std::vector<Bump> out{{direction(y, rng.uniform(0, 2 * kPi)), 0.9, rng.uniform(0.4, 0.5)}};
    const double turn = rng.uniform(0, 2 * kPi);
    for (int i = 1; i < p.bumps; ++i) {
        y = rng.uniform(0.2, 0.8);
        const double azimuth = turn + 2 * kPi * (i - 1 + rng.uniform(0.2, 0.8)) / (p.bumps - 1);
        out.push_back({direction(y, azimuth), rng.uniform(0.5, 0.9), rng.uniform(0.25, 0.35)});
    }
    constexpr int kSmallPuffs = 64;
    for (int i = 0; i < kSmallPuffs; ++i) {
        y = rng.uniform(-1, 1);
        out.push_back(
            {direction(y, rng.uniform(0, 2 * kPi)), p.roughness * rng.uniform(0.5, 1.5), rng.uniform(0.12, 0.2)});
    }
    return out;
}

// The body before the base: an ellipsoid, longest along x, swollen by the puffs.
constexpr glm::dvec3 kSemiAxes{0.8, 0.4, 0.55};
// The base is the plane y = -kBase, merged with the body by a smooth minimum of the radii (the
// p-norm of their reciprocals), which rounds the edge where they meet.
constexpr double kBase = 0.3;
constexpr int kBlend = 8;

double radius(const glm::dvec3& d, const std::vector<Bump>& bumps) {
    double swell = 1;
    for (const Bump& b : bumps) swell += b.at(d);
    const double body = swell / glm::length(d / kSemiAxes);
    const double base = std::max(-d.y, 0.0) / kBase;  // reciprocal radius of the base plane
    return std::pow(std::pow(body, -kBlend) + std::pow(base, kBlend), -1.0 / kBlend);
}

// Turns the longer horizontal side to x, then scales it to 2 and the height to 1.2, rounding to
// float. A turn about y and scaling about the origin keep the surface star-shaped about it.
void fitToSize(TriangleMesh& mesh) {
    Bounds3 b = bounds(mesh);
    if (b.hi.z - b.lo.z > b.hi.x - b.lo.x) {
        for (auto& v : mesh.positions) v = {v.z, v.y, -v.x};
        b = bounds(mesh);
    }
    const double across = 2 / (b.hi.x - b.lo.x), up = 1.2 / (b.hi.y - b.lo.y);
    for (auto& v : mesh.positions) v = {roundToFloat(v.x * across), roundToFloat(v.y * up), roundToFloat(v.z * across)};
}

void check(bool ok, const std::string& what) {
    if (!ok) throw InputError("cloud: " + what);
}

}  // namespace

TriangleMesh makeCloud(const CloudParams& p) {
    check(p.subdivisions >= 1 && p.subdivisions <= 8,
          "subdivisions must be 1 to 8, got " + std::to_string(p.subdivisions));
    check(p.bumps >= 1 && p.bumps <= 16, "bumps must be 1 to 16, got " + std::to_string(p.bumps));
    check(p.roughness >= 0 && p.roughness <= 0.15, "roughness must be 0 to 0.15");

    TriangleMesh mesh = icosphere(p.subdivisions);
    const std::vector<Bump> bumps = puffs(p);
    for (auto& v : mesh.positions) v *= radius(v, bumps);
    fitToSize(mesh);
    return mesh;
}

}  // namespace tetglow
