#include "base/ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <vector>

#include <tbb/global_control.h>

#include "base/Error.h"
#include "base/Memory.h"

namespace tetglow {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kShadowMemory = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kShadowMemory = true;
#else
constexpr bool kShadowMemory = false;
#endif
#else
constexpr bool kShadowMemory = false;
#endif

// How often the parent looks at the child's memory and the clock: a child that allocates as fast
// as the kernel can hand out pages (a few GB/s) overshoots its limit by tens of MB at most.
constexpr int kPollMilliseconds = 10;

std::atomic<double> ceilingMemory{std::numeric_limits<double>::infinity()};
std::atomic<double> ceilingSeconds{std::numeric_limits<double>::infinity()};

// The answer's last byte says what the rest is.
enum Tag : char { kResult = 'R', kInputError = 'I', kException = 'E', kOutOfMemory = 'M' };

int answerFd = -1;  // in the child, for the new-handler

void writeAll(int fd, const char* data, size_t n) {
    while (n > 0) {
        const ssize_t w = ::write(fd, data, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) ::_exit(71);
        data += w;
        n -= size_t(w);
    }
}

// /proc/<pid>/statm: the sizes in pages of the address space (field 0) and of what is resident (1).
double statmBytes(pid_t pid, int field) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/statm");
    double pages[2] = {0, 0};
    in >> pages[0] >> pages[1];
    return pages[field] * double(::sysconf(_SC_PAGE_SIZE));
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g s", s);
    return text;
}

ChildFailure outOfMemory(double limit) {
    return ChildFailure(ChildFailure::Kind::OutOfMemory, gigabytes(limit),
                        "ran out of memory (its limit is " + gigabytes(limit) + ")");
}

// In the child: run the work and write its answer; never returns.
[[noreturn]] void runChild(const std::function<std::string()>& work, int fd, pid_t parent, double memoryBytes) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlives the parent
    if (::getppid() != parent) ::_exit(72);
    if (!kShadowMemory) {
        const double room = statmBytes(::getpid(), 0) + memoryBytes;
        const rlimit limit{rlim_t(room), rlim_t(room)};
        ::setrlimit(RLIMIT_AS, &limit);
    }
    answerFd = fd;
    // Libraries may catch std::bad_alloc and report something else: the first failed
    // allocation ends the child with the cause.
    std::set_new_handler([] {
        const char tag = kOutOfMemory;
        writeAll(answerFd, &tag, 1);
        ::_exit(0);
    });
    std::string answer;
    char tag = kResult;
    try {
        answer = work();
    } catch (const std::bad_alloc&) {
        answer.clear();
        tag = kOutOfMemory;
    } catch (const InputError& e) {
        answer = e.what();
        tag = kInputError;
    } catch (const std::exception& e) {
        answer = e.what();
        tag = kException;
    } catch (...) {
        answer = "an exception that is not a std::exception";
        tag = kException;
    }
    writeAll(fd, answer.data(), answer.size());
    writeAll(fd, &tag, 1);
    ::_exit(0);
}

ChildFailure killedBy(int sig) {
    const char* abbrev = ::sigabbrev_np(sig);
    const std::string name = abbrev ? "SIG" + std::string(abbrev) : "signal " + std::to_string(sig);
    return ChildFailure(ChildFailure::Kind::Signal, ::strsignal(sig) + (", " + name),
                        "was killed by " + name + " (" + ::strsignal(sig) + ")");
}

// A thread inside the allocator at the fork leaves the allocator's lock held in the child for
// ever. glibc's malloc takes its locks around fork(); AddressSanitizer's (clang 14) does not, and
// TBB's workers free their task objects after the parallel algorithm has returned. So the
// workers end before the fork (the next parallel algorithm starts them again). Where another
// thread is inside a parallel algorithm they cannot end, and the fork goes ahead.
void endWorkerThreads() {
    tbb::task_scheduler_handle scheduler{tbb::attach{}};
    tbb::finalize(scheduler, std::nothrow);
}

}  // namespace

double defaultChildMemory() { return memoryLimit() / 2; }

void capChildLimits(const ChildLimits& ceiling) {
    ceilingMemory = ceiling.memoryBytes;
    ceilingSeconds = ceiling.seconds;
}

std::string runInChild(const std::function<std::string()>& work, ChildLimits limits) {
    limits.memoryBytes = std::min(limits.memoryBytes, ceilingMemory.load());
    limits.seconds = std::min(limits.seconds, ceilingSeconds.load());
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    std::fflush(nullptr);
    endWorkerThreads();
    const pid_t parent = ::getpid();
    const double shared = statmBytes(parent, 1);  // the child's resident memory at the fork
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw std::runtime_error(std::string("cannot fork a process: ") + std::strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        runChild(work, fds[1], parent, limits.memoryBytes);
    }
    ::close(fds[1]);
    const int fd = fds[0];
    auto stop = [&](const ChildFailure& why) {
        ::kill(pid, SIGKILL);
        while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {}
        ::close(fd);
        throw why;
    };
    std::string answer;
    std::vector<char> buffer(1 << 16);
    // Reads what is in the pipe, waiting up to `ms`; false at its end. The child's end can stay
    // open after it exits (a child forked meanwhile by another thread holds a copy), so the
    // child's exit, not the pipe's end, ends the answer.
    auto read = [&](int ms) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, ms) <= 0) return true;
        const ssize_t n = ::read(fd, buffer.data(), buffer.size());
        if (n > 0) answer.append(buffer.data(), size_t(n));
        return n > 0 || (n < 0 && errno == EINTR);
    };
    int status = 0;
    for (auto lastLook = start;;) {
        const size_t before = answer.size();
        bool open = read(kPollMilliseconds);
        if (!open || answer.size() == before) {
            const pid_t done = ::waitpid(pid, &status, WNOHANG);
            if (done == pid) {
                for (size_t had = SIZE_MAX; open && had != answer.size();) had = answer.size(), open = read(0);
                break;
            }
            if (done < 0 && errno != EINTR)
                stop(ChildFailure(ChildFailure::Kind::Exit, "lost", "was lost (waitpid failed)"));
            if (!open) ::poll(nullptr, 0, 1);
        }
        const auto now = std::chrono::steady_clock::now();
        if (now - lastLook < std::chrono::milliseconds(kPollMilliseconds)) continue;
        lastLook = now;
        if (std::chrono::duration<double>(now - start).count() > limits.seconds)
            stop(ChildFailure(ChildFailure::Kind::OutOfTime, seconds(limits.seconds),
                              "ran past its time limit of " + seconds(limits.seconds)));
        if (double(answer.size()) > limits.memoryBytes || statmBytes(pid, 1) - shared > limits.memoryBytes)
            stop(outOfMemory(limits.memoryBytes));
    }
    ::close(fd);
    if (WIFSIGNALED(status)) throw killedBy(WTERMSIG(status));
    if (WEXITSTATUS(status) != 0 || answer.empty()) {
        const std::string code = std::to_string(WEXITSTATUS(status));
        throw ChildFailure(ChildFailure::Kind::Exit, code, "exited with status " + code + " before answering");
    }
    const char tag = answer.back();
    answer.pop_back();
    switch (tag) {
        case kResult: return answer;
        case kInputError: throw InputError(answer);
        case kOutOfMemory: throw outOfMemory(limits.memoryBytes);
        default: throw ChildFailure(ChildFailure::Kind::Exception, answer, "failed: " + oneLine(answer));
    }
}

}  // namespace tetglow
