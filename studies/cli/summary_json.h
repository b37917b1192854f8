#pragma once
// DIR/summary.json of `thinlayer verify` (SPEC §4):
// {"checks":[{"id":..,"pass":..,"expected":..,"got":..,"tolerance":..}], "timings":{..}}
#include <map>
#include <string>
#include <vector>

#include "studies/drivers/table3_study.h"

namespace thinlayer {

std::string summary_json(const std::vector<Check>& checks, const std::map<std::string, double>& timings);

}  // namespace thinlayer
