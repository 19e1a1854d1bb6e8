#include "tet/WindingNumber.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <tuple>

#include <glm/geometric.hpp>

#include "tet/SoupEdges.h"

namespace tetglow {
namespace {

constexpr uint32_t kLeafSize = 8;
// Closed shells of up to this many triangles stay whole in one cluster of the tree.
constexpr uint32_t kSmallShell = 64;
constexpr uint32_t kNoShell = UINT32_MAX;
constexpr double kFourPi = 4 * M_PI;

}  // namespace

double solidAngle(const glm::dvec3& corner0, const glm::dvec3& corner1, const glm::dvec3& corner2,
                  const glm::dvec3& p) {
    const glm::dvec3 a = corner0 - p, b = corner1 - p, c = corner2 - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    return 2 * std::atan2(glm::dot(a, glm::cross(b, c)),
                          la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb);
}

WindingNumber::WindingNumber(const TriangleMesh& soup) : soup_(soup), order_(soup.triangles.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
    findShells();
    nodes_.reserve(2 * order_.size() / kLeafSize + 2);
    nodes_.emplace_back();
    if (!order_.empty()) build(0, 0, uint32_t(order_.size()));
    sealClusters();
}

// Shells: triangles joined through shared edges. A shell is closed and consistently wound when
// each of its edges has two triangles that traverse it in opposite directions. The tree keeps a
// small one in one cluster (it sorts by the shell's centroid), so that many disjoint small
// shells make sealed clusters; a large one is split by its triangles as any surface.
void WindingNumber::findShells() {
    const size_t n = order_.size();
    const EdgeMap edges = edgeTriangles(soup_.triangles);
    UnionFind shells(n);
    for (const auto& [key, users] : edges)
        for (size_t i = 1; i < users.size(); ++i) shells.unite(users[0], users[i]);
    std::vector<char> closed(n, 1);
    for (const auto& [key, users] : edges) {
        const uint32_t a = uint32_t(key >> 32), b = uint32_t(key);
        if (users.size() != 2 ||
            traverses(soup_.triangles[users[0]], a, b) == traverses(soup_.triangles[users[1]], a, b))
            closed[shells.find(users[0])] = 0;
    }
    std::vector<uint32_t> size(n, 0);
    shell_.resize(n);
    for (uint32_t t = 0; t < n; ++t) ++size[shell_[t] = shells.find(t)];
    shellCentre_.assign(n, glm::dvec3(0));
    for (uint32_t t = 0; t < n; ++t) {
        const uint32_t s = shell_[t];
        if (closed[s] && size[s] <= kSmallShell)
            shellCentre_[s] += (soup_.corner(t, 0) + soup_.corner(t, 1) + soup_.corner(t, 2)) / double(size[s]);
        else
            shell_[t] = kNoShell;  // split freely
    }
}

// A cluster is sealed when every triangle's shell is closed and lies wholly in the cluster.
void WindingNumber::sealClusters() {
    const size_t n = order_.size();
    std::vector<uint32_t> first(n, UINT32_MAX), last(n, 0);  // by small shell: its positions in order_
    for (uint32_t i = 0; i < n; ++i)
        if (const uint32_t s = shell_[order_[i]]; s != kNoShell) {
            first[s] = std::min(first[s], i);
            last[s] = std::max(last[s], i);
        }
    for (Node& node : nodes_) {
        node.sealed = node.end > node.begin;
        for (uint32_t i = node.begin; i < node.end && node.sealed; ++i) {
            const uint32_t s = shell_[order_[i]];
            node.sealed = s != kNoShell && first[s] >= node.begin && last[s] < node.end;
        }
    }
}

// Fills nodes_[index] for order_[begin, end); splits at the median of the longest axis of the
// centroids (a small closed shell's for its triangles), not inside a small closed shell.
void WindingNumber::build(uint32_t index, uint32_t begin, uint32_t end) {
    Node node;
    node.begin = begin;
    node.end = end;
    double total = 0;
    Bounds3 box;
    for (uint32_t i = begin; i < end; ++i) {
        const uint32_t t = order_[i];
        const glm::dvec3 a = soup_.corner(t, 0), b = soup_.corner(t, 1), c = soup_.corner(t, 2);
        const glm::dvec3 n = 0.5 * glm::cross(b - a, c - a);
        const double area = glm::length(n);
        node.area += n;
        node.centre += area * (a + b + c) / 3.0;
        total += area;
        node.areaSum += area;
        box.extend((a + b + c) / 3.0);
    }
    node.centre = total > 0 ? node.centre / total : 0.5 * (box.lo + box.hi);
    for (uint32_t i = begin; i < end; ++i)
        for (int k = 0; k < 3; ++k)
            node.radius = std::max(node.radius, glm::length(soup_.corner(order_[i], k) - node.centre));
    nodes_[index] = node;
    if (end - begin <= kLeafSize) return;
    const glm::dvec3 extent = box.hi - box.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto key = [&](uint32_t t) {
        if (shell_[t] != kNoShell) return std::tuple(3 * shellCentre_[shell_[t]][axis], shell_[t], t);
        return std::tuple(soup_.corner(t, 0)[axis] + soup_.corner(t, 1)[axis] + soup_.corner(t, 2)[axis], kNoShell, t);
    };
    uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    // The rest of the shell the median cuts goes left with it (it sorts first among the right);
    // where that leaves nothing right, the shell alone goes right.
    if (const uint32_t s = shell_[order_[mid - 1]]; s != kNoShell) {
        const auto at = [&](uint32_t i) { return order_.begin() + i; };
        mid = uint32_t(std::partition(at(mid), at(end), [&](uint32_t t) { return shell_[t] == s; }) - at(0));
        if (mid == end)
            mid = uint32_t(std::partition(at(begin), at(end), [&](uint32_t t) { return shell_[t] != s; }) - at(0));
        if (mid == begin) return;  // one small shell: a leaf
    }
    nodes_[index].left = uint32_t(nodes_.size());
    nodes_.resize(nodes_.size() + 2);
    build(nodes_[index].left, begin, mid);
    build(nodes_[index].left + 1, mid, end);
}

double WindingNumber::exact(const glm::dvec3& p) const {
    double omega = 0;
    for (uint32_t t = 0; t < soup_.triangles.size(); ++t) omega += solidAngle(t, p);
    return omega / kFourPi;
}

double WindingNumber::approximate(const glm::dvec3& p) const {
    if (order_.empty()) return 0;
    double omega = 0;
    uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        const glm::dvec3 d = n.centre - p;
        const double dist = glm::length(d);
        if (n.sealed && dist > n.radius) continue;
        if (dist > kFarRatio * n.radius) {
            omega += glm::dot(n.area, d) / (dist * dist * dist);
        } else if (n.left == 0) {
            for (uint32_t i = n.begin; i < n.end; ++i) omega += solidAngle(order_[i], p);
        } else {
            stack[top++] = n.left;
            stack[top++] = n.left + 1;
        }
    }
    return omega / kFourPi;
}

// A cluster seen from p as its dipole differs from its triangles' solid angle by at most
// 2 r A / (d - r)^3 (A: its triangles' area, r: its radius, d: p's distance from its centre;
// the gradient of (x - p) / |x - p|^3 is at most 2 / |x - p|^3, and every point of the cluster
// lies within r of the centre). Clusters are opened, the largest bound first, until the bounds
// cannot move the sum across `level`; leaves and clusters that p may lie in are summed exactly.
double WindingNumber::certified(const glm::dvec3& p, double level) const {
    struct Far {
        double bound, omega;
        uint32_t node;
        bool operator<(const Far& o) const { return bound < o.bound; }
    };
    std::priority_queue<Far> far;
    double omega = 0, bound = 0;
    std::vector<uint32_t> stack{0};
    const auto open = [&] {
        while (!stack.empty()) {
            const uint32_t index = stack.back();
            stack.pop_back();
            const Node& n = nodes_[index];
            const glm::dvec3 d = n.centre - p;
            const double dist = glm::length(d);
            if (n.sealed && dist > n.radius) continue;
            if (n.left == 0) {
                for (uint32_t i = n.begin; i < n.end; ++i) omega += solidAngle(order_[i], p);
            } else if (dist > n.radius) {
                const double gap = dist - n.radius;
                const Far f{2 * n.radius * n.areaSum / (gap * gap * gap), glm::dot(n.area, d) / (dist * dist * dist),
                            index};
                omega += f.omega;
                bound += f.bound;
                far.push(f);
            } else {
                stack.push_back(n.left);
                stack.push_back(n.left + 1);
            }
        }
    };
    open();
    while (!far.empty() && !(std::abs(omega - kFourPi * level) > bound)) {
        const Far f = far.top();
        far.pop();
        omega -= f.omega;
        bound -= f.bound;
        stack = {nodes_[f.node].left, nodes_[f.node].left + 1};
        open();
    }
    return omega / kFourPi;
}

double WindingNumber::classify(const glm::dvec3& p, double band) const {
    const double w = approximate(p);
    return std::abs(w - 0.5) < band && !order_.empty() ? certified(p, 0.5) : w;
}

}  // namespace tetglow
