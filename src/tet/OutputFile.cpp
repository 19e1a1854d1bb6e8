#include "tet/OutputFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "tet/TriangleMesh.h"  // InputError

namespace tetglow {
namespace fs = std::filesystem;

void prepareOutput(const std::string& path, const std::vector<std::string>& inputs) {
    const fs::path target(path);
    std::error_code ec;
    if (path.empty() || !target.has_filename() || fs::is_directory(target, ec))
        throw InputError("'" + path + "': the output must name a file, not a folder");
    for (const auto& input : inputs)
        if (fs::equivalent(input, target, ec)) throw InputError(path + ": the output is an input (" + input + "): refusing to overwrite it");
    const fs::path dir = target.parent_path();
    if (dir.empty() || fs::is_directory(dir, ec)) return;
    fs::create_directories(dir, ec);
    if (ec) throw InputError(path + ": cannot create the folder " + dir.string() + ": " + ec.message());
}

void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write) {
    const fs::path dir = fs::path(path).parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec)) throw InputError(path + ": the folder " + dir.string() + " does not exist");
    const std::string temporary = path + "." + std::to_string(::getpid()) + ".tmp";
    try {
        write(temporary);
        fs::rename(temporary, path);
    } catch (const fs::filesystem_error& e) {
        fs::remove(temporary, ec);
        throw InputError(path + ": cannot write: " + e.code().message());
    } catch (const std::exception& e) {
        fs::remove(temporary, ec);
        throw InputError(path + ": cannot write: " + oneLine(e.what()));
    }
}

void writeStream(const std::string& path, const std::function<void(std::ostream& out)>& write) {
    writeAtomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throw std::runtime_error(std::strerror(errno));
        write(out);
        out.flush();
        if (!out) throw std::runtime_error("the write failed (is the disk full?)");
    });
}

}  // namespace tetglow
