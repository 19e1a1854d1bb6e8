// Which build of tetglow is running: parts of one render (render/PartialRender.h) must all come
// from the same code, since another build may sample the same pass differently.
#pragma once
#include <string>

namespace tetglow {

// The GNU build id of the running executable in hex (the linker's hash of the program, which
// CMakeLists.txt asks for with --build-id), e.g. "3f1c...". Computed once.
const std::string& buildId();

}  // namespace tetglow
