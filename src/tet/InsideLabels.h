// Inside and outside labels of the tets of a constrained tetrahedralization, from the winding
// number at their centroids, smoothed by a minimum cut where it is uncertain (Jacobson, Kavan
// and Sorkine-Hornung 2013, section 4): over the uncertain tets the labelling minimizes
//   sum over tets of volume * (the winding number's distance past 1/2 on the wrong side)
//   + gamma * sum over faces between differently labelled tets of their area,
// so that across a hole the boundary is the least-area surface the winding number allows
// instead of following the noise of single centroids. Jacobson et al. let the cut run along
// input triangles for free; here the tets beside them keep their labels instead (below).
#pragma once
#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include <glm/vec3.hpp>

namespace tetglow {

// The face of a tet opposite its vertex j.
inline std::array<uint32_t, 3> faceOf(const std::array<uint32_t, 4>& tet, int j) {
    std::array<uint32_t, 3> f;
    for (int k = 0, m = 0; k < 4; ++k)
        if (k != j) f[m++] = tet[k];
    return f;
}

// Tets with a winding number this far from 1/2 keep the threshold's label, and so does every tet
// with an input triangle as a face: the cut moves only the others, so a clean closed part (0 or
// 1 everywhere) is labelled as by the threshold, the graph holds only the tets near holes and
// where parts cross, and no input triangle leaves the boundary or joins it (with those tets
// free, the cut shaved three triangles off the jagged rim of
// InteriorRepair.PunchedHolesLoseAtMostTheirCap to shorten the spanning surface). A tet at 3/4
// or above stays inside, so a closed part keeps its inside whatever holes the rest has.
inline constexpr double kUncertainWinding = 0.25;

// gamma in units of the mean edge length of the uncertain tets: the data term is a volume and
// the smoothness term an area, so gamma is a length, and the tets' size is the scale of the
// jaggedness to smooth. Measured on InsideLabels.NoisyWindingNumbersGiveTheCube (noise 0.1 on a
// field that crosses 1/2 over about three tets; the threshold's area 60% high): 0.01 leaves the
// cube's area 0.3% low, 0.02 0.9% low (it starts to round the cube's edges), 0.05 6% low with
// the volume 3% low; with noise 0.2, 0.01 still leaves 31% extra area, 0.02 0.3% less. On the
// barrel of InteriorRepair.MinimumCutSeparatesTheSpanningSurfaces every value from 0.01 to 0.3
// gives the same two spanning surfaces; on the other repairs 0.02 moves at most 7 of 2600
// uncertain tets.
inline constexpr double kCutGammaPerEdge = 0.02;

// One label per tet (1: inside). `neighbours[i][j]` is the tet across the face opposite vertex
// j (-1: the outside of the box TetGen filled); `constraints` holds the input's triangles as
// sorted vertex triples; `gammaPerEdge` is gamma in units of the mean edge length of the
// uncertain tets (0: the threshold w > 1/2 alone). The same labels on every run.
std::vector<char> insideLabels(const std::vector<glm::dvec3>& points, const std::vector<std::array<uint32_t, 4>>& tets,
                               const std::vector<std::array<int, 4>>& neighbours, const std::vector<double>& winding,
                               const std::set<std::array<uint32_t, 3>>& constraints, double gammaPerEdge);

}  // namespace tetglow
