// A part of a render (passes A..B-1 of N) as a file that `tetglow merge` combines with the
// others: an OpenEXR image whose R, G, B are the part's own mean (so it can be looked at) and
// whose extra channels hold the film's exact state (Film.h): the fixed-point sums as four
// 32-bit words per channel (sum.R.0 .. sum.B.3, least significant first), the samples per
// pixel (count) and the dropped ones (dropped). Attributes say what it is a part of.
#pragma once
#include <string>
#include <vector>

#include "render/Film.h"

namespace tetglow {

struct PartInfo {
    std::string fingerprint;  // the scene and every setting that changes the image (sceneFingerprint)
    std::string scene;        // the scene file, for messages
    int firstPass = 0, endPass = 0, totalPasses = 0;
    int frame = 0;
};

struct PartialRender {
    PartInfo info;
    Film film{0, 0};
};

// InputError naming the path on failure.
void writePartial(const std::string& path, const PartialRender& part);
// A missing or corrupt file, or an EXR that is not a partial render, is an InputError naming the path.
PartialRender readPartial(const std::string& path);

// Sums parts of the same render into the whole. Refuses, with an InputError naming the file,
// parts of a different scene, settings or frame, and passes that overlap, are missing or lie
// outside the render's.
PartialRender mergeParts(const std::vector<std::string>& paths);

}  // namespace tetglow
