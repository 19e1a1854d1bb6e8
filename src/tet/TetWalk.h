// Walks a ray from tet to tet through face adjacency.
//
// Every vertex is projected once onto the plane perpendicular to the ray (the ray becomes the
// origin of that plane), and every decision is the side of the origin relative to a projected
// edge, computed with the edge's lower vertex id first. Two tets sharing a face therefore decide
// from bit-identical numbers, so a ray can neither slip between tets nor loop. Signs too close
// to zero are computed exactly (Shewchuk's orient2d); exact zeros (rays through vertices and
// edges) are broken by simulation of simplicity, as if the ray were moved by (eps, eps^2).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "base/Ray.h"
#include "tet/TetMesh.h"

namespace tetglow {

struct WalkSegment {
    uint32_t tet;
    double tIn, tOut;
};

// The plane across a ray, the ray through its origin: a walk projects every vertex once and
// makes all its decisions there, from these numbers.
struct RayProjection {
    struct Point {
        glm::dvec2 uv;
        double t;  // ray parameter of the point's foot
    };
    explicit RayProjection(const Ray& ray);
    Point operator()(const glm::dvec3& p) const {
        const glm::dvec3 q = p - o;
        return {{glm::dot(q, u), glm::dot(q, v)}, glm::dot(q, d) * invDD};
    }
    glm::dvec3 o, d, u, v;  // cross(u, v) = d / |d|: counter-clockwise means along the ray
    double invDD;
};

// side() where the float sign is uncertain: exact (orient2d), zeros broken by simulation of
// simplicity with the lower vertex id first.
double sideExact(uint32_t ia, const glm::dvec2& a, uint32_t ib, const glm::dvec2& b);

// The side of the origin relative to the directed line a -> b: > 0 when a, b, origin are
// counter-clockwise. Never 0 (simulation of simplicity); antisymmetric in (a, b) exactly: the
// products commute and l - r = -(r - l) in IEEE arithmetic (the build forbids FMA contraction,
// which would break this), so the fast path needs no ordering of a and b. Inline: the walk's
// hot loop is mostly this.
inline double side(uint32_t ia, const glm::dvec2& a, uint32_t ib, const glm::dvec2& b) {
    const double l = a.x * b.y, r = a.y * b.x, det = l - r;
    constexpr double kErrBound = 3.3306690738754716e-16;  // Shewchuk's ccwerrboundA
    const double bound = kErrBound * (std::abs(l) + std::abs(r));
    if (det > bound || -det > bound) return det;
    return sideExact(ia, a, ib, b);
}

// Where the ray crosses the projected triangle (a, b, c), from its vertices' ray parameters and
// the sides of its edges: those are the barycentric coordinates of the origin.
inline double crossingT(double ta, double tb, double tc, double sAB, double sBC, double sCA) {
    const double wa = std::max(sBC, 0.0), wb = std::max(sCA, 0.0), wc = std::max(sAB, 0.0), sum = wa + wb + wc;
    if (!(sum > 0)) return (ta + tb + tc) / 3.0;
    return (wa * ta + wb * tb + wc * tc) / sum;
}

// Calls visit(t) for the surface triangles sharing a corner with s, turning around each corner
// through the tets, until it returns true.
template <class Visit>
bool anySurfaceAround(const TetMesh& mesh, uint32_t s, Visit&& visit) {
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh.surface[s][k];
        uint32_t around = s, from = mesh.surface[s][(k + 1) % 3];
        for (int guard = 0; guard < 1024; ++guard) {
            around = mesh.surfaceAcross(around, v, from);
            if (around == s) break;
            if (visit(around)) return true;
            const auto& t = mesh.surface[around];  // continue across the other edge at v
            for (int i = 0; i < 3; ++i)
                if (t[i] != v && t[i] != from) {
                    from = t[i];
                    break;
                }
        }
    }
    return false;
}

class TetWalk {
public:
    // The ray enters the medium through surface triangle `s` (as found by Embree). At an edge or
    // vertex the exact tests may place the entry in a neighbouring triangle; that one is used,
    // and if they find none, the ray only touches the surface: the walk is empty, its exitT()
    // past the triangle.
    static TetWalk enter(const TetMesh& mesh, const Ray& ray, uint32_t s);
    // The ray starts at ray.at(tStart), inside tet `tet`.
    static TetWalk start(const TetMesh& mesh, const Ray& ray, uint32_t tet, double tStart);

    // Appends the walk entering through s if the exact tests have the ray enter there, and
    // otherwise those entering through the triangles sharing a corner with s (Embree's float
    // test and the exact one disagree only at an edge or a vertex of s). Until a walk takes its
    // first step, its exitT() is its entry's t.
    static void entriesNear(const TetMesh& mesh, const Ray& ray, uint32_t s, std::vector<TetWalk>& entries);

    // The next segment, in order along the ray; false once the ray has left the medium (or was
    // lost, which exact predicates should make impossible: see lost()).
    bool next(WalkSegment& segment);

    // After exited(): continues into the region on the other side of the exit triangle, from the
    // same projected face (so the decisions stay consistent), if there is one; false (and still
    // exited) where the ray leaves every region.
    bool crossInterface();

    bool exited() const { return state_ == State::Exited; }
    bool lost() const { return state_ == State::Lost; }
    uint32_t entryTriangle() const { return entryTriangle_; }  // UINT32_MAX after start()
    uint32_t exitTriangle() const { return exitTriangle_; }    // valid once exited()
    uint32_t exitTet() const { return tet_; }                  // the last tet, once exited()
    double exitT() const { return tIn_; }                      // where the last segment ended
    size_t steps() const { return steps_; }

private:
    enum class State { Walking, Exited, Lost };
    struct Vertex {
        uint32_t id;
        glm::dvec2 uv;  // projection: the ray passes through (0, 0)
        double t;       // ray parameter of the vertex's foot point
    };

    // The exit face chosen by start(), emitted by the first next().
    struct Pending {
        int opposite;
        Vertex e, x, y;
        double sEX, sXY, sYE;
    };

    TetWalk(const TetMesh& mesh, const Ray& ray);
    Vertex project(uint32_t id) const {
        const auto [uv, t] = projection_(mesh_->vertices[id]);
        return {id, uv, t};
    }
    static double orient(const Vertex& a, const Vertex& b) { return side(a.id, a.uv, b.id, b.uv); }
    int localIndex(uint32_t id) const;
    std::array<Vertex, 3> projectSurface(uint32_t s) const;  // s's face in its tet, wound inward
    // Enters through s if the exact tests put the ray inside it; *exits tells whether they put
    // it inside s the other way round, leaving the medium there.
    bool tryEnter(uint32_t s, bool* exits = nullptr);
    bool cross(int opposite, const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE,
               WalkSegment& segment);
    void setFace(uint32_t tet, int apex, Vertex a, Vertex b, Vertex c, double ab, double bc,
                 double ca);  // by value: callers pass face_ itself
    double faceT(const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE) const;

    const TetMesh* mesh_;
    RayProjection projection_;
    size_t maxSteps_;  // a walk can visit each tet once; more means it was lost
    State state_ = State::Walking;
    uint32_t tet_ = 0;
    int apex_ = 0;       // local index of the vertex opposite the entry face
    int exitFace_ = -1;  // once exited: tet_'s local face the ray left through, -1 if none
    Vertex face_[3];     // entry face of tet_ (once exited: the exit face), counter-clockwise around the origin
    double side_[3]{};   // side(face_[k], face_[k+1]) > 0
    double tIn_ = 0;
    uint32_t entryTriangle_ = UINT32_MAX, exitTriangle_ = 0;
    size_t steps_ = 0;
    std::optional<Pending> pending_;
};

}  // namespace tetglow
