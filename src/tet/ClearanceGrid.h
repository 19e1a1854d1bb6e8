// How far a point lies from the medium's boundary, bounded from below in a few operations: the
// distances at the corners of a coarse grid over the medium's box. A ball of that radius around
// the point holds no boundary triangle, so it lies inside one region.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "tet/TetMesh.h"

namespace tetglow {

class ClearanceGrid {
public:
    ClearanceGrid() = default;
    // Cells of equal size, `cells` along the box's longest side.
    explicit ClearanceGrid(const TetMesh& mesh, int cells = 32);

    bool empty() const { return distance_.empty(); }
    // At most p's distance to the nearest surface triangle (interfaces included); 0 where empty.
    // The distance is 1-Lipschitz, so a corner c bounds it by d(c) - |p - c|.
    double lowerBound(const glm::dvec3& p) const;
    // The largest bound lowerBound gives anywhere.
    double largest() const { return largest_; }

private:
    size_t index(int i, int j, int k) const { return (size_t(k) * size_t(ny_) + size_t(j)) * size_t(nx_) + size_t(i); }
    glm::dvec3 corner(int i, int j, int k) const { return origin_ + cell_ * glm::dvec3(i, j, k); }

    glm::dvec3 origin_{0};
    double cell_ = 1;
    int nx_ = 0, ny_ = 0, nz_ = 0;  // corners per axis
    std::vector<double> distance_;  // per corner, x fastest, less a margin above its rounding
    double largest_ = 0;
};

}  // namespace tetglow
