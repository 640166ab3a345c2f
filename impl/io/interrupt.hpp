#pragma once
// SIGINT, SIGTERM and SIGHUP while swarmcheck writes: the temporary files of every AtomicFile
// not yet committed (and the temporary folders registered, such as cosim's unpacked FMUs) are removed, one line is printed, and the process exits 128 + the signal
// (130 for Ctrl-C, 143 for SIGTERM). No output is half-written: targets are only ever replaced
// by rename() on commit, so an interrupted command leaves each output as it was.
//
// The registry of temporary files is the one process-wide state in swarmcheck: a signal handler
// can reach nothing else. It is a fixed array of slots written with atomics, so the handler only
// calls async-signal-safe functions (unlink, write, _exit).
#include <sys/types.h>

namespace swarmcheck::impl::io {

// Installs the handlers (once, from main). Later calls do nothing.
void install_interrupt_cleanup();

// A temporary file to remove if the process is interrupted; returns a slot id for release
// (-1 when every slot is taken: the file is then only removed by its owner's destructor).
int register_temp_file(const char* path);
// The same for a temporary folder: removed with everything in it.
int register_temp_folder(const char* path);
void release_temp_file(int slot);   // either kind

// A child process (dot) to kill if the process ends on a signal, before the temporary files are
// removed; returns a slot id for release_child (-1 when every slot is taken).
int register_child(pid_t pid);
void release_child(int slot);

// Kills every registered child, then removes every registered temporary file and folder, now
// (async-signal-safe): for a process about to end with _exit, from a signal handler or a watchdog
// thread.
void remove_temp_files_now();
// remove_temp_files_now(), `message` (if any) on stderr, then _exit(status) (async-signal-safe):
// a second Ctrl-C, which must not wait for the tidy stop the first one asked for.
[[noreturn]] void exit_now(int status, const char* message);

}  // namespace swarmcheck::impl::io
