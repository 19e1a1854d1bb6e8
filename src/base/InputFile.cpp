#include "base/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/Error.h"

namespace tetglow {
namespace {

const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
}

// "70 MiB" for sizes of a MiB or more, else bytes.
std::string size(uint64_t bytes) {
    return bytes >= kMiB ? std::to_string(bytes / kMiB) + " MiB" : std::to_string(bytes) + " bytes";
}

thread_local InputLog* currentLog = nullptr;

struct Fd {
    int fd;
    ~Fd() { ::close(fd); }
};

}  // namespace

InputLog::InputLog() : outer_(currentLog) { currentLog = this; }
InputLog::~InputLog() { currentLog = outer_; }

void noteInputFile(const std::string& path) {
    if (currentLog) currentLog->files_.push_back(path);
}

std::string readInputFile(const std::string& path, uint64_t maxBytes, const char* what) {
    // O_NONBLOCK: opening a FIFO without a writer returns at once instead of waiting; the type
    // is then checked on the open file itself, so it cannot change between check and read.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        if (errno == ENOENT) throw InputError(path + ": no such file");
        throw InputError(path + ": cannot open: " + std::strerror(errno));
    }
    const Fd guard{fd};
    if (currentLog) currentLog->files_.push_back(path);
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError(path + ": cannot open: " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw InputError(path + ": is " + kindOf(st.st_mode) + ", not a regular file");
    const uint64_t claimed = uint64_t(st.st_size);
    const auto tooLarge = [&](const std::string& bytes) {
        return InputError(path + ": " + bytes + ", larger than the " + size(maxBytes) + " limit for " + what);
    };
    if (claimed > maxBytes) throw tooLarge(size(claimed));
    std::string data(claimed + 1, '\0');  // one more byte, so that the end is seen without growing
    size_t used = 0;
    // Reads to the end even if the file grew after fstat (or has no size, as in /proc), but
    // never more than one byte past the limit.
    for (;;) {
        if (used == data.size()) {
            if (used > maxBytes) throw tooLarge("more than " + size(maxBytes));
            data.resize(std::min<uint64_t>(std::max<uint64_t>(2 * used, 4096), maxBytes + 1));
        }
        const ssize_t n = ::read(fd, data.data() + used, data.size() - used);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw InputError(path + ": cannot read: " + std::strerror(errno));
        if (n == 0) break;
        used += size_t(n);
    }
    data.resize(used);
    return data;
}

}  // namespace tetglow
