#pragma once
// The connection layer of `swarmcheck serve`. cpp-httplib parses requests, routes them and writes
// responses, but every byte to and from a client goes through a GuardedStream, which holds what
// the library alone does not:
//  - a deadline on the request head (from the connection's start) and one on its body (from the
//    head's end, longer for a longer body): a client sending a header line every few seconds is
//    answered 408 and dropped, not waited for;
//  - limits on the head (bytes and lines): 4 000 000 headers were accepted and kept 549 MB; now
//    past the limit the client gets 431 and the connection is closed;
//  - every wait (for bytes to read, for room to write) is cut into slices of at most 100 ms that
//    check the server's stop flag, so SIGTERM ends every connection within a second whatever its
//    client does; a write that makes no progress for write_stall_max drops the connection;
//  - a thread per connection (ConnectionThreads), so slow clients hold only their own threads,
//    up to connections_max in all and connections_per_client_max per client address (503 past
//    either), instead of a fixed pool that 12 slow clients filled.
// Every connection carries one request (Connection: close).
#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace swarmcheck::views {

struct ConnectionLimits {
  std::size_t head_bytes_max = 32 << 10;   // request line and headers
  int head_lines_max = 100;                // the request line, the headers, the blank line
  std::chrono::milliseconds head_time_max{10'000};
  std::chrono::milliseconds body_time_base{10'000};   // plus one second per MiB the head announces
  std::chrono::milliseconds write_stall_max{10'000};
  int connections_max = 64;
  int connections_per_client_max = 16;
};

// The headers every response carries, the ones this layer writes itself included: no content
// sniffing, no framing by any page, no use as a subresource of another origin, no referrer.
httplib::Headers security_headers();
// A whole HTTP/1.1 response with those headers and `Connection: close`: for refusals written
// before or instead of the library's.
std::string plain_response(int status, const std::string& reason, const std::string& text);

// A TaskQueue with a thread per task (a connection); shutdown() waits until every one has ended.
class ConnectionThreads : public httplib::TaskQueue {
 public:
  void enqueue(std::function<void()> fn) override;
  void shutdown() override;

 private:
  std::mutex mutex_;
  std::condition_variable ended_;
  int running_ = 0;
};

class GuardedServer : public httplib::Server {
 public:
  GuardedServer(const ConnectionLimits& limits, const std::atomic<bool>& stopping) : limits_(limits), stopping_(stopping) {}

 private:
  bool process_and_close_socket(socket_t sock) override;
  // Counts the connection of `client` in; false when a limit says no.
  bool admit(const std::string& client, std::string& why);
  void release(const std::string& client);

  const ConnectionLimits limits_;
  const std::atomic<bool>& stopping_;
  std::mutex mutex_;
  int connections_ = 0;
  std::map<std::string, int> per_client_;
};

}  // namespace swarmcheck::views

#endif
