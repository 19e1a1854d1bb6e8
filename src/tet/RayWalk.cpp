#include "tet/RayWalk.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "tet/Predicates.h"

namespace tetglow {
namespace {

// The magnitude side() returns for a sign decided by simulation of simplicity.
constexpr double kTie = 1e-300;

}  // namespace

double side(uint32_t ia, const glm::dvec2& a, uint32_t ib, const glm::dvec2& b) {
    if (ia > ib) return -side(ib, b, ia, a);  // canonical order: the same numbers from every tet
    const double l = a.x * b.y, r = a.y * b.x, det = l - r;
    constexpr double kErrBound = 3.3306690738754716e-16;  // Shewchuk's ccwerrboundA
    const double bound = kErrBound * (std::abs(l) + std::abs(r));
    if (det > bound || -det > bound) return det;
    const double exact = orient2d(a, b, {0, 0});
    if (exact != 0) return exact;
    // Simulation of simplicity: orient2d(a, b, (eps, eps^2)) = a x b + eps (a.y - b.y) + eps^2 (b.x - a.x).
    if (a.y != b.y) return a.y > b.y ? kTie : -kTie;
    if (a.x != b.x) return b.x > a.x ? kTie : -kTie;
    return kTie;  // edge parallel to the ray: any fixed choice per edge is consistent
}

TetWalk::TetWalk(const TetMesh& mesh, const Ray& ray)
    : mesh_(&mesh), o_(ray.o), d_(ray.d), maxSteps_(mesh.tets.size() + 8) {
    invDD_ = 1.0 / glm::dot(d_, d_);
    // Duff et al. 2017 orthonormal basis with cross(u, v) = n, so counter-clockwise in the
    // projection means a face normal pointing along the ray.
    const glm::dvec3 n = glm::normalize(d_);
    const double sign = std::copysign(1.0, n.z), a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    u_ = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    v_ = {b, sign + n.y * n.y * a, -n.y};
}

TetWalk::Vertex TetWalk::project(uint32_t id) const {
    const glm::dvec3 p = mesh_->vertices[id] - o_;
    return {id, {glm::dot(p, u_), glm::dot(p, v_)}, glm::dot(p, d_) * invDD_};
}

double TetWalk::faceT(const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE) const {
    // Barycentric coordinates of the origin in the projected face are the three sides.
    const double we = std::max(sXY, 0.0), wx = std::max(sYE, 0.0), wy = std::max(sEX, 0.0), sum = we + wx + wy;
    if (!(sum > 0)) return (e.t + x.t + y.t) / 3.0;
    return (we * e.t + wx * x.t + wy * y.t) / sum;
}

void TetWalk::setFace(uint32_t tet, int apex, Vertex a, Vertex b, Vertex c, double ab, double bc, double ca) {
    tet_ = tet;
    apex_ = apex;
    face_[0] = a, face_[1] = b, face_[2] = c;
    side_[0] = ab, side_[1] = bc, side_[2] = ca;
}

std::array<TetWalk::Vertex, 3> TetWalk::projectSurface(uint32_t s) const {
    const uint32_t f = mesh_->surfaceFace[s];
    const auto& tv = mesh_->tets[f >> 2];
    const int* face = kInwardFace[f & 3];
    return {project(tv[face[0]]), project(tv[face[1]]), project(tv[face[2]])};
}

bool TetWalk::tryEnter(uint32_t s, double tLo, double tHi) {
    const auto [a, b, c] = projectSurface(s);
    const double ab = side(a.id, a.uv, b.id, b.uv), bc = side(b.id, b.uv, c.id, c.uv), ca = side(c.id, c.uv, a.id, a.uv);
    if (!(ab > 0 && bc > 0 && ca > 0)) return false;
    const double t = faceT(a, b, c, ab, bc, ca);
    if (t < tLo || t > tHi) return false;
    const uint32_t f = mesh_->surfaceFace[s];
    setFace(f >> 2, int(f & 3), a, b, c, ab, bc, ca);
    tIn_ = t;
    return true;
}

bool TetWalk::enterAround(uint32_t s, double tLo, double tHi) {
    // Every triangle sharing a corner with s, by turning around each corner through the tets.
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = mesh_->surface[s][k];
        uint32_t around = s, from = mesh_->surface[s][(k + 1) % 3];
        for (int guard = 0; guard < 1024; ++guard) {
            around = mesh_->surfaceAcross(around, v, from);
            if (around == s) break;
            if (tryEnter(around, tLo, tHi)) return true;
            const auto& t = mesh_->surface[around];  // continue across the other edge at v
            for (int i = 0; i < 3; ++i)
                if (t[i] != v && t[i] != from) {
                    from = t[i];
                    break;
                }
        }
    }
    return false;
}

TetWalk TetWalk::enter(const TetMesh& mesh, const Ray& ray, uint32_t s) {
    if (auto w = enterNear(mesh, ray, s, -INFINITY, INFINITY)) return *w;
    // The exact tests say the ray only touches the surface here: an empty walk.
    TetWalk w(mesh, ray);
    const auto [a, b, c] = w.projectSurface(s);
    w.tIn_ = w.faceT(a, b, c, 0, 0, 0);
    w.state_ = State::Exited;
    w.exitTriangle_ = s;
    return w;
}

std::optional<TetWalk> TetWalk::enterNear(const TetMesh& mesh, const Ray& ray, uint32_t s, double tLo, double tHi) {
    // Embree's float test and the exact one can disagree only at an edge or a vertex of s, so
    // the entry, if any, is through s or a triangle around its corners.
    TetWalk w(mesh, ray);
    if (w.tryEnter(s, tLo, tHi) || w.enterAround(s, tLo, tHi)) return w;
    return std::nullopt;
}

std::optional<TetWalk> TetWalk::reenter() const {
    // Embree may miss crossings within float precision of an edge or vertex; there the next
    // entry, if it follows at once, is through a triangle around the exit triangle's corners.
    if (state_ != State::Exited || !exitNearEdge_) return std::nullopt;
    return enterNear(*mesh_, Ray{o_, d_}, exitTriangle_, tIn_, tIn_ + 1e-6 * (1 + std::abs(tIn_)));
}

TetWalk TetWalk::start(const TetMesh& mesh, const Ray& ray, uint32_t tet, double tStart) {
    TetWalk w(mesh, ray);
    const auto& tv = mesh.tets[tet];
    Vertex p[4];
    for (int j = 0; j < 4; ++j) p[j] = w.project(tv[j]);
    // The exit face is the one whose outward winding is counter-clockwise around the origin;
    // if rounding puts the origin on no face, take the face it is least outside of.
    int best = 0;
    double bestMin = -INFINITY, bestSides[3] = {};
    for (int j = 0; j < 4; ++j) {
        const Vertex &a = p[kInwardFace[j][0]], &b = p[kInwardFace[j][2]], &c = p[kInwardFace[j][1]];
        const double s[3] = {side(a.id, a.uv, b.id, b.uv), side(b.id, b.uv, c.id, c.uv), side(c.id, c.uv, a.id, a.uv)};
        const double m = std::min({s[0], s[1], s[2]});
        if (m > bestMin) best = j, bestMin = m, std::copy(s, s + 3, bestSides);
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
    const double sa = side(e.id, e.uv, a.id, a.uv);
    // The origin lies in exactly one of the projected faces (e,a,b), (e,b,c), (e,c,a); two sides
    // decide which. Each face is passed counter-clockwise, as the next tet's entry face.
    if (sa > 0) {
        const double sb = side(e.id, e.uv, b.id, b.uv);
        if (sb < 0) return cross(localIndex(c.id), e, a, b, sa, side_[0], -sb, segment);
        const double sc = side(e.id, e.uv, c.id, c.uv);
        return cross(localIndex(a.id), e, b, c, sb, side_[1], -sc, segment);
    }
    const double sc = side(e.id, e.uv, c.id, c.uv);
    if (sc > 0) return cross(localIndex(b.id), e, c, a, sc, side_[2], -sa, segment);
    const double sb = side(e.id, e.uv, b.id, b.uv);
    return cross(localIndex(a.id), e, b, c, sb, side_[1], -sc, segment);
}

int TetWalk::localIndex(uint32_t id) const {
    const auto& tv = mesh_->tets[tet_];
    return tv[0] == id ? 0 : tv[1] == id ? 1 : tv[2] == id ? 2 : 3;
}

bool TetWalk::cross(int opposite, const Vertex& e, const Vertex& x, const Vertex& y, double sEX, double sXY, double sYE,
                    WalkSegment& segment) {
    const double tOut = std::max(tIn_, faceT(e, x, y, sEX, sXY, sYE));
    segment = {tet_, tIn_, tOut};
    tIn_ = tOut;
    const int32_t adj = mesh_->adjacency[tet_][opposite];
    if (TetMesh::isBoundary(adj)) {
        state_ = State::Exited;
        exitDegenerate_ = std::abs(sEX) == kTie || std::abs(sXY) == kTie || std::abs(sYE) == kTie;
        const double smallest = std::min({sEX, sXY, sYE}), sum = std::max(sEX, 0.0) + std::max(sXY, 0.0) + std::max(sYE, 0.0);
        exitNearEdge_ = !(smallest > 1e-6 * sum);
        exitTriangle_ = TetMesh::surfaceTriangle(adj);
    } else {
        setFace(TetMesh::neighbourTet(adj), TetMesh::neighbourFace(adj), e, x, y, sEX, sXY, sYE);
    }
    return true;
}

}  // namespace tetglow
