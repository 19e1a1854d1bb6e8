// What `render`, `preview` and `farm` say about the media before rendering: each volume's tets,
// and every repair validation made to a medium's mesh (the line `tetrahedralize` prints), with a
// warning where holes spanning more than kLargeHoleShare of the surface were filled: the mesh
// then renders as a solid its author may not have meant.
#pragma once
#include <string>

#include "scene/Scene.h"

namespace tetglow::cli {

inline constexpr double kLargeHoleShare = 0.1;

// On stderr: "medium NAME: repaired: SUMMARY" for each repair, and the warning.
void printRepairs(const std::string& medium, const ValidationReport& report);

// Each volume's tets, then its media's repairs.
void printVolumes(const Scene& scene);

// The repairs of every medium of `desc`, found by validating each mesh on its own (as the tets
// will be made), for a command that does not build the tets itself.
void printRepairs(const SceneDesc& desc);

}  // namespace tetglow::cli
