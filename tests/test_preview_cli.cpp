// tetglow preview's own failures, before any page is served: each a one-line error and a
// non-zero exit, never a server left running. (The page itself: tests/preview_browser.py.)
#include <gtest/gtest.h>

#include "PreviewProcess.h"
#include "TestMeshes.h"

namespace tetglow {
namespace {

const std::string kScene = std::string(TETGLOW_SOURCE_DIR) + "/scenes/sphere.json";

// The shared one-line check, and no server left serving.
void expectRefused(const test::CommandResult& r, int code, const std::string& expected) {
    test::expectOneLineError(r, code, expected);
    EXPECT_EQ(r.out.find("preview: http"), std::string::npos) << "served anyway: " << r.out;
}

TEST(PreviewCommand, ASecondPreviewOnTheSamePortIsRefused) {
    // Both would print their URL and split the requests between them, each page mixing two renders.
    test::PreviewProcess first(kScene + " --port 0 --threads 1");
    const std::string port = std::to_string(first.port());
    expectRefused(test::runTetglow("preview " + kScene + " --port " + port, 30), 1,
                  "cannot listen on 127.0.0.1:" + port);
    EXPECT_EQ(test::rawHttp(first.port(), test::httpRequest("GET", "/", first.port())).status, 200)
        << "the first preview stopped serving";
}

TEST(PreviewCommand, BadArguments) {
    expectRefused(test::runTetglow("preview " + kScene + " --host no.such.host.invalid --port 0"), 1,
                  "cannot listen on no.such.host.invalid:0");
    expectRefused(test::runTetglow("preview " + kScene + " --port 70000"), 2, "--port");
    expectRefused(test::runTetglow("preview /nonexistent.json"), 2, "/nonexistent.json");
}

}  // namespace
}  // namespace tetglow
