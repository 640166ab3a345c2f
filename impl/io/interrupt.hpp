#pragma once
// SIGINT, SIGTERM and SIGHUP while swarmcheck writes: the temporary files of every AtomicFile
// not yet committed are removed, one line is printed, and the process exits 128 + the signal
// (130 for Ctrl-C, 143 for SIGTERM). No output is half-written: targets are only ever replaced
// by rename() on commit, so an interrupted command leaves each output as it was.
//
// The registry of temporary files is the one process-wide state in swarmcheck: a signal handler
// can reach nothing else. It is a fixed array of slots written with atomics, so the handler only
// calls async-signal-safe functions (unlink, write, _exit).
namespace swarmcheck::impl::io {

// Installs the handlers (once, from main). Later calls do nothing.
void install_interrupt_cleanup();

// A temporary file to remove if the process is interrupted; returns a slot id for release
// (-1 when every slot is taken: the file is then only removed by its owner's destructor).
int register_temp_file(const char* path);
void release_temp_file(int slot);

}  // namespace swarmcheck::impl::io
