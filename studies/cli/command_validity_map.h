#pragma once
// `thinlayer study validity-map --scene FILE.json [--out DIR] ...`: the engineer's validity map of a
// joint (SPEC 3 S3; studies/drivers/validity_map.h), its cells spread over MPI ranks (SPEC §6). With
// --out: DIR/results.h5, DIR/validity_map_<name>.csv and the map's report DIR/report/index.html.
// Exit status as every study: 0 every check passes, 1 one fails, 2 bad input or an unwritable output.
#include "studies/cli/command_study.h"

namespace thinlayer {

int command_study_validity_map(const CLI::App& command, const StudyArgs& args);

}  // namespace thinlayer
