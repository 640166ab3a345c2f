#include "views/http_connection.hpp"

#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <arpa/inet.h>
#include <fmt/format.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <thread>

namespace swarmcheck::views {
namespace connection {   // named: views/ is a unity build

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kSlice{100};   // the longest wait between looks at the stop flag

int slice_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return static_cast<int>(std::clamp<std::chrono::milliseconds::rep>(left.count(), 0, kSlice.count()));
}

// Waits for `events` on `sock` for at most one slice; the revents (0 on timeout or EINTR).
short wait_for(int sock, short events, int ms) {
  pollfd p{sock, events, 0};
  const int r = ::poll(&p, 1, ms);
  return r > 0 ? p.revents : 0;
}

void address_of(int sock, bool peer, std::string& ip, int& port) {
  sockaddr_storage a{};
  socklen_t len = sizeof a;
  ip.clear();
  port = -1;
  if ((peer ? ::getpeername(sock, reinterpret_cast<sockaddr*>(&a), &len) : ::getsockname(sock, reinterpret_cast<sockaddr*>(&a), &len)) != 0) return;
  char text[INET6_ADDRSTRLEN] = {};
  if (a.ss_family == AF_INET) {
    const auto* v4 = reinterpret_cast<const sockaddr_in*>(&a);
    ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
    port = ntohs(v4->sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&a);
    ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
    port = ntohs(v6->sin6_port);
  }
  ip = text;
  if (ip.starts_with("::ffff:") && ip.find('.') != std::string::npos) ip = ip.substr(7);   // an IPv4 client
}

// Sends all of `text` unless the client stalls for `stall` or the server stops.
bool send_all(int sock, const char* data, std::size_t size, std::chrono::milliseconds stall, const std::atomic<bool>& stopping) {
  std::size_t done = 0;
  auto deadline = Clock::now() + stall;
  while (done < size) {
    if (stopping) return false;
    const ssize_t n = ::send(sock, data + done, size - done, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      deadline = Clock::now() + stall;
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return false;
    if (Clock::now() >= deadline) return false;
    wait_for(sock, POLLOUT, slice_ms(deadline));
  }
  return true;
}

// Content-Length as the head announces it (0 when absent or unreadable: the library refuses it).
std::size_t announced_length(const std::string& head) {
  std::size_t at = 0;
  while ((at = head.find('\n', at)) != std::string::npos) {
    ++at;
    constexpr std::string_view name = "content-length:";
    if (head.size() - at < name.size()) break;
    bool match = true;
    for (std::size_t k = 0; k < name.size() && match; ++k)
      match = std::tolower(static_cast<unsigned char>(head[at + k])) == name[k];
    if (!match) continue;
    std::size_t v = at + name.size();
    while (v < head.size() && head[v] == ' ') ++v;
    std::size_t n = 0;
    for (; v < head.size() && std::isdigit(static_cast<unsigned char>(head[v])) && n < (std::size_t{1} << 40); ++v)
      n = n * 10 + static_cast<std::size_t>(head[v] - '0');
    return n;
  }
  return 0;
}

class GuardedStream : public httplib::Stream {
 public:
  GuardedStream(int sock, const ConnectionLimits& limits, const std::atomic<bool>& stopping, Clock::time_point start)
      : sock_(sock), limits_(limits), stopping_(stopping), deadline_(start + limits.head_time_max) {}

  bool is_readable() const override { return begin_ < end_ || (wait_for(sock_, POLLIN, 0) & POLLIN) != 0; }

  // Room to write, and the client still there: a page that closed its stream shows as a socket
  // at end of input, which stops its run at once (the library would write on until an error).
  bool is_writable() const override {
    const auto deadline = Clock::now() + limits_.write_stall_max;
    while (!closed_ && !stopping_) {
      const short r = wait_for(sock_, POLLIN | POLLOUT, slice_ms(deadline));
      if (r & (POLLERR | POLLHUP | POLLNVAL)) return false;
      if (r & POLLIN) {
        char junk[4096];   // the request was read whole: anything more is dropped
        const ssize_t n = ::recv(sock_, junk, sizeof junk, MSG_DONTWAIT);
        if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return false;
      }
      if (r & POLLOUT) return true;
      if (Clock::now() >= deadline) return false;
    }
    return false;
  }

  ssize_t read(char* ptr, size_t size) override {
    if (closed_) return -1;
    if (begin_ == end_) {
      const ssize_t got = fill();
      if (got <= 0) return got;
    }
    std::size_t n = std::min(size, end_ - begin_);
    if (in_head_) {
      for (std::size_t k = 0; k < n; ++k) {
        const char c = buffer_[begin_ + k];
        head_ += c;
        if (c == '\n') ++lines_;
        if (head_.size() > limits_.head_bytes_max || lines_ > limits_.head_lines_max) {
          refuse(431, "Request Header Fields Too Large",
                 fmt::format("the request head is larger than the server takes ({} bytes and {} lines at most)",
                             limits_.head_bytes_max, limits_.head_lines_max));
          return -1;
        }
        if (head_.ends_with("\r\n\r\n")) {   // the head is over: the body has its own deadline
          n = k + 1;
          in_head_ = false;
          const std::size_t mib = (announced_length(head_) + (1 << 20) - 1) >> 20;
          deadline_ = Clock::now() + limits_.body_time_base + std::chrono::seconds(std::min<std::size_t>(mib, 1 << 20));
          head_.clear();
          head_.shrink_to_fit();
          break;
        }
      }
    }
    std::memcpy(ptr, buffer_ + begin_, n);
    begin_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (closed_) return static_cast<ssize_t>(size);   // this layer has answered: the library's reply is dropped
    return send_all(sock_, ptr, size, limits_.write_stall_max, stopping_) ? static_cast<ssize_t>(size) : -1;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override { address_of(sock_, true, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { address_of(sock_, false, ip, port); }
  socket_t socket() const override { return sock_; }

 private:
  // Bytes into the buffer: their count, 0 at the end of input, -1 when the deadline passed (the
  // client has been told) or the server stops.
  ssize_t fill() {
    for (;;) {
      if (stopping_) return -1;
      if (Clock::now() >= deadline_) {
        refuse(408, "Request Timeout",
               in_head_ ? fmt::format("the request head did not arrive within {} s", limits_.head_time_max.count() / 1000)
                        : std::string("the request body did not arrive in time (10 s, and a second more per MiB)"));
        return -1;
      }
      if (!(wait_for(sock_, POLLIN, slice_ms(deadline_)) & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::recv(sock_, buffer_, sizeof buffer_, MSG_DONTWAIT);
      if (n > 0) {
        begin_ = 0;
        end_ = static_cast<std::size_t>(n);
        return n;
      }
      if (n == 0) return 0;
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return -1;
    }
  }

  void refuse(int status, const char* reason, const std::string& why) {
    const std::string r = plain_response(status, reason, fmt::format("swarmcheck: error: HTTP {}: {}\n", status, why));
    send_all(sock_, r.data(), r.size(), limits_.write_stall_max, stopping_);
    closed_ = true;
  }

  const int sock_;
  const ConnectionLimits& limits_;
  const std::atomic<bool>& stopping_;
  Clock::time_point deadline_;
  char buffer_[4096];
  std::size_t begin_ = 0, end_ = 0;
  bool in_head_ = true;
  std::string head_;
  int lines_ = 0;
  bool closed_ = false;
};

// Half-closes, then reads what the client still sends for a moment before closing: closing with
// unread bytes sends a reset, which can make the client lose the response (a 413 or 403 sent
// before a body was read).
void linger_close(int sock, const std::atomic<bool>& stopping) {
  ::shutdown(sock, SHUT_WR);
  const auto deadline = Clock::now() + std::chrono::milliseconds(500);
  std::size_t drained = 0;
  char junk[4096];
  while (!stopping && drained < (1 << 20) && Clock::now() < deadline) {
    if (!(wait_for(sock, POLLIN, slice_ms(deadline)) & (POLLIN | POLLHUP | POLLERR))) continue;
    const ssize_t n = ::recv(sock, junk, sizeof junk, MSG_DONTWAIT);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) break;
    if (n > 0) drained += static_cast<std::size_t>(n);
  }
  ::close(sock);
}

}  // namespace connection

httplib::Headers security_headers() {
  return {{"X-Content-Type-Options", "nosniff"},
          {"Content-Security-Policy", "frame-ancestors 'none'"},
          {"X-Frame-Options", "DENY"},
          {"Cross-Origin-Resource-Policy", "same-origin"},
          {"Referrer-Policy", "no-referrer"}};
}

std::string plain_response(int status, const std::string& reason, const std::string& text) {
  std::string r = fmt::format("HTTP/1.1 {} {}\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: {}\r\nConnection: close\r\n",
                              status, reason, text.size());
  for (const auto& [name, value] : security_headers()) r += name + ": " + value + "\r\n";
  return r + "\r\n" + text;
}

void ConnectionThreads::enqueue(std::function<void()> fn) {
  {
    std::lock_guard lock(mutex_);
    ++running_;
  }
  auto task = [this, fn = std::move(fn)] {
    fn();
    std::unique_lock lock(mutex_);
    --running_;
    // Notified once this thread is gone, so shutdown() may return and the queue be deleted.
    std::notify_all_at_thread_exit(ended_, std::move(lock));
  };
  try {
    std::thread(task).detach();
  } catch (const std::system_error&) {   // no thread to be had: serve it on the accepting one
    task();
  }
}

void ConnectionThreads::shutdown() {
  std::unique_lock lock(mutex_);
  ended_.wait(lock, [this] { return running_ == 0; });
}

bool GuardedServer::admit(const std::string& client, std::string& why) {
  std::lock_guard lock(mutex_);
  if (connections_ >= limits_.connections_max) {
    why = fmt::format("{} connections are open (the server's limit); retry", limits_.connections_max);
    return false;
  }
  int& mine = per_client_[client];
  if (mine >= limits_.connections_per_client_max) {
    why = fmt::format("{} connections from {} are open (the limit for one client); retry", mine, client);
    if (mine == 0) per_client_.erase(client);
    return false;
  }
  ++mine;
  ++connections_;
  return true;
}

void GuardedServer::release(const std::string& client) {
  std::lock_guard lock(mutex_);
  --connections_;
  const auto it = per_client_.find(client);
  if (it != per_client_.end() && --it->second == 0) per_client_.erase(it);
}

bool GuardedServer::process_and_close_socket(socket_t sock) {
  const auto start = connection::Clock::now();
  const int one = 1;
  ::setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);   // a frame is one write: send it now
  std::string client;
  int port = 0;
  connection::address_of(sock, true, client, port);
  std::string why;
  if (!admit(client, why)) {
    const std::string r = plain_response(503, "Service Unavailable", "swarmcheck: error: HTTP 503: " + why + "\n");
    connection::send_all(sock, r.data(), r.size(), std::chrono::milliseconds(1000), stopping_);
    connection::linger_close(sock, stopping_);
    return true;
  }
  {
    connection::GuardedStream stream(sock, limits_, stopping_, start);
    bool closed = true;
    process_request(stream, /*close_connection=*/true, closed, nullptr);
  }
  release(client);
  connection::linger_close(sock, stopping_);
  return true;
}

}  // namespace swarmcheck::views

#endif
