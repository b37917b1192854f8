#pragma once
// A value from a file (a scene's JSON, a geometry, gmsh's error text, a path) as a message shows
// it (SPEC §4: a message is one line, with no control characters). The one rule of every message
// thinlayer prints and of every name it echoes (report/results_file.py's shown() follows it too):
//   - C0 controls, DEL, C1 controls (U+0080..U+009F), the line and paragraph separators
//     (U+2028, U+2029) and the bidirectional overrides and isolates (U+202A..U+202E,
//     U+2066..U+2069) as \uXXXX: no newline, no terminal escape, no text drawn backwards;
//   - a byte that is not part of valid UTF-8 as \xNN;
//   - everything else (printable ASCII, valid UTF-8: "ε", "≤") as it is.
#include <string>
#include <string_view>

namespace thinlayer {

std::string shown(std::string_view text);

}  // namespace thinlayer
