#include "FuzzInput.h"

#include <unistd.h>
#include <filesystem>
#include <fstream>

namespace tetglow::fuzz {
namespace {

struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("tetglow-fuzz-" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

}  // namespace

const std::string& folder() {
    static const Folder f;
    static const std::string s = f.path.string();
    return s;
}

std::string writeFile(const std::string& name, const void* data, size_t size) {
    const std::string path = folder() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
    return path;
}

}  // namespace tetglow::fuzz
