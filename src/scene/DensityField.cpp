#include "scene/DensityField.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace tetglow {

namespace {

// Value noise in [-1, 1]: hashed values on the integer lattice, smoothly interpolated.
double latticeValue(int x, int y, int z, uint32_t seed) {
    uint64_t h = uint64_t(uint32_t(x)) * 0x9e3779b97f4a7c15ull ^ uint64_t(uint32_t(y)) * 0xc2b2ae3d27d4eb4full ^
                 uint64_t(uint32_t(z)) * 0x165667b19e3779f9ull ^ uint64_t(seed) * 0x27d4eb2f165667c5ull;
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 29;
    return double(h >> 11) * 0x1.0p-52 - 1;
}

double valueNoise(const glm::dvec3& p, uint32_t seed) {
    const glm::dvec3 f = glm::floor(p), w = p - f;
    const glm::dvec3 s = w * w * (3.0 - 2.0 * w);
    const int x = int(f.x), y = int(f.y), z = int(f.z);
    double result = 0;
    for (int c = 0; c < 8; ++c) {
        const int dx = c & 1, dy = (c >> 1) & 1, dz = c >> 2;
        const double weight = (dx ? s.x : 1 - s.x) * (dy ? s.y : 1 - s.y) * (dz ? s.z : 1 - s.z);
        result += weight * latticeValue(x + dx, y + dy, z + dz, seed);
    }
    return result;
}

}  // namespace

double evaluateDensity(const DensityDesc& density, const glm::dvec3& p) {
    switch (density.type) {
        case DensityDesc::Type::Constant: return density.offset;
        case DensityDesc::Type::Linear: return std::max(0.0, density.offset + glm::dot(density.gradient, p));
        case DensityDesc::Type::Noise:
            return std::max(0.0,
                            density.offset * (1 + density.amplitude * valueNoise(density.frequency * p, density.seed)));
    }
    return 0;
}

std::vector<double> evaluateDensity(const DensityDesc& density, const std::vector<glm::dvec3>& points) {
    std::vector<double> values(points.size());
    for (size_t i = 0; i < points.size(); ++i) values[i] = evaluateDensity(density, points[i]);
    return values;
}

}  // namespace tetglow
