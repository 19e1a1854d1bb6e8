// The nesting of a scene's media, from their meshes: which medium lies directly inside which,
// and which share boundary triangles. Both scene formats and the scene build ask this once.
#pragma once
#include <vector>

#include "scene/SceneDescription.h"

namespace tetglow {

// Throws InputError for media that cross (naming both and a triangle pair) and for an open or
// invalid mesh (naming it). Strict when any medium asks to be.
MediaNesting nestMedia(const std::vector<MediumDesc>& media);

}  // namespace tetglow
