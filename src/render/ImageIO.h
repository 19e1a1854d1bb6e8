// Image files: OpenEXR for data (read and write), PNG for a quick look (write only).
// Files are written to a temporary name in the same directory and renamed when complete,
// so an interrupted or failed write never leaves a partial or empty file.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/Image.h"

namespace tetglow {

// An extra EXR layer, e.g. name "direct" -> channels direct.R, direct.G, direct.B.
struct ImageLayer {
    std::string name;
    const Image* image;
};

// 32-bit float R, G, B plus the layers (same size as rgb). InputError naming the path on failure.
void writeExr(const std::string& path, const Image& rgb, const std::vector<ImageLayer>& layers = {});

// The most pixels readExr reads (8192 x 8192: three floats each, 768 MiB), and at most
// kMaxResolution along either side; a header that claims more is refused before allocating.
inline constexpr int64_t kMaxExrPixels = int64_t(1) << 26;

// R, G, B of the default layer, or of the named one; half, float or uint channels, scanline or tiled.
// A missing, corrupt or incomplete file, missing channels, a special file, a file over
// kMaxImageFileBytes or an image over kMaxExrPixels is an InputError naming the path.
Image readExr(const std::string& path, const std::string& layer = "");

// An 8-bit sRGB preview: scale by 2^exposure, tonemap, sRGB OETF, round. The tonemap clamps
// negatives to 0 and divides a pixel whose largest channel exceeds 1 by that channel: values in
// [0, 1] are shown exactly, and overexposed pixels keep their hue instead of drifting towards
// white or yellow as a per-channel clamp would. NaN or Inf pixels are magenta, so they stand out.
void writePng(const std::string& path, const Image& rgb, double exposure = 0);
// The EXR of writeExr and the PNG of writePng beside it (previewPath), committed together
// (writeTogether): after a failure both files are as they were.
void writeExrAndPng(const std::string& exrPath, const Image& rgb, double exposure = 0);
// The same preview as PNG file bytes (tetglow preview serves them).
std::vector<uint8_t> encodePng(const Image& rgb, double exposure = 0);

// "out/x.exr" -> "out/x.png".
std::string previewPath(const std::string& exrPath);

}  // namespace tetglow
