#pragma once
// `swarmcheck serve` from a test: started on a free port, talked to over raw sockets (every byte
// of a request as the test writes it, so a test can send what no HTTP client would), stopped with
// a signal. kBin comes from the test target's SWARMCHECK_BIN.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace swarmcheck::testing {

using Clock = std::chrono::steady_clock;

class ServeProcess {
 public:
  // `swarmcheck serve --port 0 ARGS...`; waits for the line that names the port.
  ServeProcess(const std::string& bin, const std::vector<std::string>& args) {
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return;
    // Everything the child needs is made before fork: a fuzzer forks from several threads, and
    // the child of a threaded process may not allocate.
    std::vector<std::string> all{bin, "serve", "--port", "0"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
      // Dies with the test: a test that crashes must not leave a server holding ctest's pipe.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      ::dup2(out[1], STDOUT_FILENO);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(out[1]);
    std::string text;
    const auto deadline = Clock::now() + std::chrono::seconds(20);
    while (port_ == 0 && Clock::now() < deadline) {
      pollfd p{out[0], POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      char buf[256];
      const ssize_t n = ::read(out[0], buf, sizeof buf);
      if (n <= 0) break;
      text.append(buf, static_cast<std::size_t>(n));
      const std::size_t at = text.find("127.0.0.1:");
      if (at != std::string::npos && text.find('/', at) != std::string::npos) port_ = std::atoi(text.c_str() + at + 10);
    }
    stdout_ = out[0];
  }
  ~ServeProcess() {
    if (running()) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    if (stdout_ >= 0) ::close(stdout_);
  }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  bool running() {
    if (pid_ <= 0 || status_) return false;
    int s = 0;
    if (::waitpid(pid_, &s, WNOHANG) == pid_) status_ = s;
    return !status_;
  }
  // Sends `sig` and waits up to `bound` for the process to end: its wait status, or nullopt if
  // it is still running (a hang: the destructor kills it).
  std::optional<int> stop(int sig, std::chrono::milliseconds bound) {
    ::kill(pid_, sig);
    const auto deadline = Clock::now() + bound;
    while (running() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return status_;
  }
  // The server's peak resident memory so far (VmHWM), KiB.
  long peak_rss_kib() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
    return -1;
  }
  // The process ids of the server's children named `name` (dot, for the layouts).
  std::vector<pid_t> children_named(const std::string& name) const {
    std::vector<pid_t> out;
    std::ifstream list("/proc/" + std::to_string(pid_) + "/task/" + std::to_string(pid_) + "/children");
    for (pid_t c; list >> c;) {
      std::ifstream comm("/proc/" + std::to_string(c) + "/comm");
      std::string n;
      std::getline(comm, n);
      if (n == name) out.push_back(c);
    }
    return out;
  }

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  int stdout_ = -1;
  std::optional<int> status_;
};

// A TCP connection to 127.0.0.1:port (-1 when it cannot be made).
inline int connect_to(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(s);
    return -1;
  }
  return s;
}

inline bool send_text(int s, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::send(s, text.data() + done, text.size() - done, MSG_NOSIGNAL);
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Everything the server sends until it closes the connection (or `bound` passes).
inline std::string read_all(int s, std::chrono::milliseconds bound) {
  std::string text;
  const auto deadline = Clock::now() + bound;
  while (Clock::now() < deadline) {
    pollfd p{s, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    char buf[8192];
    const ssize_t n = ::recv(s, buf, sizeof buf, 0);
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  return text;
}

// Whether the server has sent something on the connection or closed it, without waiting.
inline bool answered_or_closed(int s) {
  pollfd p{s, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

struct HttpReply {
  int status = 0;                              // 0: no reply
  std::map<std::string, std::string> headers;  // names lowercased
  std::string body;
};

inline HttpReply parse_reply(const std::string& text) {
  HttpReply r;
  if (text.rfind("HTTP/1.1 ", 0) != 0) return r;
  r.status = std::atoi(text.c_str() + 9);
  const std::size_t end = text.find("\r\n\r\n");
  std::istringstream head(text.substr(0, end));
  std::string line;
  std::getline(head, line);
  while (std::getline(head, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    std::string value = line.substr(colon + 1);
    while (!value.empty() && value.front() == ' ') value.erase(0, 1);
    r.headers[name] = value;
  }
  if (end != std::string::npos) r.body = text.substr(end + 4);
  return r;
}

// One request as written (the caller writes every header, Host included), and its reply.
inline HttpReply http_raw(int port, const std::string& request, std::chrono::milliseconds bound = std::chrono::seconds(30)) {
  const int s = connect_to(port);
  if (s < 0) return {};
  send_text(s, request);
  const std::string text = read_all(s, bound);
  ::close(s);
  return parse_reply(text);
}

// A request with a Host of this server and Content-Length, plus `headers` (each "Name: value").
inline HttpReply http(int port, const std::string& method, const std::string& path, const std::vector<std::string>& headers = {},
                      const std::string& body = "", std::chrono::milliseconds bound = std::chrono::seconds(30)) {
  std::string r = method + " " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
  for (const auto& h : headers) r += h + "\r\n";
  if (method == "POST") r += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  return http_raw(port, r + "\r\n" + body, bound);
}

}  // namespace swarmcheck::testing
