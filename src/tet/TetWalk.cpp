#include "tet/TetWalk.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "tet/Predicates.h"

namespace tetglow {
namespace {

// The magnitude side() returns for a sign decided by simulation of simplicity.
constexpr double kTie = 1e-300;

}  // namespace

double sideExact(uint32_t ia, const glm::dvec2& a, uint32_t ib, const glm::dvec2& b) {
    if (ia > ib) return -sideExact(ib, b, ia, a);  // canonical order: the same answer from every tet
    const double exact = orient2d(a, b, {0, 0});
    if (exact != 0) return exact;
    // Simulation of simplicity: orient2d(a, b, (eps, eps^2)) = a x b + eps (a.y - b.y) + eps^2 (b.x - a.x).
    if (a.y != b.y) return a.y > b.y ? kTie : -kTie;
    if (a.x != b.x) return b.x > a.x ? kTie : -kTie;
    return kTie;  // edge parallel to the ray: any fixed choice per edge is consistent
}

RayProjection::RayProjection(const Ray& ray) : o(ray.o), d(ray.d), invDD(1.0 / glm::dot(ray.d, ray.d)) {
    // Duff et al. 2017 orthonormal basis with cross(u, v) = d / |d|.
    const glm::dvec3 n = glm::normalize(d);
    const double sign = std::copysign(1.0, n.z), a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    u = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    v = {b, sign + n.y * n.y * a, -n.y};
}

TetWalk::TetWalk(const TetMesh& mesh, const Ray& ray)
    : mesh_(&mesh), projection_(ray), maxSteps_(mesh.tets.size() + 8) {}

inline double TetWalk::faceT(const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY,
                             double sYE) const {
    return crossingT(e.t, x.t, y.t, sEX, sXY, sYE);
}

inline void TetWalk::setFace(uint32_t tet, int apex, Vertex a, Vertex b, Vertex c, double ab, double bc, double ca) {
    tet_ = tet;
    apex_ = apex;
    face_[0] = a;
    face_[1] = b;
    face_[2] = c;
    side_[0] = ab;
    side_[1] = bc;
    side_[2] = ca;
}

std::array<TetWalk::Vertex, 3> TetWalk::projectSurface(uint32_t s) const {
    const uint32_t f = mesh_->surfaceFace[s];
    const auto& tv = mesh_->tets[f >> 2];
    const int* face = kInwardFace[f & 3];
    return {project(tv[face[0]]), project(tv[face[1]]), project(tv[face[2]])};
}

bool TetWalk::tryEnter(uint32_t s, bool* exits) {
    if (exits) *exits = false;
    if (mesh_->surfaceFaceFront[s] != UINT32_MAX) return false;  // an interface: reached from inside only
    const auto [a, b, c] = projectSurface(s);
    const double ab = orient(a, b), bc = orient(b, c), ca = orient(c, a);
    if (exits) *exits = ab < 0 && bc < 0 && ca < 0;
    if (!(ab > 0 && bc > 0 && ca > 0)) return false;
    const uint32_t f = mesh_->surfaceFace[s];
    setFace(f >> 2, int(f & 3), a, b, c, ab, bc, ca);
    tIn_ = faceT(a, b, c, ab, bc, ca);
    entryTriangle_ = s;
    return true;
}

TetWalk TetWalk::enter(const TetMesh& mesh, const Ray& ray, uint32_t s) {
    TetWalk w(mesh, ray);
    if (w.tryEnter(s) || anySurfaceAround(mesh, s, [&](uint32_t t) { return w.tryEnter(t); })) return w;
    // The exact tests say the ray only touches the surface here: an empty walk, which ends
    // past the triangle's corners, where the ray surely goes on outside.
    const auto [a, b, c] = w.projectSurface(s);
    w.tIn_ = std::max({a.t, b.t, c.t});
    w.state_ = State::Exited;
    w.exitTriangle_ = s;
    return w;
}

void TetWalk::entriesNear(const TetMesh& mesh, const Ray& ray, uint32_t s, std::vector<TetWalk>& entries) {
    TetWalk w(mesh, ray);
    bool exits = false;
    if (w.tryEnter(s, &exits)) return entries.push_back(w);
    if (exits) return;  // through s's interior the other way: no entry can be near
    anySurfaceAround(mesh, s, [&](uint32_t t) {
        if (w.tryEnter(t)) entries.push_back(w);
        return false;
    });
}

TetWalk TetWalk::start(const TetMesh& mesh, const Ray& ray, uint32_t tet, double tStart) {
    TetWalk w(mesh, ray);
    const auto& tv = mesh.tets[tet];
    Vertex p[4];
    for (int j = 0; j < 4; ++j) p[j] = w.project(tv[j]);
    // The four faces share six edges, and side() is exactly antisymmetric: each edge is decided
    // once, edge[i][k] = orient(p[i], p[k]) for i < k, and read with its sign flipped the other way.
    double edge[4][4];
    for (int i = 0; i < 4; ++i)
        for (int k = i + 1; k < 4; ++k) {
            edge[i][k] = orient(p[i], p[k]);
            edge[k][i] = -edge[i][k];
        }
    // The exit face is the one whose outward winding is counter-clockwise around the origin;
    // if rounding puts the origin on no face, take the face it is least outside of.
    int best = 0;
    double bestMin = -INFINITY, bestSides[3] = {};
    for (int j = 0; j < 4; ++j) {
        const int ia = kInwardFace[j][0], ib = kInwardFace[j][2], ic = kInwardFace[j][1];
        const double s[3] = {edge[ia][ib], edge[ib][ic], edge[ic][ia]};
        const double m = std::min({s[0], s[1], s[2]});
        if (m > bestMin) {
            best = j;
            bestMin = m;
            std::copy(s, s + 3, bestSides);
        }
        if (m > 0) break;
    }
    // Pose the exit face as the entry face of the tet across it, then emit the first segment.
    const Vertex &a = p[kInwardFace[best][0]], &b = p[kInwardFace[best][2]], &c = p[kInwardFace[best][1]];
    w.tet_ = tet;
    w.tIn_ = tStart;
    w.pending_ = Pending{best, a, b, c, bestSides[0], bestSides[1], bestSides[2]};
    return w;
}

bool TetWalk::next(WalkSegment& segment) {
    if (state_ != State::Walking) return false;
    if (++steps_ > maxSteps_) {
        state_ = State::Lost;
        return false;
    }
    if (pending_) {
        const Pending f = *pending_;
        pending_.reset();
        return cross(f.opposite, f.e, f.x, f.y, f.sEX, f.sXY, f.sYE, segment);
    }
    const Vertex e = project(mesh_->tets[tet_][apex_]);  // the vertex not on the entry face
    const Vertex &a = face_[0], &b = face_[1], &c = face_[2];
    const double sa = orient(e, a);
    // The origin lies in exactly one of the projected faces (e,a,b), (e,b,c), (e,c,a); two sides
    // decide which. Each face is passed counter-clockwise, as the next tet's entry face.
    if (sa > 0) {
        const double sb = orient(e, b);
        if (sb < 0) return cross(localIndex(c.id), e, a, b, sa, side_[0], -sb, segment);
        const double sc = orient(e, c);
        return cross(localIndex(a.id), e, b, c, sb, side_[1], -sc, segment);
    }
    const double sc = orient(e, c);
    if (sc > 0) return cross(localIndex(b.id), e, c, a, sc, side_[2], -sa, segment);
    const double sb = orient(e, b);
    return cross(localIndex(a.id), e, b, c, sb, side_[1], -sc, segment);
}

inline int TetWalk::localIndex(uint32_t id) const {
    const auto& tv = mesh_->tets[tet_];
    return int(tv[1] == id) + 2 * int(tv[2] == id) + 3 * int(tv[3] == id);  // no branches
}

inline bool TetWalk::cross(int opposite, const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY,
                           double sYE, WalkSegment& segment) {
    const double tOut = std::max(tIn_, faceT(e, x, y, sEX, sXY, sYE));
    segment = {tet_, tIn_, tOut};
    tIn_ = tOut;
    const int32_t adj = mesh_->adjacency[tet_][opposite];
    if (TetMesh::isBoundary(adj)) {
        state_ = State::Exited;
        exitTriangle_ = TetMesh::surfaceTriangle(adj);
        exitFace_ = opposite;
        setFace(tet_, apex_, e, x, y, sEX, sXY, sYE);  // kept for crossInterface()
    } else {
        setFace(TetMesh::neighbourTet(adj), TetMesh::neighbourFace(adj), e, x, y, sEX, sXY, sYE);
    }
    return true;
}

bool TetWalk::crossInterface() {
    if (state_ != State::Exited || exitFace_ < 0) return false;
    const uint32_t f = mesh_->across(exitTriangle_, 4 * tet_ + uint32_t(exitFace_));
    if (f == UINT32_MAX) return false;
    setFace(f >> 2, int(f & 3), face_[0], face_[1], face_[2], side_[0], side_[1], side_[2]);
    exitFace_ = -1;
    state_ = State::Walking;
    return true;
}

}  // namespace tetglow
