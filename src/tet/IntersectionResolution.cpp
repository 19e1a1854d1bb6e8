#include "tet/IntersectionResolution.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "tet/CoplanarOverlap.h"
#include "tet/MeshMessage.h"
#include "tet/MeshValidation.h"
#include "tet/SelfIntersection.h"
#include "tet/TetGenProcess.h"

namespace tetglow {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

constexpr int kMaxRounds = 4;
// Splitting coplanar overlaps can leave a vertex on the edge of a coplanar neighbour, which the
// next round splits in turn.
constexpr int kMaxCoplanarRounds = 4;

// Splitting costs CGAL about a millisecond of exact arithmetic per point where three triangles
// cross (each becomes a vertex of the pieces): 40 thin boxes crossing in general position
// (17,924 such points) take 30 s, a fan of 53 thin tetrahedra (53,420) took 400 s and 280,000
// pieces. Beyond this many the triangles are left unsplit, as when CGAL fails.
constexpr size_t kMaxTriplePoints = 25000;

// The points where three mutually crossing triangles' planes meet inside all three, counted in
// doubles: an estimate of the vertices that splitting creates inside the triangles.
size_t triplePoints(const TriangleMesh& soup, const std::vector<std::pair<uint32_t, uint32_t>>& crossings) {
    std::vector<std::vector<uint32_t>> partners(soup.triangles.size());
    for (const auto& [i, j] : crossings) {
        partners[i].push_back(j);
        partners[j].push_back(i);
    }
    for (auto& p : partners) std::sort(p.begin(), p.end());
    const auto normal = [&](uint32_t t) {
        return glm::cross(soup.corner(t, 1) - soup.corner(t, 0), soup.corner(t, 2) - soup.corner(t, 0));
    };
    const auto holds = [&](uint32_t t, const glm::dvec3& p) {
        const glm::dvec3 n = normal(t);
        for (int k = 0; k < 3; ++k)
            if (glm::dot(glm::cross(soup.corner(t, (k + 1) % 3) - soup.corner(t, k), p - soup.corner(t, k)), n) < 0)
                return false;
        return true;
    };
    size_t count = 0;
    std::vector<uint32_t> common;
    for (const auto& [i, j] : crossings) {
        common.clear();
        std::set_intersection(partners[i].begin(), partners[i].end(), partners[j].begin(), partners[j].end(),
                              std::back_inserter(common));
        for (uint32_t k : common) {
            if (k < j) continue;  // each triple i < j < k once
            const glm::dmat3 planes = glm::transpose(glm::dmat3(normal(i), normal(j), normal(k)));
            if (glm::determinant(planes) == 0) {
                ++count;  // through one line: CGAL's hardest case
                continue;
            }
            const glm::dvec3 p = glm::inverse(planes) * glm::dvec3(glm::dot(normal(i), soup.corner(i, 0)),
                                                                   glm::dot(normal(j), soup.corner(j, 0)),
                                                                   glm::dot(normal(k), soup.corner(k, 0)));
            count += holds(i, p) && holds(j, p) && holds(k, p);
        }
    }
    return count;
}

// One autorefinement of the whole soup. CGAL's corefinement wants a halfedge mesh: orienting
// the soup first duplicates the vertices where it is not a manifold (an edge of three
// triangles), which welding undoes afterwards. Orientation is irrelevant here: the pieces
// only constrain the tets.
TriangleMesh autorefine(const TriangleMesh& soup) {
    std::vector<Point> points;
    points.reserve(soup.positions.size());
    for (const auto& p : soup.positions) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(soup.triangles.size());
    for (const auto& t : soup.triangles) polygons.push_back({t[0], t[1], t[2]});
    PMP::orient_polygon_soup(points, polygons);
    SurfaceMesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    PMP::experimental::autorefine(mesh);
    points.clear();
    polygons.clear();
    PMP::polygon_mesh_to_polygon_soup(mesh, points, polygons);
    TriangleMesh out;
    for (const Point& p : points)
        out.positions.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    for (const auto& f : polygons) {
        if (f.size() != 3) throw std::logic_error("autorefinement returned a face that is not a triangle");
        out.triangles.push_back({uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
    }
    return out;
}

// CGAL's autorefinement in a child process (meshingLimits): the crossings of a hostile mesh
// can be quadratic in its triangles, in time and in memory. The child has the soup from the
// fork; only the result crosses the pipe (36 bytes a vertex and a triangle).
TriangleMesh autorefineIsolated(const TriangleMesh& soup) {
    std::string answer;
    try {
        answer = runInChild(
            [&] {
                ByteWriter m;
                addMesh(m, autorefine(soup));
                return std::move(m.bytes());
            },
            meshingLimits(soup.triangles.size()));
    } catch (const ChildFailure& e) {
        if (e.kind == ChildFailure::Kind::Exception)
            throw InputError("cannot split the crossing triangles (CGAL: " + oneLine(e.detail) + ")");
        throw InputError("cannot split the crossing triangles: CGAL's autorefinement " + std::string(e.what()));
    }
    ByteReader reply(std::move(answer), "CGAL's autorefinement");
    return takeMesh(reply);
}

}  // namespace

SoupCleaning dropDegenerateAndDuplicates(TriangleMesh& soup) {
    SoupCleaning c;
    std::map<std::array<uint32_t, 3>, uint32_t> seen;
    std::vector<std::array<uint32_t, 3>> kept;
    kept.reserve(soup.triangles.size());
    for (const auto& t : soup.triangles) {
        const glm::dvec3& a = soup.positions[t[0]];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || collinear(a, soup.positions[t[1]], soup.positions[t[2]])) {
            ++c.degenerate;
            c.degenerateAt.push_back(a);
            continue;
        }
        auto key = t;
        std::sort(key.begin(), key.end());
        if (!seen.emplace(key, uint32_t(kept.size())).second) {
            ++c.duplicates;
            c.duplicateAt.push_back(a);
            continue;
        }
        kept.push_back(t);
    }
    soup.triangles = std::move(kept);
    // A vertex only a dropped triangle used could lie on another's edge: TetGen must not see it.
    weldVertices(soup);
    return c;
}

ResolvedSurface resolveIntersections(const TriangleMesh& soup, std::vector<std::pair<uint32_t, uint32_t>> crossings) {
    ResolvedSurface r;
    r.surface = soup;
    int coplanarRounds = 0;
    for (int round = 0; round < kMaxRounds && !crossings.empty(); ++round) {
        // Coplanar overlaps first, by their own exact triangulation: CGAL 5.5 gives up on them.
        while (coplanarRounds < kMaxCoplanarRounds && splitCoplanarOverlaps(r.surface, crossings)) {
            ++coplanarRounds;
            weldVertices(r.surface);
            dropDegenerateAndDuplicates(r.surface);
            crossings = findSelfIntersections(r.surface);
        }
        if (crossings.empty()) break;
        if (const size_t points = triplePoints(r.surface, crossings); points > kMaxTriplePoints) {
            r.unsplitReason = "splitting them would take minutes: their planes meet inside three of them at " +
                              std::to_string(points) + " points, more than " + std::to_string(kMaxTriplePoints);
            break;
        }
        try {
            TriangleMesh split = autorefineIsolated(r.surface);
            weldVertices(split);  // rounds the constructed points to float
            dropDegenerateAndDuplicates(split);
            r.surface = std::move(split);
        } catch (const InputError& e) {
            r.unsplitReason = e.what();
            break;
        }
        crossings = findSelfIntersections(r.surface);
    }
    if (crossings.empty()) return r;
    if (r.unsplitReason.empty())
        r.unsplitReason = std::to_string(crossings.size()) + " crossing pairs remained after splitting them " +
                          std::to_string(kMaxRounds) + " times at float precision";
    std::vector<char> crossing(r.surface.triangles.size(), 0);
    for (const auto& [i, j] : crossings) {
        crossing[i] = 1;
        crossing[j] = 1;
    }
    std::vector<std::array<uint32_t, 3>> kept;
    for (size_t t = 0; t < crossing.size(); ++t)
        if (crossing[t])
            ++r.unsplit;
        else
            kept.push_back(r.surface.triangles[t]);
    r.surface.triangles = std::move(kept);
    weldVertices(r.surface);  // their corners no kept triangle uses must not reach TetGen
    return r;
}

}  // namespace tetglow
