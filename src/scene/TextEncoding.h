// Mesh files written as UTF-16 text (Windows tools save OBJ that way, byte-order mark first) or
// with a UTF-8 byte-order mark, turned into the plain UTF-8 the text readers take.
#pragma once
#include <string>

namespace tetglow {

// `data` as UTF-8 without a byte-order mark: UTF-16 (little- or big-endian, told by its mark)
// decoded, a UTF-8 mark dropped, anything else as it is. UTF-16 that does not decode (an odd
// byte count, a lone surrogate) is an InputError "<path>: ...".
std::string utf8Text(std::string data, const std::string& path);

}  // namespace tetglow
