#pragma once
// DIR/results.h5 of a study or of `verify`: the layout marker the report checks, every scene,
// the studies' tables, and every check (SPEC §4).
#include <memory>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "core/io/output_ownership.h"
#include "core/io/scene_record.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

// Root attributes `layout` and `layout_version`: the report refuses files without them or
// with another version. Bump the version whenever a reader would misread the old layout.
constexpr const char* results_layout = results_layout_name;  // core/io/output_ownership.h
// Version 2 (issue 15): every --out file (a `solve` file too) is a results file, /checks is
// always there (empty datasets if no check), and the scenes describe themselves (units,
// status legend, node_plus/node_minus, mesh/cell_body). The report reads versions 1 and 2.
constexpr int results_layout_version = 2;

// Opens FILE (written on commit only), marked with the layout and the environment
// (/environment: compiler, library versions, commit). Throws OutputError, before anything is
// written, if FILE may not be replaced under `rules` (core/io/output_ownership.h); the commit
// judges it again under the same rules, and so does every file written beside it
// (H5Writer::write_beside).
std::unique_ptr<H5Writer> open_results_file(const std::string& file, const OutputRules& rules = {});

// Creates DIR if needed and opens DIR/results.h5 as open_results_file does; the folders it
// made are removed again if the file is abandoned (no empty output folder is left behind).
// Null for an empty DIR. Throws OutputError if DIR cannot be created.
std::unique_ptr<H5Writer> open_results(const std::string& dir, const OutputRules& rules = {});

// One scene as a results file (a `solve --out` file): layout, environment, the scene, /checks
// (empty), committed.
void write_scene_file(const std::string& file, const SceneRecord& record, const OutputRules& rules);

// /checks: datasets id, pass (0/1), expected, got, tolerance — one entry per check, empty
// datasets if there is none (SPEC §4: the group is always there).
void write_checks(H5Writer& out, const std::vector<Check>& checks);

}  // namespace thinlayer
