#include "PreviewProcess.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "TestMeshes.h"

namespace tetglow::test {

PreviewProcess::PreviewProcess(const std::string& args, const std::string& errPath) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe");
    // TETGLOW_TEST_BINARY: another build, to see a test fail on the code before its fix.
    const char* binary = std::getenv("TETGLOW_TEST_BINARY") ? std::getenv("TETGLOW_TEST_BINARY") : TETGLOW_BINARY;
    const std::string cache = processScratchDir() + "/preview-cache";
    const std::string command =
        "TETGLOW_CACHE_DIR=" + cache + " exec " + binary + " preview " + args + " 2>" + errPath + " </dev/null";
    pid_ = fork();
    if (pid_ == 0) {
        dup2(out[1], 1);
        close(out[0]);
        close(out[1]);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    close(out[1]);
    // "preview: http://127.0.0.1:PORT/ (Ctrl-C stops)"
    std::string line;
    pollfd p{out[0], POLLIN, 0};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(120 * testTimeScale());
    char c = 0;
    while (line.find('\n') == std::string::npos && std::chrono::steady_clock::now() < deadline) {
        if (poll(&p, 1, 100) > 0 && read(out[0], &c, 1) == 1)
            line += c;
        else if (p.revents & POLLHUP)
            break;
    }
    close(out[0]);
    const size_t colon = line.find(':', line.find("//"));
    if (line.rfind("preview: http://", 0) != 0 || colon == std::string::npos) {
        stop();
        throw std::runtime_error("tetglow preview " + args + " printed no URL: '" + line + "'");
    }
    port_ = std::stoi(line.substr(colon + 1));
}

PreviewProcess::~PreviewProcess() { stop(); }

int PreviewProcess::stop(double limit) {
    if (pid_ <= 0) return -1;
    kill(pid_, SIGTERM);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit);
    pid_t ended = 0;
    while ((ended = waitpid(pid_, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const bool hung = ended == 0;
    if (hung) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
    }
    pid_ = -1;
    if (hung) return -2;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

long PreviewProcess::peakMemoryKiB() const {
    std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    return -1;
}

int connectTo(int port) {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) return s;
    close(s);
    return -1;
}

HttpReply rawHttp(int port, const std::string& request, double timeoutSeconds) {
    HttpReply reply;
    const int s = connectTo(port);
    if (s < 0) return reply;
    if (send(s, request.data(), request.size(), MSG_NOSIGNAL) != ssize_t(request.size())) {
        close(s);
        return reply;
    }
    std::string text;
    char buffer[65536];
    pollfd p{s, POLLIN, 0};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (poll(&p, 1, 100) <= 0) continue;
        const ssize_t n = recv(s, buffer, sizeof buffer, 0);
        if (n <= 0) break;
        text.append(buffer, size_t(n));
    }
    close(s);
    const size_t end = text.find("\r\n\r\n");
    if (text.rfind("HTTP/1.", 0) != 0 || end == std::string::npos) return reply;
    reply.status = std::stoi(text.substr(9, 3));
    reply.body = text.substr(end + 4);
    return reply;
}

std::string httpRequest(const std::string& method, const std::string& path, int port,
                        const std::map<std::string, std::string>& headers, const std::string& body) {
    std::string request = method + " " + path + " HTTP/1.1\r\n";
    if (!headers.count("Host")) request += "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
    for (const auto& [name, value] : headers) request += name + ": " + value + "\r\n";
    if (!body.empty() || method == "POST") request += "Content-Length: " + std::to_string(body.size()) + "\r\n";
    return request + "Connection: close\r\n\r\n" + body;
}

}  // namespace tetglow::test
