// The parity baseline's debug picture of its inside test: every camera ray is marched through each
// medium's bounding box, and each sample is classified by the tets and by the parity test.
// Green: inside by both; dim red: in the box but outside by both (what --boundary bbox would
// fill); magenta: the two disagree, so a single wrong sample shows.
#pragma once
#include <vector>

#include "render/Image.h"
#include "scene/Camera.h"
#include "tet/TetTraversal.h"

namespace tetglow {

struct BoundaryPicture {
    Image image;
    size_t samples = 0;                 // march samples inside some bounding box
    size_t disagreements = 0;           // samples where tets and parity differ
    size_t pixelsWithDisagreement = 0;  // magenta pixels
};

// `step`: the march's step in world units; `parityRays`: rays per parity test (majority).
BoundaryPicture renderBoundaryPicture(const Camera& camera, const std::vector<const TetTraversal*>& media, double step,
                                      int parityRays);

}  // namespace tetglow
