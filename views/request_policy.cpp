#include "views/request_policy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace swarmcheck::views {
namespace policy {   // named: views/ is a unity build

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool is_ipv4_loopback(std::string_view h) {
  int parts = 0;
  int first = -1;
  while (true) {
    std::size_t k = 0;
    while (k < h.size() && k < 4 && std::isdigit(static_cast<unsigned char>(h[k]))) ++k;
    if (k == 0 || k > 3) return false;
    int v = 0;
    std::from_chars(h.data(), h.data() + k, v);
    if (v > 255) return false;
    if (first < 0) first = v;
    ++parts;
    h.remove_prefix(k);
    if (h.empty()) break;
    if (h.front() != '.') return false;
    h.remove_prefix(1);
  }
  return parts == 4 && first == 127;
}

// The address a socket reports, as a Host header would carry it (an IPv4 client of a dual-stack
// socket shows as ::ffff:a.b.c.d).
std::string host_form(std::string_view address) {
  std::string a = lower(address);
  if (a.starts_with("::ffff:") && a.find('.') != std::string::npos) a = a.substr(7);
  return a;
}

bool names_this_server(const ServerIdentity& me, const RequestHead& head, const HostPort& h) {
  if (h.port ? *h.port != me.port : me.port != 80) return false;
  if (is_loopback_name(h.host)) return true;
  const std::string bind = host_form(me.bind);
  if (h.host == bind && bind != "0.0.0.0" && bind != "::") return true;
  if (!head.local_address.empty() && h.host == host_form(head.local_address)) return true;
  return std::any_of(me.allowed_hosts.begin(), me.allowed_hosts.end(), [&](const std::string& a) { return lower(a) == h.host; });
}

std::string accepted_hosts(const ServerIdentity& me) {
  const std::string bind = host_form(me.bind);
  std::string s = fmt::format("127.0.0.1:{}, localhost:{} (and other loopback names)", me.port, me.port);
  if (!is_loopback_name(bind) && bind != "0.0.0.0" && bind != "::") s += fmt::format(", {}:{}", bind, me.port);
  else if (bind == "0.0.0.0" || bind == "::") s += fmt::format(", this machine's addresses with port {}", me.port);
  for (const auto& a : me.allowed_hosts) s += fmt::format(", {}:{}", a, me.port);
  return s;
}

bool is_api_post(const RequestHead& head) { return head.method == "POST" && head.path.starts_with("/api/"); }

}  // namespace policy

std::vector<std::string> RequestHead::values(std::string_view name) const {
  std::vector<std::string> out;
  const std::string wanted = policy::lower(name);
  for (const auto& [k, v] : headers)
    if (policy::lower(k) == wanted) out.emplace_back(policy::trimmed(v));
  return out;
}

bool is_loopback_name(std::string_view host) {
  const std::string h = policy::lower(host);
  return h == "localhost" || h.ends_with(".localhost") || h == "localhost.localdomain" || h == "ip6-localhost" ||
         h == "ip6-loopback" || h == "::1" || h == "0:0:0:0:0:0:0:1" || policy::is_ipv4_loopback(h);
}

std::optional<HostPort> parse_host_header(std::string_view value) {
  value = policy::trimmed(value);
  HostPort out;
  std::string_view rest;
  if (value.starts_with("[")) {   // [v6]:port
    const std::size_t close = value.find(']');
    if (close == std::string_view::npos || close == 1) return std::nullopt;
    const std::string_view v6 = value.substr(1, close - 1);
    if (!std::all_of(v6.begin(), v6.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) || c == ':' || c == '.'; }))
      return std::nullopt;
    out.host = policy::lower(v6);
    rest = value.substr(close + 1);
  } else {
    const std::size_t colon = value.find(':');
    const std::string_view name = value.substr(0, colon);
    if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_'; }))
      return std::nullopt;
    out.host = policy::lower(name);
    rest = colon == std::string_view::npos ? std::string_view() : value.substr(colon);
  }
  if (rest.empty()) return out;
  if (rest.front() != ':' || rest.size() < 2 || rest.size() > 6) return std::nullopt;
  rest.remove_prefix(1);
  int port = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), port);
  if (ec != std::errc() || end != rest.data() + rest.size() || port < 1 || port > 65535) return std::nullopt;
  out.port = port;
  return out;
}

std::optional<Refusal> check_request_head(const ServerIdentity& me, const RequestHead& head) {
  const std::vector<std::string> hosts = head.values("Host");
  if (hosts.size() != 1) return Refusal{400, fmt::format("a request must name this server in exactly one Host header (got {})", hosts.size())};
  const std::optional<HostPort> host = parse_host_header(hosts[0]);
  if (!host || !policy::names_this_server(me, head, *host))
    return Refusal{403, fmt::format("Host \"{}\" is not this server: it answers to {} (a page that reached it under another "
                                    "name is refused; --allow-host NAME adds a name)",
                                    hosts[0], policy::accepted_hosts(me))};
  const std::vector<std::string> origins = head.values("Origin");
  const std::vector<std::string> sites = head.values("Sec-Fetch-Site");
  if (origins.size() > 1 || sites.size() > 1) return Refusal{400, "at most one Origin and one Sec-Fetch-Site header"};
  const std::string site = sites.empty() ? "" : policy::lower(sites[0]);
  const bool changes_state = head.method != "GET" && head.method != "HEAD";
  if (changes_state) {
    if (!origins.empty()) {
      const std::string origin = policy::lower(origins[0]);
      std::optional<HostPort> o;
      if (origin.starts_with("http://")) o = parse_host_header(std::string_view(origin).substr(7));
      const bool same = o && o->host == host->host && o->port.value_or(80) == host->port.value_or(80);
      if (!same)
        return Refusal{403, fmt::format("a page of another origin ({}) may not {} {} here: requests that change "
                                        "anything must come from this server's own pages (http://{})",
                                        origins[0], head.method, head.path, hosts[0])};
    }
    if (!site.empty() && site != "same-origin" && site != "none")
      return Refusal{403, fmt::format("a {} page may not {} {} here (Sec-Fetch-Site: {}): requests that change anything "
                                      "must come from this server's own pages", site, head.method, head.path, sites[0])};
  } else if (site == "cross-site" || site == "same-site") {
    const std::vector<std::string> modes = head.values("Sec-Fetch-Mode");
    if (modes.empty() || policy::lower(modes[0]) != "navigate")
      return Refusal{403, fmt::format("a page of another site may not load {} from this server (Sec-Fetch-Site: {}); "
                                      "open http://{}{} itself", head.path, sites[0], hosts[0], head.path)};
  }
  if (policy::is_api_post(head)) {
    const std::vector<std::string> types = head.values("Content-Type");
    const std::string type = types.size() == 1 ? policy::lower(policy::trimmed(std::string_view(types[0]).substr(0, types[0].find(';')))) : "";
    if (type != "application/json")
      return Refusal{415, fmt::format("request body: expected Content-Type: application/json, got {} (curl: -H 'Content-Type: "
                                      "application/json'; /api/view takes {{\"name\": FILE NAME, \"text\": THE FILE}})",
                                      types.empty() ? std::string("none") : types.size() > 1 ? std::string("several") : types[0])};
  }
  return std::nullopt;
}

}  // namespace swarmcheck::views
