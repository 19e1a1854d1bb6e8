// Who may use `tetglow preview`. A page from anywhere can make a browser send requests to
// 127.0.0.1, so the server, not the network, decides:
// - the Host must name this server (an IP address, "localhost" or the --host name, with its
//   port): a DNS-rebinding page, whose requests carry its own name, can read nothing;
// - a request that changes something (POST) must come from the preview's own page: its Origin
//   (or, without one, Sec-Fetch-Site or Referer) is the page's, and its body is declared
//   application/json, which no other page can send without a CORS preflight, and the server
//   answers none. A client that is no browser sends none of these headers and is let through.
#pragma once
#include <string>

#include <httplib.h>

namespace tetglow::cli {

struct Refusal {
    int status = 0;       // 0: allowed
    std::string message;  // one line, for the page and the log
};

// `host` and `port`: what the server is bound to.
Refusal accessRefusal(const httplib::Request& req, const std::string& host, int port);

}  // namespace tetglow::cli
