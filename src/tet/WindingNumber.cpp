#include "tet/WindingNumber.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

#include <glm/geometric.hpp>

namespace tetglow {
namespace {

constexpr uint32_t kLeafSize = 8;
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
    nodes_.reserve(2 * order_.size() / kLeafSize + 2);
    nodes_.emplace_back();
    if (!order_.empty()) build(0, 0, uint32_t(order_.size()));
}

// Fills nodes_[index] for order_[begin, end); splits at the median of the longest axis of the centroids.
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
    if (end - begin <= kLeafSize) {
        nodes_[index] = node;
        return;
    }
    const glm::dvec3 extent = box.hi - box.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto key = [&](uint32_t t) {
        return soup_.corner(t, 0)[axis] + soup_.corner(t, 1)[axis] + soup_.corner(t, 2)[axis];
    };
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](uint32_t a, uint32_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
    node.left = uint32_t(nodes_.size());
    nodes_.resize(nodes_.size() + 2);
    nodes_[index] = node;
    build(node.left, begin, mid);
    build(node.left + 1, mid, end);
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
