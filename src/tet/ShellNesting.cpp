#include "tet/ShellNesting.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tet/WindingNumber.h"

namespace tetglow {
namespace {

// Generalized winding number of the given triangles around p: +-1 inside a closed shell, 0
// outside, robust for p off the surface.
double windingNumber(const TriangleMesh& mesh, const std::vector<uint32_t>& tris, const glm::dvec3& p) {
    double omega = 0;
    for (uint32_t t : tris) omega += solidAngle(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2), p);
    return omega / (4 * M_PI);
}

// A uniform grid over the shells' bounds; each cell lists the shells whose bounds overlap it.
class BoundsGrid {
public:
    explicit BoundsGrid(const std::vector<Bounds3>& boxes) {
        for (const Bounds3& b : boxes) all_.extend(b);
        n_ = std::clamp(int(std::cbrt(double(boxes.size()))), 1, 64);
        cells_.resize(size_t(n_) * n_ * n_);
        for (uint32_t s = 0; s < boxes.size(); ++s) {
            const auto lo = cell(boxes[s].lo), hi = cell(boxes[s].hi);
            for (int z = lo[2]; z <= hi[2]; ++z)
                for (int y = lo[1]; y <= hi[1]; ++y)
                    for (int x = lo[0]; x <= hi[0]; ++x) cells_[index(x, y, z)].push_back(s);
        }
    }
    // The shells whose bounds may hold p.
    const std::vector<uint32_t>& candidates(const glm::dvec3& p) const {
        const auto c = cell(p);
        return cells_[index(c[0], c[1], c[2])];
    }

private:
    std::array<int, 3> cell(const glm::dvec3& p) const {
        std::array<int, 3> c;
        for (int i = 0; i < 3; ++i) {
            const double extent = all_.hi[i] - all_.lo[i];
            const double u = extent > 0 ? (p[i] - all_.lo[i]) / extent : 0;
            c[i] = std::clamp(int(u * n_), 0, n_ - 1);
        }
        return c;
    }
    size_t index(int x, int y, int z) const { return (size_t(z) * n_ + y) * n_ + x; }

    Bounds3 all_;
    int n_ = 1;
    std::vector<std::vector<uint32_t>> cells_;
};

}  // namespace

std::vector<std::vector<uint32_t>> containingShells(const TriangleMesh& mesh,
                                                    const std::vector<std::vector<uint32_t>>& shells) {
    std::vector<std::vector<uint32_t>> containers(shells.size());
    if (shells.size() < 2) return containers;
    std::vector<Bounds3> boxes(shells.size());
    for (size_t s = 0; s < shells.size(); ++s)
        for (uint32_t t : shells[s])
            for (int k = 0; k < 3; ++k) boxes[s].extend(mesh.corner(t, k));
    const BoundsGrid grid(boxes);
    for (uint32_t s = 0; s < shells.size(); ++s) {
        // Shells meet at most at shared corners and edges, so a centroid is off the others.
        const uint32_t t = shells[s][0];
        const glm::dvec3 probe = (mesh.corner(t, 0) + mesh.corner(t, 1) + mesh.corner(t, 2)) / 3.0;
        for (uint32_t o : grid.candidates(probe))
            if (o != s && boxes[o].contains(probe) && std::abs(windingNumber(mesh, shells[o], probe)) > 0.5)
                containers[s].push_back(o);
    }
    return containers;
}

}  // namespace tetglow
