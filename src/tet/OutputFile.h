// Files a command writes, handled the same way by every command: the output is checked before
// any work (not a folder, not one of the inputs, its folder created), and written to a temporary
// beside it that is renamed when complete, so that a failed or interrupted write leaves neither a
// partial file nor the temporary behind.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace tetglow {

// InputError when `path` has no file name, is a folder, or names one of `inputs` (by any spelling
// or link: std::filesystem::equivalent); creates the folders it lies in when they are missing.
void prepareOutput(const std::string& path, const std::vector<std::string>& inputs = {});

// Runs write(temporary) and renames the temporary onto `path` (whose folder must exist: commands
// create it with prepareOutput). Any exception becomes an InputError "<path>: cannot write:
// <why>" on one line; the temporary is removed.
void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);
// The same for a file written as a stream: write(out) fills it; a failed stream is an error.
void writeStream(const std::string& path, const std::function<void(std::ostream& out)>& write);

}  // namespace tetglow
