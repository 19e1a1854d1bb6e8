// Image files: OpenEXR for data (read and write), PNG for a quick look (write only).
// Files are written to a temporary name in the same directory and renamed when complete,
// so an interrupted or failed write never leaves a partial or empty file.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "render/Image.h"

namespace tetglow {

// Runs write(temporary path) and renames the result onto path; on failure the temporary is
// removed and the error is an InputError naming path. Every file writer goes through it.
void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

// An extra EXR layer, e.g. name "direct" -> channels direct.R, direct.G, direct.B.
struct ImageLayer {
    std::string name;
    const Image* image;
};

// 32-bit float R, G, B plus the layers (same size as rgb). InputError naming the path on failure.
void writeExr(const std::string& path, const Image& rgb, const std::vector<ImageLayer>& layers = {});

// R, G, B of the default layer, or of the named one; half, float or uint channels, scanline or tiled.
// A missing, corrupt or incomplete file, or missing channels, is an InputError naming the path.
Image readExr(const std::string& path, const std::string& layer = "");

// An 8-bit sRGB preview: scale by 2^exposure, tonemap, sRGB OETF, round. The tonemap clamps
// negatives to 0 and divides a pixel whose largest channel exceeds 1 by that channel: values in
// [0, 1] are shown exactly, and overexposed pixels keep their hue instead of drifting towards
// white or yellow as a per-channel clamp would. NaN or Inf pixels are magenta, so they stand out.
void writePng(const std::string& path, const Image& rgb, double exposure = 0);

// "out/x.exr" -> "out/x.png".
std::string previewPath(const std::string& exrPath);

}  // namespace tetglow
