// A `tetglow preview` running in the background for a test, and raw HTTP to it: the bytes a
// browser (or an attacker) sends, every header written by the test, nothing tidied on the way.
#pragma once
#include <sys/types.h>

#include <map>
#include <string>

namespace tetglow::test {

class PreviewProcess {
public:
    // Starts `tetglow preview ARGS` (add "--port 0" for a free port) and waits for its URL; its
    // stderr goes to `errPath`.
    explicit PreviewProcess(const std::string& args, const std::string& errPath = "/dev/null");
    ~PreviewProcess();
    PreviewProcess(const PreviewProcess&) = delete;
    PreviewProcess& operator=(const PreviewProcess&) = delete;

    int port() const { return port_; }
    pid_t pid() const { return pid_; }
    long peakMemoryKiB() const;  // VmHWM: the most resident memory it has held
    // SIGTERM; the exit code, or -2 where it still runs after `limit` seconds (then SIGKILL).
    int stop(double limit = 60);

private:
    pid_t pid_ = -1;
    int port_ = 0;
};

struct HttpReply {
    int status = 0;  // 0: no reply (the connection failed or closed first)
    std::string body;
};

// A TCP connection to 127.0.0.1:port; -1 when refused.
int connectTo(int port);

// Sends `request` as it is and reads the reply until the server closes the connection.
HttpReply rawHttp(int port, const std::string& request, double timeoutSeconds = 20);

// "METHOD PATH HTTP/1.1", a Host of 127.0.0.1:PORT unless `headers` name another, the headers,
// a Content-Length when there is a body, and "Connection: close".
std::string httpRequest(const std::string& method, const std::string& path, int port,
                        const std::map<std::string, std::string>& headers = {}, const std::string& body = "");

}  // namespace tetglow::test
