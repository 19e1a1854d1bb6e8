// Where the photon integrator estimates density: regions of one volume that hold the same medium
// (equal coefficients and density) and meet at index-matched interfaces are one medium as far as
// light can tell, so they share one photon map and one kernel. Kept apart, a thin region (a shell
// between two spheres of one medium) would see only its own few photons and divide them by the
// sliver of each kernel that lies inside it, which the kernel's volume quadrature cannot resolve.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "scene/Scene.h"

namespace tetglow {

struct PhotonDomains {
    std::vector<int> ofMedium;            // per scene medium: its domain
    std::vector<std::vector<int>> media;  // per domain: its scene media, ascending
    // Per domain: the surface triangles of its volume's tet mesh with the domain on one side
    // only (its boundary: the volume's surface, dielectric interfaces and other media).
    std::vector<std::vector<std::array<uint32_t, 3>>> boundary;
    std::vector<int> volume;  // per domain: its volume
};

PhotonDomains photonDomains(const Scene& scene);

}  // namespace tetglow
