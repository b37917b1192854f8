#pragma once
// What the refinement study (refinement_study.h) prints and writes: per case and mesh the scenes
// and their Cauchy differences, the verdict per case and quantity (one line each, naming h, h/2
// and h/4), the scenes without an answer, the floor under refinement, the slowest scenes; the same
// in the results file (/studies/convergence/refinement) and as a Markdown table for
// studies/convergence_rates.md.
#include <string>

#include "core/io/h5_writer.h"
#include "studies/drivers/refinement_study.h"

namespace thinlayer {

void print_refinement(const RefinementResult& result, const RefinementStudyOptions& options);
void write_refinement(H5Writer& out, const RefinementResult& result, const RefinementStudyOptions& options);
// The verdict table (case × quantity: the rate and its last local slopes at each mesh, the verdict),
// the floor and the scenes without an answer, in Markdown.
std::string refinement_markdown(const RefinementResult& result, const RefinementStudyOptions& options);

}  // namespace thinlayer
