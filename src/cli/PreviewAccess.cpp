#include "cli/PreviewAccess.h"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

namespace tetglow::cli {
namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool isAddress(const std::string& name) {
    unsigned char bytes[16];
    if (name.size() > 2 && name.front() == '[' && name.back() == ']')
        return inet_pton(AF_INET6, name.substr(1, name.size() - 2).c_str(), bytes) == 1;
    return inet_pton(AF_INET, name.c_str(), bytes) == 1;
}

// A Host header ("name:port", "[v6]:port") that names this server. An IP address cannot be
// rebound to another machine, so any is accepted; of names, only "localhost" and the one the
// server was started with.
bool namesThisServer(const std::string& hostHeader, const std::string& host, int port) {
    const size_t colon = hostHeader.rfind(':');
    const bool hasPort = colon != std::string::npos && hostHeader.find(']', colon) == std::string::npos;
    const std::string name = lower(hasPort ? hostHeader.substr(0, colon) : hostHeader);
    if (hasPort ? hostHeader.substr(colon + 1) != std::to_string(port) : port != 80) return false;
    const std::string bound = lower(host.find(':') != std::string::npos ? "[" + host + "]" : host);
    return name == "localhost" || name == bound || isAddress(name);
}

// The request comes from the page this server serves, or from no browser at all.
bool fromOwnPage(const httplib::Request& req, const std::string& ownOrigin) {
    if (req.has_header("Origin")) return lower(req.get_header_value("Origin")) == ownOrigin;
    if (req.has_header("Sec-Fetch-Site")) return req.get_header_value("Sec-Fetch-Site") == "same-origin";
    if (req.has_header("Referer")) return lower(req.get_header_value("Referer")).rfind(ownOrigin + "/", 0) == 0;
    return true;
}

}  // namespace

Refusal accessRefusal(const httplib::Request& req, const std::string& host, int port) {
    const std::string hostHeader = req.get_header_value("Host");
    if (!namesThisServer(hostHeader, host, port))
        return {403, "refused: Host \"" + hostHeader + "\" is not this preview's address (" + host + ":" +
                         std::to_string(port) + ")"};
    if (req.method == "GET" || req.method == "HEAD") return {};
    const std::string ownOrigin = "http://" + lower(hostHeader);
    if (!fromOwnPage(req, ownOrigin)) {
        const std::string from =
            req.has_header("Origin") ? req.get_header_value("Origin") : req.get_header_value("Referer");
        return {403, "refused: a " + req.method + " from another page (" + (from.empty() ? "cross-site" : from) +
                         "); only the preview's own page at " + ownOrigin + "/ may change it"};
    }
    const std::string type = req.get_header_value("Content-Type");
    if (lower(type.substr(0, type.find(';'))) != "application/json")
        return {415, "refused: a " + req.method + " body must be declared \"Content-Type: application/json\", not \"" +
                         type + "\""};
    return {};
}

}  // namespace tetglow::cli
