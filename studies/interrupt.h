#pragma once
// Ctrl-C and kill (SIGINT, SIGTERM; mpirun turns a Ctrl-C into SIGTERM for every rank) leave no
// partial output (SPEC §4): the temporary files registered here are removed, then the process
// dies of the signal as it would have without us. A result file is only ever written to a
// temporary file and renamed at the end (core/io/h5_writer.h), so the previous result stays.
#include <string>

namespace thinlayer {

// Once per process (ProcessGroup does it).
void install_interrupt_handlers();

// Removed if a signal arrives before the process ends. Up to a handful of files per run;
// a path that no longer exists when the signal comes (renamed into place) is harmless.
void remove_on_interrupt(const std::string& path);

}  // namespace thinlayer
