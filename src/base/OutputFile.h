// Files a command writes, handled the same way by every command: the output is checked before
// any work (not a folder, not one of the inputs, not a link to nothing, its folder created and
// writable), and written to a temporary beside it that is renamed when complete, so that a
// failed or interrupted write leaves neither a partial file nor the temporary behind. The
// outputs of one command are committed together: every temporary is complete before the first
// rename. A temporary is a new file under a name no one can guess (in a shared folder another
// user could otherwise plant a link at the name and choose the file written), and an output
// replaced keeps its permissions.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace tetglow {

// InputError when `path` has no file name, is a folder, is a link to nothing, or names one of
// `inputs` (by any spelling or link: std::filesystem::equivalent), or when its folder cannot be
// written; creates the folders it lies in when they are missing.
void prepareOutput(const std::string& path, const std::vector<std::string>& inputs = {});

// A file of a commit: write(temporary) fills the temporary (created empty) that is renamed onto
// `path` (whose folder must exist: commands create it with prepareOutput). A link at `path` that
// the user named is written through, as editors do: the temporary lies beside the file it leads
// to and replaces that file, and the link stays. A link at a name the program chose (`named`
// false: a mesh beside a converted scene, a cache entry, a numbered save) is refused, so that no
// one who can plant a link there chooses the file written.
struct OutputWrite {
    std::string path;
    std::function<void(const std::string& temporary)> write;
    bool named = true;
};
// Writes every file to its temporary, then renames them all (renames within a folder need no
// space, so a full disk fails a write, never a rename). Any exception becomes an InputError
// "<path>: cannot write: <why>" on one line; no temporary remains, and after a failed write
// every path holds what it held before.
void writeTogether(const std::vector<OutputWrite>& files);
// The same for one file.
void writeAtomically(const std::string& path, const std::function<void(const std::string& temporary)>& write,
                     bool named = true);
// The same for a file written as a stream: write(out) fills it; a failed stream is an error.
void writeStream(const std::string& path, const std::function<void(std::ostream& out)>& write, bool named = true);
// The write of writeStream, for a commit of several files.
OutputWrite streamWrite(const std::string& path, std::function<void(std::ostream& out)> write, bool named = true);

// Removes the temporaries of the writes in progress. Async-signal-safe: for a signal handler
// that ends the process in the middle of a write.
void removeTemporaries() noexcept;

}  // namespace tetglow
