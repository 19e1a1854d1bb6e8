#include "scene/TextEncoding.h"

#include <iconv.h>
#include <cerrno>

#include "base/Error.h"

namespace tetglow {

std::string utf8Text(std::string data, const std::string& path) {
    if (data.rfind("\xEF\xBB\xBF", 0) == 0) return data.substr(3);
    const char* encoding = data.rfind("\xFF\xFE", 0) == 0   ? "UTF-16LE"
                           : data.rfind("\xFE\xFF", 0) == 0 ? "UTF-16BE"
                                                            : nullptr;
    if (!encoding) return data;
    const std::string fix = "; save it as UTF-8 (in Notepad: Save As, Encoding UTF-8)";
    if (data.size() % 2)
        throw InputError(path + ": UTF-16 text (it starts with a byte-order mark) of an odd number of bytes" + fix);
    iconv_t cd = iconv_open("UTF-8", encoding);
    if (cd == iconv_t(-1)) throw InputError(path + ": UTF-16 text, and this system cannot decode it" + fix);
    // Every UTF-16 unit of 2 bytes becomes at most 3 bytes of UTF-8 (a pair of 4, 4).
    std::string out(data.size() / 2 * 3, '\0');
    char* in = data.data() + 2;
    size_t inLeft = data.size() - 2, outLeft = out.size();
    char* to = out.data();
    const size_t done = iconv(cd, &in, &inLeft, &to, &outLeft);
    iconv_close(cd);
    if (done == size_t(-1))
        throw InputError(path + ": UTF-16 text that does not decode at byte " + std::to_string(data.size() - inLeft) +
                         " (half a surrogate pair)" + fix);
    out.resize(out.size() - outLeft);
    return out;
}

}  // namespace tetglow
