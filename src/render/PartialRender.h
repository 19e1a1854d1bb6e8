// A part of a render (passes A..B-1 of N) as a file that `tetglow merge` combines with the
// others: an OpenEXR image whose R, G, B are the part's own mean (so it can be looked at) and
// whose extra channels hold the film's exact state (Film.h): the fixed-point sums as four
// 32-bit words per channel (sum.R.0 .. sum.B.3, least significant first), the samples per
// pixel (count) and the dropped ones (dropped). Attributes say what it is a part of and which
// build of tetglow made it.
#pragma once
#include <string>
#include <vector>

#include "render/BuildId.h"
#include "render/Film.h"

namespace tetglow {

struct PartInfo {
    std::string fingerprint;        // the scene and every setting that changes the image (sceneFingerprint)
    std::string build = buildId();  // the binary that rendered it: another build may sample differently
    std::string scene;              // the scene file, for messages
    int firstPass = 0, endPass = 0, totalPasses = 0;
    int frame = 0;
};

// The memory a film takes per pixel: its sum, sample count, dropped and too-bright counts.
inline constexpr size_t kFilmBytesPerPixel = sizeof(FixedSum) + 3 * sizeof(uint32_t);

struct PartialRender {
    PartInfo info;
    Film film{0, 0};
};

// InputError naming the path on failure.
void writePartial(const std::string& path, const PartialRender& part);
// A missing or corrupt file, an EXR that is not a partial render, or one whose film would not
// fit in memory beside `heldBytes` already taken, is an InputError naming the path.
PartialRender readPartial(const std::string& path, double heldBytes = 0);

// Sums parts of the same render into the whole, holding one part at a time beside the sum.
// Refuses, with an InputError naming the file, parts of another build, a different scene,
// settings or frame, and passes that overlap, are missing or lie outside the render's.
PartialRender mergeParts(const std::vector<std::string>& paths);

}  // namespace tetglow
