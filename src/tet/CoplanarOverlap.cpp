#include "tet/CoplanarOverlap.h"

#include <map>
#include <set>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "tet/Predicates.h"
#include "tet/SoupEdges.h"

namespace tetglow {
namespace {

// Exact constructions: the crossing points of edges, and their lift onto the plane.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point2 = Kernel::Point_2;
using FT = Kernel::FT;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Default, CGAL::Exact_intersections_tag>;

int side(const TriangleMesh& soup, uint32_t i, const glm::dvec3& p) {
    const double o = orient3d(soup.corner(i, 0), soup.corner(i, 1), soup.corner(i, 2), p);
    return (o > 0) - (o < 0);
}

// What of triangle j lies in the plane of triangle i and touches it there without crossing it: all
// of j (coplanar), an edge (the third corner off the plane), a corner (the others on one side).
struct Contact {
    bool coplanar = false;
    std::vector<glm::dvec3> points;  // one or two: a corner of j or an edge
};
Contact contact(const TriangleMesh& soup, uint32_t i, uint32_t j) {
    Contact c;
    int off = 0;
    for (int k = 0; k < 3; ++k) {
        const int s = side(soup, i, soup.corner(j, k));
        if (s == 0)
            c.points.push_back(soup.corner(j, k));
        else if (off * s < 0)
            return {};  // through the plane: a crossing for CGAL
        else
            off = s;
    }
    c.coplanar = c.points.size() == 3;
    return c;
}

// The plane of one triangle of a group, as coordinates (u, v) in the projection that drops the
// axis `drop` and the exact height along it over any (u, v).
struct Plane {
    int drop = 0;
    std::array<FT, 3> normal;
    FT offset;  // normal . p for p on the plane

    explicit Plane(const std::array<glm::dvec3, 3>& t) {
        const glm::dvec3 &a = t[0], &b = t[1], &c = t[2];
        for (int axis = 0; axis < 3; ++axis) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            normal[axis] = (FT(b[u]) - a[u]) * (FT(c[v]) - a[v]) - (FT(b[v]) - a[v]) * (FT(c[u]) - a[u]);
        }
        for (int axis = 1; axis < 3; ++axis)
            if (CGAL::abs(normal[axis]) > CGAL::abs(normal[drop])) drop = axis;
        offset = normal[0] * a[0] + normal[1] * a[1] + normal[2] * a[2];
    }
    Point2 project(const glm::dvec3& p) const { return {p[(drop + 1) % 3], p[(drop + 2) % 3]}; }
    glm::dvec3 lift(const Point2& q) const {
        const int u = (drop + 1) % 3, v = (drop + 2) % 3;
        const FT height = (offset - normal[u] * q.x() - normal[v] * q.y()) / normal[drop];
        glm::dvec3 p;
        p[u] = CGAL::to_double(CGAL::exact(q.x()));
        p[v] = CGAL::to_double(CGAL::exact(q.y()));
        p[drop] = CGAL::to_double(CGAL::exact(height));
        return p;
    }
};

// The group's union, triangulated with every edge of every member and the points and edges of
// other triangles that touch them in their plane as constraints; appends its vertices to `positions` and its faces to
// `out`.
void triangulateUnion(const TriangleMesh& soup, const std::vector<uint32_t>& group,
                      const std::vector<std::vector<glm::dvec3>>& touching, std::vector<glm::dvec3>& positions,
                      std::vector<std::array<uint32_t, 3>>& out) {
    const Plane plane({soup.corner(group[0], 0), soup.corner(group[0], 1), soup.corner(group[0], 2)});
    Cdt cdt;
    std::vector<std::array<Point2, 3>> members;
    for (uint32_t t : group) {
        members.push_back(
            {plane.project(soup.corner(t, 0)), plane.project(soup.corner(t, 1)), plane.project(soup.corner(t, 2))});
        for (int k = 0; k < 3; ++k) cdt.insert_constraint(members.back()[k], members.back()[(k + 1) % 3]);
    }
    for (const auto& c : touching)
        if (c.size() == 1)
            cdt.insert(plane.project(c[0]));
        else
            cdt.insert_constraint(plane.project(c[0]), plane.project(c[1]));
    std::map<Cdt::Vertex_handle, uint32_t> index;
    const auto vertex = [&](Cdt::Vertex_handle v) {
        auto [it, added] = index.emplace(v, uint32_t(positions.size()));
        if (added) positions.push_back(plane.lift(v->point()));
        return it->second;
    };
    // Every member's edges are constraints, so the faces inside a member are those reached from
    // the one at its centroid without crossing its edges: an edge inside it with both ends on one
    // of its edges' lines lies on that edge (the member is convex). A walk per member costs its
    // own faces, not all faces times all members.
    std::map<Cdt::Face_handle, size_t> visitedBy;  // the last member whose walk reached the face
    std::set<Cdt::Face_handle> emitted;
    for (size_t k = 0; k < members.size(); ++k) {
        const auto& m = members[k];
        const auto onEdge = [&](const Point2& a, const Point2& b) {
            for (int e = 0; e < 3; ++e)
                if (CGAL::collinear(m[e], m[(e + 1) % 3], a) && CGAL::collinear(m[e], m[(e + 1) % 3], b)) return true;
            return false;
        };
        std::vector<Cdt::Face_handle> stack{cdt.locate(CGAL::centroid(m[0], m[1], m[2]))};
        visitedBy[stack[0]] = k;
        while (!stack.empty()) {
            const Cdt::Face_handle f = stack.back();
            stack.pop_back();
            if (emitted.insert(f).second)
                out.push_back({vertex(f->vertex(0)), vertex(f->vertex(1)), vertex(f->vertex(2))});
            for (int i = 0; i < 3; ++i) {
                if (onEdge(f->vertex(Cdt::cw(i))->point(), f->vertex(Cdt::ccw(i))->point())) continue;
                const Cdt::Face_handle g = f->neighbor(i);
                if (auto [it, added] = visitedBy.emplace(g, k); added || it->second != k) {
                    it->second = k;
                    stack.push_back(g);
                }
            }
        }
    }
}

}  // namespace

bool splitCoplanarOverlaps(TriangleMesh& soup, const std::vector<std::pair<uint32_t, uint32_t>>& crossings) {
    UnionFind groups(soup.triangles.size());
    std::vector<char> member(soup.triangles.size(), 0);
    std::map<uint32_t, std::vector<std::vector<glm::dvec3>>> touching;  // by triangle
    for (const auto& [i, j] : crossings)
        for (const auto& [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
            Contact c = contact(soup, a, b);
            if (c.coplanar)
                groups.unite(a, b);
            else if (!c.points.empty())
                touching[a].push_back(std::move(c.points));
            else
                continue;
            member[a] = 1;
        }
    std::map<uint32_t, std::vector<uint32_t>> byRoot;
    std::vector<std::array<uint32_t, 3>> kept;
    for (uint32_t t = 0; t < soup.triangles.size(); ++t)
        if (member[t])
            byRoot[groups.find(t)].push_back(t);
        else
            kept.push_back(soup.triangles[t]);
    if (byRoot.empty()) return false;
    for (const auto& [root, group] : byRoot) {
        std::vector<std::vector<glm::dvec3>> constraints;
        for (uint32_t t : group)
            if (auto it = touching.find(t); it != touching.end())
                constraints.insert(constraints.end(), it->second.begin(), it->second.end());
        triangulateUnion(soup, group, constraints, soup.positions, kept);
    }
    soup.triangles = std::move(kept);
    return true;
}

}  // namespace tetglow
