// The edges of a triangle soup: which triangles use each (a rim edge has one, a manifold edge
// two), for orienting patches and finding holes; and a union-find over vertices or triangles.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace tetglow {

inline uint64_t edgeKey(uint32_t a, uint32_t b) { return (uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

using EdgeMap = std::unordered_map<uint64_t, std::vector<uint32_t>>;

inline EdgeMap edgeTriangles(const std::vector<std::array<uint32_t, 3>>& triangles) {
    EdgeMap edges;
    edges.reserve(triangles.size() * 2);
    for (uint32_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) edges[edgeKey(triangles[t][k], triangles[t][(k + 1) % 3])].push_back(t);
    return edges;
}

struct UnionFind {
    std::vector<uint32_t> root;
    explicit UnionFind(size_t n) : root(n) { std::iota(root.begin(), root.end(), 0u); }
    uint32_t find(uint32_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    }
    void unite(uint32_t a, uint32_t b) { root[find(a)] = find(b); }
};

// Whether triangle f runs from a to b along one of its edges.
inline bool traverses(const std::array<uint32_t, 3>& f, uint32_t a, uint32_t b) {
    for (int k = 0; k < 3; ++k)
        if (f[k] == a && f[(k + 1) % 3] == b) return true;
    return false;
}

}  // namespace tetglow
