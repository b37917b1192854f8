#include "studies/tools/run_phase.h"

#include <exception>
#include <iostream>
#include <mutex>
#include <new>

#include "core/io/shown_text.h"

namespace thinlayer {

namespace {

std::mutex& phase_mutex() {
  static std::mutex m;
  return m;
}

std::string& phase() {
  static std::string p;
  return p;
}

}  // namespace

RunPhase::RunPhase(std::string what) : exceptions_(std::uncaught_exceptions()) {
  std::lock_guard<std::mutex> lock(phase_mutex());
  previous_ = std::move(phase());
  phase() = std::move(what);
}

RunPhase::~RunPhase() {
  if (std::uncaught_exceptions() > exceptions_) return;  // unwinding: the handler names this phase
  std::lock_guard<std::mutex> lock(phase_mutex());
  phase() = std::move(previous_);
}

std::string run_phase() {
  std::lock_guard<std::mutex> lock(phase_mutex());
  return phase();
}

void print_message(const std::string& command, const std::string& message) {
  std::cerr << "thinlayer " + command + ": " + shown(message) + "\n" << std::flush;
}

std::string failure_text(const std::exception& e) {
  if (!dynamic_cast<const std::bad_alloc*>(&e)) return e.what();
  const std::string now = run_phase();
  return "out of memory" + (now.empty() ? std::string() : " while " + now) + " (" + e.what() +
         "): give the run more memory (ulimit -v) or a coarser mesh";
}

}  // namespace thinlayer
