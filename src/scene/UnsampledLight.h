// Light that a unidirectional path tracer cannot carry. A delta light (point, spot of radius 0,
// distant) is reached only by next-event estimation; a shadow ray from inside a volume sealed in
// a dielectric boundary cannot refract (Scene::sealed), and a path that refracts out never hits a
// light of zero size. So volpath and single leave such a medium dark under delta lights, as pbrt
// and Cycles do; photon mapping traces from the light and renders it, unless the medium is
// optically dense: photon mapping walks that as volpath does.
#pragma once
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace tetglow {

// Whether the scene has a point, spot of radius 0 or distant light.
bool hasDeltaLight(const Scene& scene);

// One line per sealed, scattering volume that the scene's delta lights light only through its
// dielectric boundary, naming the volume, volpath or single (`integrator`) and the integrator that
// renders it; none where no such light exists.
std::vector<std::string> unsampledLightWarnings(const Scene& scene, IntegratorType integrator);

}  // namespace tetglow
