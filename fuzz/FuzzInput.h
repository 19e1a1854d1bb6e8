// What the fuzz targets share. The readers take paths, so each input is written to a file first.
// An InputError is the right answer to bad input; any other exception that escapes a target is a
// finding (raw library text such as std::bad_alloc instead of a message), as is any crash,
// sanitizer report, hang (-timeout) or runaway memory (-rss_limit_mb).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace tetglow::fuzz {

// This process's own folder (removed at exit), for the input and the files it may name.
const std::string& folder();
// Writes `size` bytes to folder()/name and returns the path.
std::string writeFile(const std::string& name, const void* data, size_t size);

}  // namespace tetglow::fuzz
