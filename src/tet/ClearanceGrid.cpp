#include "tet/ClearanceGrid.h"

#include <algorithm>
#include <cmath>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace tetglow {

ClearanceGrid::ClearanceGrid(const TetMesh& mesh, int cells) {
    if (mesh.surface.empty() || cells < 1) return;
    // Distances need no exact predicates: a margin covers their rounding (CGAL's AABB tree).
    using Kernel = CGAL::Simple_cartesian<double>;
    using Triangle = Kernel::Triangle_3;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
    Bounds3 box;
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.surface.size());
    for (const auto& f : mesh.surface) {
        const glm::dvec3 &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
        triangles.emplace_back(Kernel::Point_3(a.x, a.y, a.z), Kernel::Point_3(b.x, b.y, b.z),
                               Kernel::Point_3(c.x, c.y, c.z));
        box.extend(a), box.extend(b), box.extend(c);
    }
    const glm::dvec3 extent = box.hi - box.lo;
    const double longest = std::max({extent.x, extent.y, extent.z});
    if (!(longest > 0) || !std::isfinite(longest)) return;
    cell_ = longest / cells;
    origin_ = box.lo;
    // At least one cell along each axis, even for a flat box.
    auto corners = [&](double side) { return std::max(2, int(std::ceil(side / cell_)) + 1); };
    nx_ = corners(extent.x), ny_ = corners(extent.y), nz_ = corners(extent.z);
    Tree tree(triangles.begin(), triangles.end());
    auto distance = [&](const glm::dvec3& p) {
        return std::sqrt(tree.squared_distance(Kernel::Point_3(p.x, p.y, p.z)));
    };
    // The tree and its search tree for distances are otherwise built by the first query: built
    // here, one thread, so that the parallel queries below only read them.
    tree.build();
    tree.accelerate_distance_queries();
    // The distance's rounding is about 1e-16 of the coordinates' size.
    const glm::dvec3 far = glm::max(glm::abs(box.lo), glm::abs(box.hi));
    const double margin = 1e-9 * (std::max({far.x, far.y, far.z}) + longest);
    distance_.resize(size_t(nx_) * size_t(ny_) * size_t(nz_));
    tbb::parallel_for(0, nz_, [&](int k) {
        for (int j = 0; j < ny_; ++j)
            for (int i = 0; i < nx_; ++i) distance_[index(i, j, k)] = std::max(0.0, distance(corner(i, j, k)) - margin);
    });
    largest_ = *std::max_element(distance_.begin(), distance_.end());
}

double ClearanceGrid::lowerBound(const glm::dvec3& p) const {
    if (empty()) return 0;
    const glm::dvec3 g = (p - origin_) / cell_;
    // Outside the grid (or NaN) no corner is near: no bound worth the work.
    if (!(g.x >= 0 && g.y >= 0 && g.z >= 0 && g.x <= nx_ - 1 && g.y <= ny_ - 1 && g.z <= nz_ - 1)) return 0;
    // The nearest corner c, at most 0.87 cells away: one lookup and one square root, and since
    // d(c) >= d(p) - |p - c|, at most 1.74 cells short of p's distance.
    const int i = int(g.x + 0.5), j = int(g.y + 0.5), k = int(g.z + 0.5);
    return std::max(0.0, distance_[index(i, j, k)] - glm::length(p - corner(i, j, k)));
}

}  // namespace tetglow
