#include "studies/interrupt.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <stdexcept>

namespace thinlayer {

namespace {

// The handler may only call async-signal-safe functions: so the paths wait in fixed buffers,
// published by a counter, and are removed with unlink().
constexpr int max_files = 8;
constexpr std::size_t max_path = 4096;
char paths[max_files][max_path];
std::atomic<int> registered{0};

extern "C" void on_interrupt(int signal) {
  const int n = registered.load();
  for (int i = 0; i < n && i < max_files; ++i) ::unlink(paths[i]);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handlers() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

void remove_on_interrupt(const std::string& path) {
  const int slot = registered.load();
  if (slot >= max_files || path.size() >= max_path) throw std::logic_error("remove_on_interrupt: too many or too long paths");
  std::memcpy(paths[slot], path.c_str(), path.size() + 1);
  registered.store(slot + 1);
}

}  // namespace thinlayer
