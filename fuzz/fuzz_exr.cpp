// The OpenEXR reader behind `tetglow diff`: the header's claims, then the pixels.
#include "FuzzInput.h"
#include "base/Error.h"
#include "render/ImageIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::readExr(tetglow::fuzz::writeFile("image.exr", data, size));
    } catch (const tetglow::InputError&) {}
    return 0;
}
