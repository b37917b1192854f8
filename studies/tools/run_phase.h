#pragma once
// What a command is doing, for the one line that running out of memory becomes (SPEC §4: out
// of memory anywhere is exit status 2 with one line naming the phase, never a bare
// "std::bad_alloc" and never exit 1 "result written" with nothing written).
//
//   RunPhase phase("solving the limit mode");   // until the end of the scope
//   ... catch (const std::exception& e) { print_message("solve", failure_text(e)); }
//
// The phase is the main thread's (the command's); a study's worker threads run inside one. A
// phase left by an exception stays the phase until the next one starts: the handler that
// catches it, outside the scope, still knows where it came from.
#include <exception>
#include <string>

namespace thinlayer {

class RunPhase {
 public:
  explicit RunPhase(std::string what);
  ~RunPhase();
  RunPhase(const RunPhase&) = delete;
  RunPhase& operator=(const RunPhase&) = delete;

 private:
  std::string previous_;
  int exceptions_;  // std::uncaught_exceptions() when it began
};

// The phase under way ("" before the first).
std::string run_phase();

// e.what(), or for std::bad_alloc "out of memory while <phase> (std::bad_alloc): ...".
std::string failure_text(const std::exception& e);

// "thinlayer <command>: <message>" and a newline on stderr, the message shown as every message
// is (core/io/shown_text.h: one line, a value from a file or from gmsh escaped). Every line
// thinlayer says about a run goes through here.
void print_message(const std::string& command, const std::string& message);

}  // namespace thinlayer
