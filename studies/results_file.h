#pragma once
// DIR/results.h5 of a study or of `verify`: the layout marker the report checks, every scene,
// the studies' tables, and every check (SPEC §4).
#include <memory>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/table3_study.h"

namespace thinlayer {

// Root attributes `layout` and `layout_version`: the report refuses files without them or
// with another version. Bump the version whenever a reader would misread the old layout.
constexpr const char* results_layout = "thinlayer-results";
constexpr int results_layout_version = 1;

// Creates DIR if needed and opens DIR/results.h5 (written on commit only), marked with the
// layout and the environment (/environment: compiler, library versions, commit). Null for an
// empty DIR.
std::unique_ptr<H5Writer> open_results(const std::string& dir);

// /checks: datasets id, pass (0/1), expected, got, tolerance — one entry per check.
void write_checks(H5Writer& out, const std::vector<Check>& checks);

}  // namespace thinlayer
