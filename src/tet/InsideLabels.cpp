#include "tet/InsideLabels.h"

#include <algorithm>
#include <cmath>

// GCC 12 takes the boost::optional in Boost's edge iterator for uninitialized (a false positive).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <glm/geometric.hpp>

#include "tet/Predicates.h"

namespace tetglow {
namespace {

using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
struct Node {
    boost::default_color_type colour = boost::white_color;
    long distance = 0;
    Traits::edge_descriptor predecessor;
};
struct Arc {
    double capacity = 0, residual = 0;
    Traits::edge_descriptor reverse;
};
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, Node, Arc>;

// u -> v with `forward`, v -> u with `backward`, each the other's reverse.
void addArcs(Graph& g, size_t u, size_t v, double forward, double backward) {
    const auto a = boost::add_edge(u, v, g).first, b = boost::add_edge(v, u, g).first;
    g[a].capacity = forward;
    g[b].capacity = backward;
    g[a].reverse = b;
    g[b].reverse = a;
}

}  // namespace

std::vector<char> insideLabels(const std::vector<glm::dvec3>& points, const std::vector<std::array<uint32_t, 4>>& tets,
                               const std::vector<std::array<int, 4>>& neighbours, const std::vector<double>& winding,
                               const std::set<std::array<uint32_t, 3>>& constraints, double gammaPerEdge) {
    const size_t n = tets.size();
    std::vector<char> inside(n);
    std::vector<long> node(n, -1);  // the graph vertex of each uncertain tet
    size_t uncertain = 0;
    double edgeSum = 0;
    const auto constrained = [&](size_t i, int j) {
        auto f = faceOf(tets[i], j);
        std::sort(f.begin(), f.end());
        return constraints.count(f) > 0;
    };
    for (size_t i = 0; i < n; ++i) {
        inside[i] = winding[i] > 0.5;
        if (std::abs(winding[i] - 0.5) >= kUncertainWinding) continue;
        if (constrained(i, 0) || constrained(i, 1) || constrained(i, 2) || constrained(i, 3)) continue;
        node[i] = long(uncertain++);
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) edgeSum += glm::length(points[tets[i][a]] - points[tets[i][b]]);
    }
    if (uncertain == 0 || gammaPerEdge <= 0) return inside;
    const double gamma = gammaPerEdge * edgeSum / double(6 * uncertain);

    // Source: inside, sink: outside. A tet's arc from the source is what labelling it outside
    // costs, its arc to the sink what labelling it inside costs; a face shared with a tet whose
    // label is fixed adds its area to the arc that separates the two.
    Graph g(uncertain + 2);
    const size_t source = uncertain, sink = uncertain + 1;
    std::vector<double> outsideCost(uncertain), insideCost(uncertain);
    for (size_t i = 0; i < n; ++i) {
        if (node[i] < 0) continue;
        const size_t u = size_t(node[i]);
        const auto& v = tets[i];
        const double volume = std::abs(orient3d(points[v[0]], points[v[1]], points[v[2]], points[v[3]])) / 6;
        outsideCost[u] += volume * std::max(0.0, winding[i] - 0.5);
        insideCost[u] += volume * std::max(0.0, 0.5 - winding[i]);
        for (int j = 0; j < 4; ++j) {
            const int other = neighbours[i][j];
            if (other >= 0 && node[size_t(other)] >= 0 && size_t(other) < i) continue;  // added from the other side
            const auto f = faceOf(v, j);
            const double cut =
                gamma * 0.5 * glm::length(glm::cross(points[f[1]] - points[f[0]], points[f[2]] - points[f[0]]));
            if (other < 0)
                insideCost[u] += cut;  // the box's outside
            else if (node[size_t(other)] < 0)
                (inside[size_t(other)] ? outsideCost : insideCost)[u] += cut;
            else
                addArcs(g, u, size_t(node[size_t(other)]), cut, cut);
        }
    }
    for (size_t u = 0; u < uncertain; ++u) {
        addArcs(g, source, u, outsideCost[u], 0);
        addArcs(g, u, sink, insideCost[u], 0);
    }
    boost::boykov_kolmogorov_max_flow(g, boost::get(&Arc::capacity, g), boost::get(&Arc::residual, g),
                                      boost::get(&Arc::reverse, g), boost::get(&Node::predecessor, g),
                                      boost::get(&Node::colour, g), boost::get(&Node::distance, g),
                                      boost::get(boost::vertex_index, g), source, sink);
    // The source's side of the minimum cut: the vertices its search tree holds at the end.
    for (size_t i = 0; i < n; ++i)
        if (node[i] >= 0) inside[i] = g[size_t(node[i])].colour == boost::black_color;
    return inside;
}

}  // namespace tetglow
