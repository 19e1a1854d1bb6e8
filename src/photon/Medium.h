// A participating medium confined to a tetrahedralized closed mesh. Optical depth is exact:
// density is constant or linear inside each tet, so every segment of a ray walk integrates in
// closed form, and free-flight distances are sampled by inverting that integral.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "photon/PhaseFunction.h"
#include "photon/Spectrum.h"
#include "tet/TetVolume.h"

namespace tetglow {

struct MediumParams {
    RGB sigmaA{0}, sigmaS{1};  // per unit length at density 1
    double g = 0;              // Henyey-Greenstein asymmetry
    RGB emission{0};           // radiance emitted per unit length at density 1
};

// Where a walk through the medium begins.
struct WalkStart {
    uint32_t index = 0;          // a surface triangle, or a tet
    bool throughSurface = false; // true: the ray enters through that triangle; false: starts inside that tet
    static WalkStart surface(uint32_t triangle) { return {triangle, true}; }
    static WalkStart inside(uint32_t tet) { return {tet, false}; }
};

struct FreeFlight {
    bool scattered = false;  // an interaction at t (in tet); otherwise the ray passed tMax or left the medium
    double t = 0;
    uint32_t tet = 0;
    double density = 1;      // at the interaction
    RGB transmittance{1};    // from the start to the interaction, or to where the flight ended
    double column = 0;       // density integrated over the same stretch
    // Without an interaction: the walk left the medium before tMax, through surface triangle
    // exitTriangle at exitT.
    bool left = false;
    uint32_t exitTriangle = 0;
    double exitT = 0;
};

class Medium {
public:
    // vertexDensity: one value >= 0 per tet vertex, or empty for density 1 everywhere.
    Medium(const MediumParams& params, TetMesh mesh, std::vector<double> vertexDensity = {});
    // New coefficients and density on the same tets (the preview's re-tuning: no new tets).
    void setParams(const MediumParams& params, std::vector<double> vertexDensity = {});

    const TetVolume& volume() const { return volume_; }
    const TetMesh& mesh() const { return volume_.mesh(); }
    const MediumParams& params() const { return params_; }
    RGB sigmaT() const { return sigmaT_; }
    const HenyeyGreenstein& phase() const { return phase_; }
    bool homogeneous() const { return densityPlane_.empty(); }
    bool emissive() const { return maxComponent(params_.emission) > 0; }
    double density(uint32_t tet, const glm::dvec3& p) const;
    // Density integrated along the ray (unit direction) over [tIn, tOut] inside `tet`.
    double densityIntegral(uint32_t tet, const Ray& ray, double tIn, double tOut) const;

    TetWalk beginWalk(const Ray& ray, WalkStart start) const;

    // Free flight along `ray` (unit direction) from `start` up to tMax, the distance sampled
    // exactly for the hero channel's extinction (see SpectralPath).
    FreeFlight sampleFlight(const Ray& ray, WalkStart start, double tMax, int hero, double u) const;
    // exp(-optical depth) from `start` to tMax or to where the ray leaves the medium.
    RGB transmittance(const Ray& ray, WalkStart start, double tMax) const;

private:
    MediumParams params_;
    RGB sigmaT_;
    HenyeyGreenstein phase_;
    TetVolume volume_;
    std::vector<glm::dvec4> densityPlane_;  // per tet: density(p) = w + dot(xyz, p)
};

}  // namespace tetglow
