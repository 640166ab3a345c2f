#pragma once
// Who may talk to `swarmcheck serve`: decided on a request's head, before its body is read.
//
//  - Host must name this server: the address it is bound to, the address the client connected
//    to, a loopback name (localhost, *.localhost, 127.x.y.z, [::1]) or a name given with
//    --allow-host, each with the server's port. A DNS-rebinding page (evil.example resolving to
//    127.0.0.1) sends Host: evil.example and is refused, so it can read nothing.
//  - A request that changes state (every POST, any method but GET and HEAD) must come from the
//    server's own pages: an Origin other than http://<its Host> is refused, and so is a browser's
//    Sec-Fetch-Site other than same-origin or none. A request with neither header (curl, a
//    script) is a program on a machine that may reach the server, not a web page.
//  - A GET that another site's page makes without navigating (an <img>, <script> or fetch in
//    no-cors mode: Sec-Fetch-Site cross-site or same-site) is refused too.
//  - API bodies are JSON: a POST to /api/ must say Content-Type: application/json, which a page
//    of another origin cannot send without a CORS preflight, and the server answers none.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace swarmcheck::views {

struct RequestHead {
  std::string method;
  std::string path;
  std::vector<std::pair<std::string, std::string>> headers;   // as received; names in any case
  std::string local_address;   // the address the client connected to (from the socket)

  // The values of every header named `name` (case-insensitive), in order.
  std::vector<std::string> values(std::string_view name) const;
};

struct ServerIdentity {
  std::string bind;                        // --bind (127.0.0.1, 0.0.0.0, ::1, a name)
  int port = 0;                            // the port listened on
  std::vector<std::string> allowed_hosts;  // --allow-host names (without port)
};

struct Refusal {
  int status;            // 400, 403 or 415
  std::string message;   // what was wrong and what is accepted (no "swarmcheck: error: ")
};

// nullopt: the request may proceed.
std::optional<Refusal> check_request_head(const ServerIdentity& me, const RequestHead& head);

// "host" of a Host header value "host:port" / "[v6]:port" / "host", lowercased, and its port
// (nullopt when absent); nullopt when the value is not of that shape.
struct HostPort {
  std::string host;
  std::optional<int> port;
};
std::optional<HostPort> parse_host_header(std::string_view value);

bool is_loopback_name(std::string_view host);   // localhost, *.localhost, 127.0.0.0/8, ::1, ...

}  // namespace swarmcheck::views
