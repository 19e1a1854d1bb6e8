// Light that a unidirectional path tracer cannot carry. A delta light (point, spot of radius 0,
// distant) is reached only by next-event estimation; a shadow ray from inside a volume sealed in
// a dielectric boundary cannot refract (Scene::sealed), and a path that refracts out never hits a
// light of zero size. So volpath and single leave such a medium dark under delta lights, as pbrt
// and Cycles do; photon mapping traces from the light and renders it.
#pragma once
#include <string>
#include <vector>

#include "render/Scene.h"

namespace tetglow {

// One line per sealed, scattering volume that the scene's delta lights light only through its
// dielectric boundary, naming the volume, the integrator and the one that renders it; none for
// the photon integrator or where no such light exists.
std::vector<std::string> unsampledLightWarnings(const Scene& scene, IntegratorType integrator);

}  // namespace tetglow
