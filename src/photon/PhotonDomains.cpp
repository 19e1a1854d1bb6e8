#include "photon/PhotonDomains.h"

#include <algorithm>
#include <numeric>

namespace tetglow {

namespace {

// The same medium: equal coefficients (a constant density already scales them) and, where the
// density varies, the same density field (evaluated at the same vertices, so equal there).
bool sameMedium(const MediumDesc& a, const MediumDesc& b, const Medium& ra, const Medium& rb) {
    const MediumParams &p = ra.params, &q = rb.params;
    if (p.sigmaA != q.sigmaA || p.sigmaS != q.sigmaS || p.g != q.g || p.emission != q.emission || a.cavity != b.cavity)
        return false;
    if (a.density.isConstant() && b.density.isConstant()) return true;
    const DensityDesc &x = a.density, &y = b.density;
    return x.type == y.type && x.offset == y.offset && x.gradient == y.gradient && x.frequency == y.frequency &&
           x.amplitude == y.amplitude && x.seed == y.seed;
}

int root(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

PhotonDomains photonDomains(const Scene& scene) {
    const size_t n = scene.media().size();
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (const SceneVolume& v : scene.volumes()) {
        const Volume& volume = *v.volume;
        const TetMesh& mesh = volume.mesh();
        for (size_t s = 0; s < mesh.surface.size(); ++s) {
            const auto [r0, r1] = mesh.surfaceRegions[s];
            if (r1 < 0 || volume.stopsAt(uint32_t(s))) continue;
            const int a = v.regionMedium[size_t(r0)], b = v.regionMedium[size_t(r1)];
            if (!sameMedium(scene.desc().media[a], scene.desc().media[b], volume.region(r0), volume.region(r1)))
                continue;
            const int ra = root(parent, a), rb = root(parent, b);
            parent[std::max(ra, rb)] = std::min(ra, rb);  // a set's root stays its smallest medium
        }
    }
    PhotonDomains d;
    d.ofMedium.assign(n, -1);
    for (size_t m = 0; m < n; ++m) {
        const int r = root(parent, int(m));
        if (d.ofMedium[r] < 0) {  // roots come first: a root is its domain's smallest medium
            d.ofMedium[r] = int(d.media.size());
            d.media.emplace_back();
            d.volume.push_back(scene.media()[m].volume);
        }
        d.ofMedium[m] = d.ofMedium[r];
        d.media[size_t(d.ofMedium[m])].push_back(int(m));
    }
    d.boundary.resize(d.media.size());
    for (const SceneVolume& v : scene.volumes()) {
        const TetMesh& mesh = v.volume->mesh();
        for (size_t s = 0; s < mesh.surface.size(); ++s) {
            const auto [r0, r1] = mesh.surfaceRegions[s];
            const int a = d.ofMedium[size_t(v.regionMedium[size_t(r0)])],
                      b = r1 < 0 ? -1 : d.ofMedium[size_t(v.regionMedium[size_t(r1)])];
            if (a == b) continue;
            d.boundary[size_t(a)].push_back(mesh.surface[s]);
            if (b >= 0) d.boundary[size_t(b)].push_back(mesh.surface[s]);
        }
    }
    return d;
}

}  // namespace tetglow
