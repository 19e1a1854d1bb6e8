#include "scene/MeshWeld.h"

#include <cmath>
#include <unordered_map>

namespace tetglow {
namespace {

struct PositionHash {
    size_t operator()(const glm::dvec3& p) const {
        size_t h = std::hash<double>()(p.x + 0.0);  // + 0.0: -0 hashes as 0, as it compares
        h = h * 0x9e3779b97f4a7c15ull ^ std::hash<double>()(p.y + 0.0);
        return h * 0x9e3779b97f4a7c15ull ^ std::hash<double>()(p.z + 0.0);
    }
};

}  // namespace

void weldEqualPositions(TriangleMesh& mesh) {
    std::unordered_map<glm::dvec3, uint32_t, PositionHash> index;
    std::vector<glm::dvec3> positions;
    std::vector<uint32_t> remap(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3& p = mesh.positions[i];
        // A non-finite vertex stays apart, for validation to name (and NaN, equal to nothing,
        // would pile every NaN vertex into one bucket of the map).
        if (!std::isfinite(p.x + p.y + p.z)) {
            remap[i] = uint32_t(positions.size());
            positions.push_back(p);
            continue;
        }
        const auto [it, added] = index.try_emplace(p, uint32_t(positions.size()));
        if (added) positions.push_back(p);
        remap[i] = it->second;
    }
    for (auto& t : mesh.triangles)
        for (auto& v : t) v = remap[v];
    mesh.positions = std::move(positions);
}

}  // namespace tetglow
