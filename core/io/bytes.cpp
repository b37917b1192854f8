#include "core/io/bytes.h"

namespace thinlayer {

void put(ByteWriter& w, const std::string& s) {
  put(w, static_cast<std::uint64_t>(s.size()));
  w.raw(s.data(), s.size());
}
void get(ByteReader& r, std::string& s) {
  std::uint64_t n = 0;
  get(r, n);
  r.check_count(n, 1);
  s.resize(n);
  r.raw(s.data(), n);
}

}  // namespace thinlayer
