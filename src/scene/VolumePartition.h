// Which media of a scene share one tet mesh, and what lies between its regions. Media that nest
// or touch are found from their meshes (never stated) and tetrahedralized together, one region
// each; media apart from all others keep a tet mesh of their own.
#pragma once
#include <vector>

#include "scene/SceneDescription.h"
#include "tet/TetMesh.h"

namespace tetglow {

// The volumes, each its media in description order (its region r is medium members[r]), ordered by their
// first medium. `nesting`: as a reader found it (SceneDesc::nesting), else null to find it here.
// Throws InputError for media that cross (naming both and a triangle pair), an open or invalid
// mesh (naming it), and a cavity that lies in no medium.
std::vector<std::vector<int>> findVolumes(const std::vector<MediumDesc>& media, const MediaNesting* nesting = nullptr);

// The finest of the members' TetGen options: the smallest maximum volume and radius-edge ratio
// any of them asks for.
TetOptions volumeTetOptions(const std::vector<MediumDesc>& media, const std::vector<int>& members);

// For every surface triangle of a volume's tet mesh, the material between the regions on its
// two sides (region r: media[members[r]]): index-matched where their indices of refraction are
// equal, else a dielectric with the ratio behind / in front. A region's index is its boundary's
// where that is a dielectric, else that of the region around it (1 outside every region).
void interfaceMaterials(const TetMesh& mesh, const std::vector<MediumDesc>& media, const std::vector<int>& members,
                        std::vector<uint32_t>& triangleMaterial, std::vector<MaterialDesc>& materials);

}  // namespace tetglow
