#include "photon/Medium.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

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

Medium::Medium(const MediumParams& params, TetMesh mesh, std::vector<double> vertexDensity) : volume_(std::move(mesh)) {
    setParams(params, std::move(vertexDensity));
}

void Medium::setParams(const MediumParams& params, std::vector<double> vertexDensity) {
    const TetMesh& m = volume_.mesh();
    if (!vertexDensity.empty() && vertexDensity.size() != m.vertices.size())
        throw std::invalid_argument("Medium: one density per tet vertex expected");
    params_ = params;
    sigmaT_ = params.sigmaA + params.sigmaS;
    phase_ = HenyeyGreenstein(params.g);
    densityPlane_.assign(vertexDensity.empty() ? 0 : m.tets.size(), glm::dvec4(0));
    for (uint32_t t = 0; t < densityPlane_.size(); ++t) densityPlane_[t] = affineThrough(m, t, vertexDensity);
}

double Medium::density(uint32_t tet, const glm::dvec3& p) const {
    if (homogeneous()) return 1;
    const glm::dvec4& a = densityPlane_[tet];
    return std::max(0.0, a.w + glm::dot(glm::dvec3(a), p));
}

double Medium::densityIntegral(uint32_t tet, const Ray& ray, double tIn, double tOut) const {
    if (homogeneous()) return tOut - tIn;
    // Linear along the segment: the midpoint rule is exact.
    return (tOut - tIn) * density(tet, ray.at(0.5 * (tIn + tOut)));
}

TetWalk Medium::beginWalk(const Ray& ray, WalkStart start) const {
    return start.throughSurface ? TetWalk::enter(mesh(), ray, start.index) : TetWalk::start(mesh(), ray, start.index, 0);
}

FreeFlight Medium::sampleFlight(const Ray& ray, WalkStart start, double tMax, int hero, double u) const {
    // The distance solves integral(density) = target, target = -ln(1 - u) / sigmaT[hero].
    const double target = sigmaT_[hero] > 0 ? -std::log1p(-u) / sigmaT_[hero] : INFINITY;
    double column = 0;  // density integrated so far
    FreeFlight flight;
    TetWalk walk = beginWalk(ray, start);
    for (WalkSegment s; walk.next(s);) {
        const double tIn = std::max(s.tIn, 0.0), tOut = std::min(s.tOut, tMax);
        if (tOut <= tIn) {
            if (s.tIn >= tMax) break;
            continue;
        }
        const double piece = densityIntegral(s.tet, ray, tIn, tOut);
        if (column + piece >= target) {
            const double need = target - column;
            double x;  // distance into the segment where the column reaches the target
            if (homogeneous()) {
                x = need;
            } else {
                // density(tIn + x) = r0 + k x: r0 x + k x^2 / 2 = need, in the cancellation-free form.
                const double r0 = density(s.tet, ray.at(tIn));
                const double k = (density(s.tet, ray.at(tOut)) - r0) / (tOut - tIn);
                x = 2 * need / (r0 + std::sqrt(std::max(0.0, r0 * r0 + 2 * k * need)));
            }
            flight.scattered = true;
            flight.t = std::min(tIn + x, tOut);
            flight.tet = s.tet;
            flight.density = density(s.tet, ray.at(flight.t));
            flight.transmittance = exp(-sigmaT_ * target);
            flight.column = target;
            return flight;
        }
        column += piece;
        if (s.tOut >= tMax) break;
    }
    flight.transmittance = exp(-sigmaT_ * column);
    flight.column = column;
    if (walk.exited() && walk.exitT() < tMax) flight.left = true, flight.exitTriangle = walk.exitTriangle(), flight.exitT = walk.exitT();
    return flight;
}

RGB Medium::transmittance(const Ray& ray, WalkStart start, double tMax) const {
    return sampleFlight(ray, start, tMax, 0, 1.0).transmittance;  // u = 1: an infinite target, no interaction
}

}  // namespace tetglow
