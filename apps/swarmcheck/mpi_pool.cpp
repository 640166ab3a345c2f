#include "apps/swarmcheck/mpi_pool.hpp"

#include <cstdlib>
#include <ctime>
#include <deque>
#include <stdexcept>

#if SWARMCHECK_HAVE_MPI
#define OMPI_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace swarmcheck::cli::mpi {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

}  // namespace

Launch launch_from_environment() {
  Launch l;
  l.size = env_int("OMPI_COMM_WORLD_SIZE", env_int("PMI_SIZE", env_int("PMIX_SIZE", 1)));
  l.rank = env_int("OMPI_COMM_WORLD_RANK", env_int("PMI_RANK", env_int("PMIX_RANK", 0)));
  return l;
}

bool compiled_in() { return SWARMCHECK_HAVE_MPI != 0; }

std::string missing_mpi_message() {
  return "this swarmcheck was built without Open MPI, so its copies under mpirun would each do all the work: "
         "install libopenmpi-dev and openmpi-bin (scripts/install-deps tries to), rebuild, and run mpirun again";
}

#if SWARMCHECK_HAVE_MPI

namespace {

enum Tag : int { kReady = 1, kTask = 2, kReply = 3, kRelease = 4 };

std::deque<int> g_idle;   // rank 0: workers waiting for a task
bool g_idle_known = false;

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// "index\n" + body
std::string with_index(std::size_t i, const std::string& body) { return std::to_string(i) + "\n" + body; }
std::pair<std::size_t, std::string> split_index(const std::string& text) {
  const std::size_t nl = text.find('\n');
  return {static_cast<std::size_t>(std::stoull(text.substr(0, nl))), text.substr(nl + 1)};
}

void pause_briefly() {
  timespec t{0, 200000};   // 0.2 ms: the master polls, so that a signal's flag is seen soon
  nanosleep(&t, nullptr);
}

}  // namespace

Session::Session() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() { MPI_Finalize(); }

void Session::abort(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

void distribute(const std::vector<std::string>& tasks, const std::function<void(std::size_t, std::string)>& done,
                const std::function<bool(std::size_t)>& skip) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (!g_idle_known) {   // every worker announces itself once
    for (int w = 1; w < size; ++w) {
      MPI_Status st;
      MPI_Probe(MPI_ANY_SOURCE, kReady, MPI_COMM_WORLD, &st);
      (void)receive_text(st);
      g_idle.push_back(st.MPI_SOURCE);
    }
    g_idle_known = true;
  }
  std::size_t next = 0, in_flight = 0;
  const auto hand_out = [&] {
    while (!g_idle.empty() && next < tasks.size()) {
      const std::size_t i = next++;
      if (skip && skip(i)) continue;
      send_text(with_index(i, tasks[i]), g_idle.front(), kTask);
      g_idle.pop_front();
      ++in_flight;
    }
  };
  hand_out();
  while (in_flight > 0) {
    int ready = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kReply, MPI_COMM_WORLD, &ready, &st);
    if (!ready) {
      pause_briefly();
      continue;
    }
    auto [i, reply] = split_index(receive_text(st));
    --in_flight;
    g_idle.push_back(st.MPI_SOURCE);
    if (!reply.empty() && reply[0] == '!') throw std::runtime_error("rank " + std::to_string(st.MPI_SOURCE) + ": " + reply.substr(1));
    done(i, std::move(reply));
    hand_out();
  }
}

void release_workers() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (!g_idle_known)
    for (int w = 1; w < size; ++w) {
      MPI_Status st;
      MPI_Probe(MPI_ANY_SOURCE, kReady, MPI_COMM_WORLD, &st);
      (void)receive_text(st);
    }
  for (int w = 1; w < size; ++w) send_text("", w, kRelease);
  g_idle.clear();
  g_idle_known = false;
}

void serve(const std::function<std::string(const std::string&)>& work) {
  send_text("", 0, kReady);
  while (true) {
    MPI_Status st;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    const std::string text = receive_text(st);
    if (st.MPI_TAG == kRelease) return;
    auto [i, task] = split_index(text);
    std::string reply;
    try {
      reply = work(task);
    } catch (const std::exception& e) {
      reply = std::string("!") + e.what();
    }
    send_text(with_index(i, reply), 0, kReply);
  }
}

#else   // without MPI: a multi-rank launch is refused before any of these is reached

Session::Session() { throw std::runtime_error(missing_mpi_message()); }
Session::~Session() = default;
void Session::abort(int status) { std::exit(status); }
void distribute(const std::vector<std::string>&, const std::function<void(std::size_t, std::string)>&,
                const std::function<bool(std::size_t)>&) {}
void release_workers() {}
void serve(const std::function<std::string(const std::string&)>&) {}

#endif

}  // namespace swarmcheck::cli::mpi
