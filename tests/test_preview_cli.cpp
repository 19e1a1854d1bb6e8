// tetglow preview's own failures, before any page is served: each a one-line error and a
// non-zero exit, never a server left running. (The page itself: tests/preview_browser.py.)
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "TestMeshes.h"

namespace tetglow {
namespace {

const std::string kScene = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

// The shared one-line check, and no server left serving.
void expectRefused(const test::CommandResult& r, int code, const std::string& expected) {
    test::expectOneLineError(r, code, expected);
    EXPECT_EQ(r.out.find("preview: http"), std::string::npos) << "served anyway: " << r.out;
}

TEST(PreviewCommand, PortInUseIsAnError) {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    ASSERT_EQ(listen(s, 1), 0);
    socklen_t size = sizeof address;
    getsockname(s, reinterpret_cast<sockaddr*>(&address), &size);
    const std::string port = std::to_string(ntohs(address.sin_port));
    const auto r = test::runTetglow("preview " + kScene + " --port " + port);
    close(s);
    expectRefused(r, 1, "cannot listen on 127.0.0.1:" + port);
}

TEST(PreviewCommand, BadArguments) {
    expectRefused(test::runTetglow("preview " + kScene + " --host no.such.host.invalid --port 0"), 1, "cannot listen on no.such.host.invalid:0");
    expectRefused(test::runTetglow("preview " + kScene + " --port 70000"), 2, "--port");
    expectRefused(test::runTetglow("preview /nonexistent.json"), 2, "/nonexistent.json");
}

}  // namespace
}  // namespace tetglow
