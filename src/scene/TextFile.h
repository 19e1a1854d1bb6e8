// Whole files as text, for the scene readers.
#pragma once
#include <string>

namespace tetglow {

// The bytes of the file at `path`. Throws InputError "<path>: no such file" (or "is a
// directory", "cannot open").
std::string readTextFile(const std::string& path);

}  // namespace tetglow
