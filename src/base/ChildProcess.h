// Work that a hostile input can make crash, loop or take all memory (a library's parser, a
// mesher) runs in a forked child process, bounded in memory and wall-clock time, and hands back
// bytes through a pipe. Every way it can end is a distinct error in the caller.
#pragma once
#include <functional>
#include <stdexcept>
#include <string>

namespace tetglow {

struct ChildLimits {
    // Memory the work may take beyond what the child had at the fork: resident memory, polled
    // by the parent in every build; outside AddressSanitizer (whose shadow memory is a
    // reservation of terabytes) also address space, so that one huge allocation fails at once.
    // The answer the parent gathers is bounded by it too.
    double memoryBytes;
    double seconds;  // wall-clock time from the fork
};

// Half of memoryLimit() (base/Memory.h): the parent keeps the rest for the answer it decodes.
double defaultChildMemory();

// From now on every child gets at most `ceiling` (a fuzzer, say, whose own bounds are lower).
void capChildLimits(const ChildLimits& ceiling);

// How a child ended without an answer. what(): a phrase to follow the name of the work, e.g.
// "ran out of memory (its limit is 2.15 GB)".
struct ChildFailure : std::runtime_error {
    enum class Kind { OutOfMemory, OutOfTime, Signal, Exit, Exception };
    ChildFailure(Kind kind, const std::string& detail, const std::string& phrase)
        : std::runtime_error(phrase), kind(kind), detail(detail) {}
    Kind kind;
    std::string
        detail;  // the limit, the signal ("Segmentation fault, SIGSEGV"), the exit status or the exception's message
};

// Runs `work` in a forked child under `limits` and returns the bytes it returned. An InputError
// thrown in the child is thrown here as it was; any other outcome is a ChildFailure: the memory
// or the time limit (the child is killed), a signal, an exit, another exception's message.
// TBB's worker threads end before the fork, so that none holds a lock the child needs.
std::string runInChild(const std::function<std::string()>& work, ChildLimits limits);

}  // namespace tetglow
