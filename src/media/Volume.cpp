#include "media/Volume.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "media/Roulette.h"

namespace tetglow {

namespace {

// The affine function through four (vertex, value) pairs: solves for the gradient from the
// three edges at vertex 0.
glm::dvec4 affineThrough(const TetMesh& mesh, uint32_t t, const std::vector<double>& value) {
    const auto& v = mesh.tets[t];
    const glm::dvec3 p0 = mesh.vertices[v[0]];
    const glm::dmat3 edges(mesh.vertices[v[1]] - p0, mesh.vertices[v[2]] - p0, mesh.vertices[v[3]] - p0);
    const glm::dvec3 rise(value[v[1]] - value[v[0]], value[v[2]] - value[v[0]], value[v[3]] - value[v[0]]);
    // rise_k = dot(gradient, edge_k): gradient = inverse(transpose(edges)) * rise.
    const glm::dvec3 gradient = glm::inverse(glm::transpose(edges)) * rise;
    return {gradient, value[v[0]] - glm::dot(gradient, p0)};
}

}  // namespace

Volume::Volume(const MediumParams& params, TetMesh mesh, std::vector<double> vertexDensity)
    : traversal_(std::move(mesh)) {
    std::vector<MediumField> regions(std::max<size_t>(1, this->mesh().regionCount()), MediumField{params, {}});
    for (MediumField& r : regions) r.vertexDensity = vertexDensity;
    setRegions(std::move(regions));
}

Volume::Volume(TetMesh mesh, std::vector<MediumField> regions) : traversal_(std::move(mesh)) {
    setRegions(std::move(regions));
}

void Volume::setRegions(std::vector<MediumField> regions) {
    const TetMesh& m = traversal_.mesh();
    if (regions.size() != std::max<size_t>(1, m.regionCount()))
        throw std::invalid_argument("Volume: one medium per region expected");
    regions_.clear();
    tetChord_.clear();
    emissive_ = scatters_ = false;
    bool varying = false;
    for (const MediumField& r : regions) {
        if (!r.vertexDensity.empty() && r.vertexDensity.size() != m.vertices.size())
            throw std::invalid_argument("Volume: one density per tet vertex expected");
        regions_.emplace_back(r.params);
        // A regular tet's mean chord (4 V / S) is 0.55 times the cube root of its volume.
        const int32_t index = int32_t(regions_.size()) - 1;
        const double tets = m.regionCount() ? double(m.regionTets[size_t(index) + 1] - m.regionTets[size_t(index)])
                                            : double(m.tets.size());
        const double volume = m.regionCount() ? m.regionVolume(index) : m.volume();
        tetChord_.push_back(r.vertexDensity.empty() && tets > 0 ? 0.55 * std::cbrt(volume / tets) : 0.0);
        emissive_ |= maxComponent(r.params.emission) > 0;
        scatters_ |= maxComponent(r.params.sigmaS) > 0;
        varying |= !r.vertexDensity.empty();
    }
    // Clear balls pay only where a shadow ray inside one can reach the roulette's first test:
    // in a region of constant density whose mean free path is short against the box.
    const glm::dvec3 extent = traversal_.bounds().hi - traversal_.bounds().lo;
    const double deepest = 0.5 * std::min({extent.x, extent.y, extent.z});
    for (size_t r = 0; r < regions_.size() && clearance_.empty(); ++r)
        if (tetChord_[r] > 0 && minComponent(regions_[r].sigmaT) * deepest > ShadowRoulette{}.at)
            clearance_ = ClearanceGrid(m);
    densityPlane_.assign(varying ? m.tets.size() : 0, glm::dvec4(0, 0, 0, 1));
    for (uint32_t t = 0; t < densityPlane_.size(); ++t)
        if (const auto& density = regions[size_t(std::max(0, m.region(t)))].vertexDensity; !density.empty())
            densityPlane_[t] = affineThrough(m, t, density);
}

double Volume::density(uint32_t tet, const glm::dvec3& p) const {
    if (homogeneous()) return 1;
    const glm::dvec4& a = densityPlane_[tet];
    return std::max(0.0, a.w + glm::dot(glm::dvec3(a), p));
}

double Volume::densityIntegral(uint32_t tet, const Ray& ray, double tIn, double tOut) const {
    if (homogeneous()) return tOut - tIn;
    // Linear along the segment: the midpoint rule is exact.
    return (tOut - tIn) * density(tet, ray.at(0.5 * (tIn + tOut)));
}

double Volume::columnDistance(uint32_t tet, const Ray& ray, double tIn, double tOut, double column) const {
    if (homogeneous()) return std::min(column, tOut - tIn);
    // density(tIn + x) = r0 + k x: r0 x + k x^2 / 2 = column, in the cancellation-free form.
    const double r0 = density(tet, ray.at(tIn));
    const double k = (density(tet, ray.at(tOut)) - r0) / (tOut - tIn);
    return std::min(2 * column / (r0 + std::sqrt(std::max(0.0, r0 * r0 + 2 * k * column))), tOut - tIn);
}

TetWalk Volume::beginWalk(const Ray& ray, WalkStart start) const {
    if (start.throughSurface) return TetWalk::enter(mesh(), ray, start.index);
    if (!start.located) {
        // The exact tet of the origin, found from the region's tet near it. An origin that
        // rounding put outside the region (it lies inside by more than the exit query's
        // tolerance along the ray that placed it) keeps that tet.
        const int64_t tet = traversal_.locate(ray.o, start.index);
        if (tet >= 0 && mesh().region(uint32_t(tet)) == mesh().region(start.index)) start.index = uint32_t(tet);
    }
    return TetWalk::start(mesh(), ray, start.index, 0);
}

}  // namespace tetglow
