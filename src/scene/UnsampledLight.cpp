#include "scene/UnsampledLight.h"

#include <algorithm>

namespace tetglow {

bool hasDeltaLight(const Scene& scene) {
    const auto& lights = scene.lights();
    return std::any_of(lights.begin(), lights.end(), [](const auto& l) { return l->isDelta(); });
}

std::vector<std::string> unsampledLightWarnings(const Scene& scene, IntegratorType integrator) {
    std::vector<std::string> warnings;
    if (!hasDeltaLight(scene)) return warnings;
    const std::string name = integrator == IntegratorType::VolPath ? "volpath" : "single";
    for (size_t v = 0; v < scene.volumes().size(); ++v) {
        const SceneVolume& volume = scene.volumes()[v];
        if (!scene.sealed(int(v)) || !volume.volume->scatters()) continue;
        warnings.push_back(volume.name + " lies inside a dielectric boundary, through which " + name +
                           " cannot carry light from a point, spot or distant light (a specular path from a light "
                           "of zero size): that light is missing from it; --integrator photon renders it");
    }
    return warnings;
}

}  // namespace tetglow
