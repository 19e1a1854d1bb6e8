#include "scene/VolumePartition.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "scene/MediaNesting.h"

namespace tetglow {

std::vector<std::vector<int>> findVolumes(const std::vector<MediumDesc>& media, const MediaNesting* found) {
    const int n = int(media.size());
    std::vector<int> root(n);
    std::iota(root.begin(), root.end(), 0);
    const auto find = [&](int i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    std::vector<int32_t> parent(n, -1);
    if (n > 1 || (n == 1 && media[0].cavity)) {
        if (found && found->parent.size() != media.size())
            throw std::logic_error("findVolumes: a nesting of other media");
        const MediaNesting nesting = found ? *found : nestMedia(media);
        parent = nesting.parent;
        for (int i = 0; i < n; ++i)
            if (parent[i] >= 0) root[find(i)] = find(parent[i]);
        for (const auto& [a, b] : nesting.touching) root[find(a)] = find(b);
    }
    for (int i = 0; i < n; ++i)
        if (media[i].cavity && parent[i] < 0) throw InputError(media[i].name + ": a cavity must lie inside a medium");
    std::vector<std::vector<int>> volumes;
    std::vector<int> volumeOf(n, -1);
    for (int i = 0; i < n; ++i) {
        int& g = volumeOf[find(i)];
        if (g < 0) {
            g = int(volumes.size());
            volumes.emplace_back();
        }
        volumes[g].push_back(i);
    }
    return volumes;
}

TetOptions volumeTetOptions(const std::vector<MediumDesc>& media, const std::vector<int>& members) {
    TetOptions options = media[members[0]].tetOptions;
    const auto finest = [](double& a, double b) {
        if (b > 0 && (a == 0 || b < a)) a = b;  // 0 asks for nothing
    };
    for (int i : members) {
        finest(options.maxVolume, media[i].tetOptions.maxVolume);
        finest(options.radiusEdgeRatio, media[i].tetOptions.radiusEdgeRatio);
        options.strict = options.strict || media[i].tetOptions.strict;
    }
    return options;
}

void interfaceMaterials(const TetMesh& mesh, const std::vector<MediumDesc>& media, const std::vector<int>& members,
                        std::vector<uint32_t>& triangleMaterial, std::vector<MaterialDesc>& materials) {
    const auto ior = [&](int32_t r) {
        for (; r >= 0; r = mesh.regionParent[size_t(r)]) {
            const MaterialDesc& b = media[members[size_t(r)]].boundaryMaterial;
            if (b.type == MaterialType::Dielectric) return b.ior;
        }
        return 1.0;
    };
    triangleMaterial.clear();
    materials.clear();
    for (const auto& [behind, front] : mesh.surfaceRegions) {
        const double a = ior(behind), b = ior(front);
        const MaterialDesc m =
            a == b ? MaterialDesc{MaterialType::Interface} : MaterialDesc{MaterialType::Dielectric, RGB(0.5), a / b};
        uint32_t k = 0;
        while (k < materials.size() && !(materials[k].type == m.type && materials[k].ior == m.ior)) ++k;
        if (k == materials.size()) materials.push_back(m);
        triangleMaterial.push_back(k);
    }
}

}  // namespace tetglow
