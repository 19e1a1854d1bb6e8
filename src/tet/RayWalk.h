// Walks a ray from tet to tet through face adjacency.
//
// Every vertex is projected once onto the plane perpendicular to the ray (the ray becomes the
// origin of that plane), and every decision is the side of the origin relative to a projected
// edge, computed with the edge's lower vertex id first. Two tets sharing a face therefore decide
// from bit-identical numbers, so a ray can neither slip between tets nor loop. Signs too close
// to zero are computed exactly (Shewchuk's orient2d); exact zeros (rays through vertices and
// edges) are broken by simulation of simplicity, as if the ray were moved by (eps, eps^2).
#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include <glm/vec2.hpp>

#include "tet/Ray.h"
#include "tet/TetMesh.h"

namespace tetglow {

struct WalkSegment {
    uint32_t tet;
    double tIn, tOut;
};

class TetWalk {
public:
    // The ray enters the medium through surface triangle `s` (as found by Embree). At an edge or
    // vertex the exact tests may place the entry in a neighbouring triangle; that one is used,
    // and if they find none, the ray only touches the surface: the walk is empty.
    static TetWalk enter(const TetMesh& mesh, const Ray& ray, uint32_t s);
    // The ray starts at ray.at(tStart), inside tet `tet`.
    static TetWalk start(const TetMesh& mesh, const Ray& ray, uint32_t tet, double tStart);

    // The ray's entry through s or a triangle sharing a corner with s, with t in [tLo, tHi].
    static std::optional<TetWalk> enterNear(const TetMesh& mesh, const Ray& ray, uint32_t s, double tLo, double tHi);
    // After an exit within 1e-6 (relative) of a surface edge or vertex, the entry that follows
    // within 1e-6 along the ray through a triangle around it, if any.
    std::optional<TetWalk> reenter() const;

    // The next segment, in order along the ray; false once the ray has left the medium (or was
    // lost, which exact predicates should make impossible: see lost()).
    bool next(WalkSegment& segment);

    bool exited() const { return state_ == State::Exited; }
    bool lost() const { return state_ == State::Lost; }
    uint32_t exitTriangle() const { return exitTriangle_; }  // valid once exited()
    uint32_t exitTet() const { return tet_; }                 // the last tet, once exited()
    // The exit was exactly through an edge or vertex of the surface: whether the ray leaves the
    // medium there depends on what lies beyond, which the exit face alone cannot tell.
    bool exitDegenerate() const { return exitDegenerate_; }
    double exitT() const { return tIn_; }                     // where the last segment ended
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
    Vertex project(uint32_t id) const;
    int localIndex(uint32_t id) const;
    std::array<Vertex, 3> projectSurface(uint32_t s) const;  // s's face in its tet, wound inward
    // Enters through s if the exact tests put the ray inside it at a t in [tLo, tHi].
    bool tryEnter(uint32_t s, double tLo, double tHi);
    // tryEnter on the triangles sharing a corner with s, accepting entries with t in [tLo, tHi].
    bool enterAround(uint32_t s, double tLo, double tHi);
    bool cross(int opposite, const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE,
               WalkSegment& segment);
    void setFace(uint32_t tet, int apex, Vertex a, Vertex b, Vertex c, double ab, double bc, double ca);  // by value: callers pass face_ itself
    double faceT(const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE) const;

    const TetMesh* mesh_;
    glm::dvec3 o_, d_, u_, v_;
    size_t maxSteps_;  // a walk can visit each tet once; more means it was lost
    double invDD_;
    State state_ = State::Walking;
    uint32_t tet_ = 0;
    int apex_ = 0;       // local index of the vertex opposite the entry face
    Vertex face_[3];     // entry face of tet_, counter-clockwise around the origin
    double side_[3]{};   // side(face_[k], face_[k+1]) > 0
    double tIn_ = 0;
    uint32_t exitTriangle_ = 0;
    size_t steps_ = 0;
    bool exitDegenerate_ = false, exitNearEdge_ = false;
    std::optional<Pending> pending_;
};

// The side of the origin relative to the directed line a -> b: > 0 when a, b, origin are
// counter-clockwise. Never 0 (simulation of simplicity); antisymmetric in (a, b) exactly.
double side(uint32_t ia, const glm::dvec2& a, uint32_t ib, const glm::dvec2& b);

}  // namespace tetglow
