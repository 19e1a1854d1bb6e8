// The pbrt-v3 tokenizer alone: strings, escapes, comments, numbers, brackets.
#include "FuzzInput.h"
#include "base/Error.h"
#include "scene/PbrtTokenizer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        tetglow::PbrtTokenizer tokens(tetglow::fuzz::writeFile("scene.pbrt", data, size));
        while (tokens.next()) {}
    } catch (const tetglow::InputError&) {}
    return 0;
}
