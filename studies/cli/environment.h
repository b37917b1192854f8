#pragma once
// What built and runs this program, for the reports: compiler, library versions, build flags
// and the source tree's git commit. Lets a result file say which code produced it.
#include <map>
#include <string>

#include "core/io/h5_writer.h"

namespace thinlayer {

// Keys: compiler, eigen, cholmod, suitesparse, gmsh, hdf5 (versions of the headers compiled
// against), build_type ("optimized" or "unoptimized", with assertions on or off: read from
// the compiler's macros, since CMake's build type is not passed to the code), and commit
// (`git rev-parse HEAD` of the source tree at run time, plus " (modified)" if
// `git status --porcelain` lists anything, " (status unknown)" if only that fails; "unknown"
// if git fails, e.g. outside a clone or where git is not installed).
std::map<std::string, std::string> environment_info();

// environment_info() as string attributes of the group /environment.
void write_environment(H5Writer& out);

}  // namespace thinlayer
