// base/ChildProcess.h: work in a child process ends in its answer or in one distinct error,
// within its memory and time limits, whatever the work does.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include "Sanitizers.h"
#include "base/ByteMessage.h"
#include "base/ChildProcess.h"
#include "base/Error.h"

namespace tetglow {
namespace {

// The failure `work` ends in under `limits` (a test failure when it answers instead).
ChildFailure failureOf(const std::function<std::string()>& work, ChildLimits limits) {
    try {
        runInChild(work, limits);
    } catch (const ChildFailure& e) {
        return e;
    }
    ADD_FAILURE() << "the child answered";
    return ChildFailure(ChildFailure::Kind::Exception, "", "");
}

constexpr double kMiB = 1 << 20;

// A child that allocates and touches memory without end is killed at its limit.
TEST(ChildProcess, AChildThatAllocatesForeverRunsOutOfMemory) {
    const ChildFailure e = failureOf(
        [] {
            std::vector<std::vector<char>> held;
            for (;;) held.emplace_back(size_t(kMiB), 'x');
            return std::string();
        },
        {256 * kMiB, 600});
    EXPECT_EQ(e.kind, ChildFailure::Kind::OutOfMemory);
    EXPECT_STREQ(e.what(), "ran out of memory (its limit is 0.268 GB)");
}

// One allocation far beyond the limit fails at once (the address-space limit), before a page is
// touched; under AddressSanitizer only resident memory is bounded, so a lazy one succeeds.
TEST(ChildProcess, OneAllocationBeyondTheLimitRunsOutOfMemory) {
    if (test::kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory rules out an address-space limit";
    const ChildFailure e = failureOf([] { return std::string(size_t(4) << 30, 'x'); }, {256 * kMiB, 600});
    EXPECT_EQ(e.kind, ChildFailure::Kind::OutOfMemory) << e.what();
}

TEST(ChildProcess, AChildThatSleepsForeverRunsOutOfTime) {
    const ChildFailure e = failureOf(
        [] {
            std::this_thread::sleep_for(std::chrono::hours(1));
            return std::string();
        },
        {256 * kMiB, 0.5});
    EXPECT_EQ(e.kind, ChildFailure::Kind::OutOfTime);
    EXPECT_STREQ(e.what(), "ran past its time limit of 0.5 s");
}

// An InputError crosses as itself; any other exception as its message, on one line.
TEST(ChildProcess, ExceptionsInTheChildReachTheParent) {
    try {
        runInChild([]() -> std::string { throw InputError("box.glb: no triangles"); }, {256 * kMiB, 60});
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "box.glb: no triangles");
    }
    const ChildFailure e = failureOf([]() -> std::string { throw std::logic_error("two\nlines"); }, {256 * kMiB, 60});
    EXPECT_EQ(e.kind, ChildFailure::Kind::Exception);
    EXPECT_EQ(e.detail, "two\nlines");
    EXPECT_STREQ(e.what(), "failed: two lines");
}

TEST(ChildProcess, AChildThatSegfaultsNamesTheSignal) {
    const ChildFailure e = failureOf(
        [] {
            std::signal(SIGSEGV, SIG_DFL);  // AddressSanitizer's handler would report and exit instead
            *static_cast<volatile int*>(nullptr) = 1;
            return std::string();
        },
        {256 * kMiB, 60});
    EXPECT_EQ(e.kind, ChildFailure::Kind::Signal);
    EXPECT_EQ(e.detail, "Segmentation fault, SIGSEGV");
    EXPECT_STREQ(e.what(), "was killed by SIGSEGV (Segmentation fault)");
}

TEST(ChildProcess, AChildThatExitsWithoutAnAnswer) {
    const ChildFailure e = failureOf([]() -> std::string { ::_exit(3); }, {256 * kMiB, 60});
    EXPECT_EQ(e.kind, ChildFailure::Kind::Exit);
    EXPECT_STREQ(e.what(), "exited with status 3 before answering");
}

// Many times the pipe's buffer, byte for byte; an empty answer is an answer too.
TEST(ChildProcess, ALargeAnswerArrivesWhole) {
    const size_t size = size_t(64) << 20;
    const auto byteAt = [](size_t i) { return char(i * 2654435761u >> 24); };
    const std::string answer = runInChild(
        [&] {
            std::string s(size, '\0');
            for (size_t i = 0; i < size; ++i) s[i] = byteAt(i);
            return s;
        },
        {1024 * kMiB, 600});
    ASSERT_EQ(answer.size(), size);
    size_t wrong = 0;
    for (size_t i = 0; i < size; ++i) wrong += answer[i] != byteAt(i);
    EXPECT_EQ(wrong, 0u);
    EXPECT_EQ(runInChild([] { return std::string(); }, {256 * kMiB, 60}), "");
}

size_t threadsOf(pid_t pid) {
    const auto tasks = std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task");
    return size_t(std::distance(begin(tasks), end(tasks)));
}

// The parent forks with no worker thread of TBB alive: one that is inside the allocator at the
// fork leaves its lock held in the child, which waits on it for ever (AddressSanitizer's
// allocator takes no lock around fork(); tests that tetrahedralize hung so in the sanitized
// suite). The workers start again at the next parallel algorithm.
TEST(ChildProcess, NoWorkerThreadOfTheParentLivesAtTheFork) {
    if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one CPU: TBB starts no worker";
    const pid_t parent = ::getpid();
    for (int round = 0; round < 2; ++round) {
        tbb::parallel_for(0, 64, [](int) { std::this_thread::sleep_for(std::chrono::milliseconds(2)); });
        ASSERT_GT(threadsOf(parent), 1u) << "round " << round << ": no worker started";
        const std::string threads = runInChild([&] { return std::to_string(threadsOf(parent)); }, {256 * kMiB, 60});
        EXPECT_EQ(threads, "1") << "round " << round;
    }
}

// An empty list reads back as empty (an empty vector's data() may be null: UBSan reported the
// memcpy into it when the tet cache job of a farm run handed back a mesh with no warnings).
TEST(ByteMessage, EmptyItemsAndStringsRoundTrip) {
    ByteWriter out;
    out.add(std::vector<double>());
    out.add(std::string());
    out.addStrings({});
    out.add(std::vector<double>{1.5, -2});
    ByteReader in(out.bytes(), "the test");
    EXPECT_TRUE(in.items<double>().empty());
    EXPECT_EQ(in.string(), "");
    EXPECT_TRUE(in.strings().empty());
    EXPECT_EQ(in.items<double>(), (std::vector<double>{1.5, -2}));
    EXPECT_THROW(in.number(), std::runtime_error);
}

}  // namespace
}  // namespace tetglow
