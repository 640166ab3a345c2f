// `swarmcheck serve` against other web pages and hostile clients (issue 38), through the binary
// and raw sockets: who may ask (Host, Origin, Content-Type), how long and how much a client may
// send, what runs and layouts a client may start, what every response carries, and that SIGTERM
// ends the server whatever the clients do. Each case failed before the guard was built.
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/util/serve_process.hpp"
#include "views/request_policy.hpp"

namespace {

using namespace swarmcheck::testing;
using swarmcheck::views::check_request_head;
using swarmcheck::views::RequestHead;
using swarmcheck::views::ServerIdentity;

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string default_scenario() { return read_file(kSource + "/scenarios/default.json"); }

const std::vector<std::string> kJson{"Content-Type: application/json"};

// ---- the policy itself (views/request_policy.hpp), on request heads ----

RequestHead head(const std::string& method, const std::string& path, std::vector<std::pair<std::string, std::string>> headers) {
  return RequestHead{method, path, std::move(headers), "127.0.0.1"};
}

TEST(RequestPolicy, HostMustNameThisServerWithItsPort) {
  const ServerIdentity me{"127.0.0.1", 8080, {"lab-pc"}};
  for (const std::string ok : {"127.0.0.1:8080", "localhost:8080", "LOCALHOST:8080", "app.localhost:8080", "[::1]:8080",
                               "127.3.2.1:8080", "lab-pc:8080"})
    EXPECT_FALSE(check_request_head(me, head("GET", "/", {{"Host", ok}}))) << ok;
  for (const std::string bad : {"evil.example:8080", "127.0.0.1:8081", "127.0.0.1", "localhost", "evil.example",
                                "localhost.evil.example:8080", "127.0.0.1.evil.example:8080", "128.0.0.1:8080",
                                "0.0.0.0:8080", "user@127.0.0.1:8080", "", "127.0.0.1:8080:1"}) {
    const auto r = check_request_head(me, head("GET", "/", {{"Host", bad}}));
    ASSERT_TRUE(r) << bad;
    EXPECT_EQ(r->status, 403) << bad;
  }
  EXPECT_EQ(check_request_head(me, head("GET", "/", {}))->status, 400);
  EXPECT_EQ(check_request_head(me, head("GET", "/", {{"Host", "localhost:8080"}, {"host", "evil.example:8080"}}))->status, 400);
  // Bound to every address, the one the client connected to is a name of the server too.
  const ServerIdentity any{"0.0.0.0", 9000, {}};
  RequestHead lan = head("GET", "/", {{"Host", "192.168.1.20:9000"}});
  lan.local_address = "192.168.1.20";
  EXPECT_FALSE(check_request_head(any, lan));
  lan.local_address = "192.168.1.21";
  EXPECT_TRUE(check_request_head(any, lan));
}

TEST(RequestPolicy, APostFromAPageOfAnotherOriginIsRefusedAndOneFromItsOwnIsNot) {
  const ServerIdentity me{"127.0.0.1", 8080, {}};
  const auto post = [&](std::vector<std::pair<std::string, std::string>> extra) {
    std::vector<std::pair<std::string, std::string>> h{{"Host", "127.0.0.1:8080"}, {"Content-Type", "application/json"}};
    h.insert(h.end(), extra.begin(), extra.end());
    return check_request_head(me, head("POST", "/api/runs", h));
  };
  EXPECT_FALSE(post({{"Origin", "http://127.0.0.1:8080"}, {"Sec-Fetch-Site", "same-origin"}}));
  EXPECT_FALSE(post({}));   // curl: no Origin, no Sec-Fetch-Site
  for (const std::string o : {"http://evil.example", "http://127.0.0.1:9999", "http://localhost:8080", "https://127.0.0.1:8080", "null"})
    EXPECT_EQ(post({{"Origin", o}}).value_or(swarmcheck::views::Refusal{0, ""}).status, 403) << o;
  for (const std::string s : {"cross-site", "same-site"}) EXPECT_EQ(post({{"Sec-Fetch-Site", s}})->status, 403) << s;
  // A page's navigation from another site still opens the page; its subresource loads do not.
  const auto get = [&](const std::string& site, const std::string& mode) {
    return check_request_head(me, head("GET", "/", {{"Host", "127.0.0.1:8080"}, {"Sec-Fetch-Site", site}, {"Sec-Fetch-Mode", mode}}));
  };
  EXPECT_FALSE(get("cross-site", "navigate"));
  EXPECT_FALSE(get("same-origin", "cors"));
  EXPECT_EQ(get("cross-site", "no-cors")->status, 403);
  EXPECT_EQ(get("same-site", "cors")->status, 403);
}

TEST(RequestPolicy, AnApiBodyMustBeDeclaredJson) {
  const ServerIdentity me{"127.0.0.1", 8080, {}};
  const auto post = [&](const std::string& path, std::vector<std::pair<std::string, std::string>> h) {
    h.emplace_back("Host", "127.0.0.1:8080");
    return check_request_head(me, head("POST", path, h));
  };
  EXPECT_FALSE(post("/api/runs", {{"Content-Type", "application/json"}}));
  EXPECT_FALSE(post("/api/view", {{"Content-Type", "Application/JSON; charset=utf-8"}}));
  for (const std::string t : {"text/plain", "text/plain;charset=UTF-8", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x", "application/jsonx"})
    EXPECT_EQ(post("/api/validate", {{"Content-Type", t}})->status, 415) << t;
  EXPECT_EQ(post("/api/runs", {})->status, 415);
}

// ---- the binary ----

// Finding 1's reproduction: a plain text/plain POST from another site (no preflight) started a
// run; with the Host of a DNS-rebinding page it could also read the answer.
TEST(ServeGuard, TheCrossSitePlainTextPostOfTheIssueIsRefusedWith403AndStartsNoRun) {
  ServeProcess s(kBin, {"--runs-max", "1", "--runs-per-client", "1"});
  ASSERT_GT(s.port(), 0);
  std::string attack = "POST /api/runs HTTP/1.1\r\nHost: evil.example\r\nOrigin: http://evil.example\r\nContent-Type: text/plain\r\n";
  attack += "Content-Length: " + std::to_string(default_scenario().size()) + "\r\n\r\n" + default_scenario();
  const HttpReply r = http_raw(s.port(), attack);
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_NE(r.body.find("is not this server"), std::string::npos) << r.body;
  // With this server's Host but another origin: still refused, for its Origin.
  const HttpReply o = http(s.port(), "POST", "/api/runs", {"Origin: http://evil.example", "Content-Type: text/plain"}, default_scenario());
  EXPECT_EQ(o.status, 403) << o.body;
  EXPECT_NE(o.body.find("a page of another origin (http://evil.example) may not POST /api/runs"), std::string::npos) << o.body;
  // No run was started: the one slot is still free for the server's own page.
  const HttpReply mine = http(s.port(), "POST", "/api/runs", {"Origin: http://127.0.0.1:" + std::to_string(s.port()), kJson[0]},
                              default_scenario());
  EXPECT_EQ(mine.status, 201) << mine.body;
}

TEST(ServeGuard, AHostThatIsNotThisServerIsRefusedOnEveryRouteSoARebindingPageReadsNothing) {
  ServeProcess s(kBin, {});
  ASSERT_GT(s.port(), 0);
  for (const std::string path : {"/", "/editor", "/api/schema", "/no/such/page"}) {
    const HttpReply r = http_raw(s.port(), "GET " + path + " HTTP/1.1\r\nHost: rebind.evil.example:" + std::to_string(s.port()) + "\r\n\r\n");
    EXPECT_EQ(r.status, 403) << path;
    EXPECT_EQ(r.body.find("swarmcheck-data"), std::string::npos) << path;
  }
  EXPECT_EQ(http(s.port(), "GET", "/").status, 200);
  const HttpReply named = http_raw(s.port(), "GET / HTTP/1.1\r\nHost: localhost:" + std::to_string(s.port()) + "\r\n\r\n");
  EXPECT_EQ(named.status, 200);
}

TEST(ServeGuard, ApiBodiesThatAreNotDeclaredJsonAreRefusedWith415BeforeTheyAreRead) {
  ServeProcess s(kBin, {});
  ASSERT_GT(s.port(), 0);
  for (const std::string path : {"/api/runs", "/api/validate", "/api/view"}) {
    const HttpReply r = http(s.port(), "POST", path, {"Content-Type: text/plain"}, default_scenario());
    EXPECT_EQ(r.status, 415) << path << ": " << r.body;
    EXPECT_NE(r.body.find("expected Content-Type: application/json"), std::string::npos) << r.body;
  }
  EXPECT_EQ(http(s.port(), "POST", "/api/validate", kJson, default_scenario()).status, 200);
}

TEST(ServeGuard, RunsAreCappedPerClientAsWellAsInAll) {
  ServeProcess s(kBin, {"--runs-max", "8", "--runs-per-client", "3"});
  ASSERT_GT(s.port(), 0);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(http(s.port(), "POST", "/api/runs", kJson, default_scenario()).status, 201) << k;
  const HttpReply fourth = http(s.port(), "POST", "/api/runs", kJson, default_scenario());
  EXPECT_EQ(fourth.status, 429);
  EXPECT_NE(fourth.body.find("runs of this client (127.0.0.1) are going on already (the limit for one client)"), std::string::npos)
      << fourth.body;
}

// A client that sends a header line every second: before, twelve of them held every worker of
// the server (every other client waited), and SIGTERM was ignored while they were connected.
// The request timeout is made long here, so the slow clients are all still connected when the
// other client is answered and when the server is stopped.
TEST(ServeGuard, TwelveSlowClientsNeitherKeepOthersWaitingNorKeepSigtermFromEndingTheServer) {
  ServeProcess s(kBin, {"--request-timeout", "120"});
  ASSERT_GT(s.port(), 0);
  std::vector<int> slow;
  for (int k = 0; k < 12; ++k) {
    slow.push_back(connect_to(s.port()));
    ASSERT_GE(slow.back(), 0);
    send_text(slow.back(), "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) + "\r\n");
  }
  std::atomic<bool> dribbling{true};
  std::thread dribble([&] {
    for (int line = 0; dribbling; ++line) {
      for (const int c : slow) send_text(c, "X-Slow-" + std::to_string(line) + ": 1\r\n");
      for (int t = 0; t < 10 && dribbling; ++t) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  for (int k = 0; k < 3; ++k) {
    const HttpReply r = http(s.port(), "GET", "/api/schema");
    EXPECT_EQ(r.status, 200) << "request " << k << " while twelve slow clients are connected";
  }
  for (const int c : slow) EXPECT_FALSE(answered_or_closed(c)) << "a slow client was answered or dropped before the others were served";
  const auto status = s.stop(SIGTERM, std::chrono::seconds(30));
  dribbling = false;
  dribble.join();
  for (const int c : slow) ::close(c);
  ASSERT_TRUE(status) << "serve is still running 30 s after SIGTERM, with twelve slow clients connected";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << *status;
}

TEST(ServeGuard, ARequestHeadThatDoesNotArriveInTimeIsAnswered408AndDropped) {
  ServeProcess s(kBin, {"--request-timeout", "0.5"});
  ASSERT_GT(s.port(), 0);
  const int c = connect_to(s.port());
  send_text(c, "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) + "\r\n");   // and no blank line
  const HttpReply r = parse_reply(read_all(c, std::chrono::seconds(30)));
  ::close(c);
  EXPECT_EQ(r.status, 408);
  EXPECT_NE(r.body.find("the request head did not arrive within"), std::string::npos) << r.body;
  // A body announced and not sent.
  const int d = connect_to(s.port());
  send_text(d, "POST /api/validate HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) +
                   "\r\nContent-Type: application/json\r\nContent-Length: 100\r\n\r\n{");
  const HttpReply b = parse_reply(read_all(d, std::chrono::seconds(30)));
  ::close(d);
  EXPECT_EQ(b.status, 408);
  EXPECT_NE(b.body.find("the request body did not arrive in time"), std::string::npos) << b.body;
}

// Before: a request of 4 000 000 headers was read whole and the server kept 549 MB.
TEST(ServeGuard, AHeadOfTooManyHeadersIsRefusedWith431AndTheServerDoesNotGrow) {
  ServeProcess s(kBin, {});
  ASSERT_GT(s.port(), 0);
  std::string many = "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) + "\r\n";
  for (int k = 0; k < 200; ++k) many += "X-H" + std::to_string(k) + ": v\r\n";
  const HttpReply r = http_raw(s.port(), many + "\r\n");
  EXPECT_EQ(r.status, 431);
  EXPECT_NE(r.body.find("the request head is larger than the server takes"), std::string::npos) << r.body;
  const HttpReply big = http_raw(s.port(), "GET /" + std::string(40000, 'a') + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) + "\r\n\r\n");
  EXPECT_TRUE(big.status == 431 || big.status == 414) << big.status;
  const long before = s.peak_rss_kib();
  // Four million header lines, sent as fast as the server takes them: it stops reading at its limit.
  const int c = connect_to(s.port());
  send_text(c, "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) + "\r\n");
  std::string block;
  for (int k = 0; k < 10000; ++k) block += "X-A: b\r\n";
  int sent = 0;
  while (sent < 400 && send_text(c, block)) ++sent;
  ::close(c);
  EXPECT_LT(sent, 400) << "the server read four million header lines";
  EXPECT_EQ(http(s.port(), "GET", "/api/schema").status, 200);
  EXPECT_LT(s.peak_rss_kib() - before, 64 * 1024) << "KiB more at its peak after the flood";
}

TEST(ServeGuard, EveryResponseCarriesNosniffAndFrameAncestorsNoneThe404Included) {
  ServeProcess s(kBin, {"--runs-max", "1", "--runs-per-client", "1"});
  ASSERT_GT(s.port(), 0);
  const std::string p = std::to_string(s.port());
  std::vector<std::pair<std::string, HttpReply>> replies{
      {"page", http(s.port(), "GET", "/")},
      {"schema", http(s.port(), "GET", "/api/schema")},
      {"404", http(s.port(), "GET", "/no/such/page")},
      {"405", http(s.port(), "PUT", "/api/validate")},
      {"400", http(s.port(), "POST", "/api/validate", kJson, "{")},
      {"403", http_raw(s.port(), "GET / HTTP/1.1\r\nHost: evil.example\r\n\r\n")},
      {"415", http(s.port(), "POST", "/api/validate", {"Content-Type: text/plain"}, "{}")},
      {"413", http(s.port(), "POST", "/api/validate", kJson, std::string(2 << 20, ' '))},
      {"431", http_raw(s.port(), "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + p + "\r\n" + std::string(40000, 'x') + "\r\n\r\n")},
      {"201", http(s.port(), "POST", "/api/runs", kJson, default_scenario())},
      {"429", http(s.port(), "POST", "/api/runs", kJson, default_scenario())}};
  for (const auto& [what, r] : replies) {
    EXPECT_NE(r.status, 0) << what;
    EXPECT_EQ(r.headers.count("x-content-type-options") ? r.headers.at("x-content-type-options") : "", "nosniff") << what;
    EXPECT_EQ(r.headers.count("content-security-policy") ? r.headers.at("content-security-policy") : "", "frame-ancestors 'none'") << what;
    EXPECT_EQ(r.headers.count("x-frame-options") ? r.headers.at("x-frame-options") : "", "DENY") << what;
  }
}

// An automaton just under the layout cap that keeps dot busy for minutes: 63 states, each with
// 63 transitions.
std::string dense_fsm() {
  std::string t = "63\n";
  for (int i = 0; i < 63; ++i) {
    t += "\ns" + std::to_string(i) + "\t0\t63\n";
    for (int j = 0; j < 63; ++j) t += "e" + std::to_string(j) + "\ts" + std::to_string((i + j) % 63) + "\tc\to\n";
  }
  return t;
}

// Before: twelve POST /api/view of a 50 KB automaton started twelve dot processes at once, and
// the server answered nothing else meanwhile. Now at most two views are built at once (429 past
// them), and SIGTERM kills the dots and ends the server.
TEST(ServeGuard, AtMostTwoViewsAreBuiltAtOnceAndSigtermKillsTheirDots) {
  ServeProcess s(kBin, {});
  ASSERT_GT(s.port(), 0);
  std::string body = "{\"name\": \"dense.fsm\", \"text\": \"";
  for (const char c : dense_fsm()) body += c == '\n' ? std::string("\\n") : c == '\t' ? std::string("\\t") : std::string(1, c);
  body += "\"}";
  const std::string request = "POST /api/view HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(s.port()) +
                              "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  std::vector<int> posts;
  for (int k = 0; k < 6; ++k) {
    posts.push_back(connect_to(s.port()));
    send_text(posts.back(), request);
  }
  // Four are refused at once; two lay out.
  int refused = 0;
  const auto deadline = Clock::now() + std::chrono::seconds(20);
  std::vector<bool> answered(posts.size(), false);
  while (refused < 4 && Clock::now() < deadline) {
    for (std::size_t k = 0; k < posts.size(); ++k) {
      if (answered[k] || !answered_or_closed(posts[k])) continue;
      answered[k] = true;
      const HttpReply r = parse_reply(read_all(posts[k], std::chrono::seconds(1)));
      EXPECT_EQ(r.status, 429) << r.body;
      EXPECT_NE(r.body.find("2 views are being built (the limit"), std::string::npos) << r.body;
      refused += r.status == 429;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(refused, 4);
  std::size_t dots = 0;
  for (int t = 0; t < 100 && dots < 2; ++t, std::this_thread::sleep_for(std::chrono::milliseconds(50))) dots = s.children_named("dot").size();
  EXPECT_LE(s.children_named("dot").size(), 2u);
  EXPECT_EQ(http(s.port(), "GET", "/api/schema").status, 200) << "the server answers while two layouts run";
  const std::vector<pid_t> running = s.children_named("dot");
  const auto status = s.stop(SIGTERM, std::chrono::seconds(30));
  for (const int c : posts) ::close(c);
  ASSERT_TRUE(status) << "serve is still running 30 s after SIGTERM, with two layouts going";
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0) << *status;
  for (const pid_t d : running) EXPECT_NE(::kill(d, 0), 0) << "dot " << d << " outlived the server";
}

}  // namespace
