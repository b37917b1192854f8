#pragma once
// What the validity map (studies/drivers/validity_map.h) prints and writes: per ν_g and quantity, the
// distance of the finite law to the layer over (t/L, E_g/E_a) at h/2, with the cells the mesh does not
// resolve and those that did not converge marked; SPEC §3 S6's estimate against it; where the paper's
// rule picks another law and what that costs. In the results file /studies/validity_map/<name>/ (one
// row per cell: every dataset with its units and a description), and beside it
// validity_map_<name>.csv (the same rows).
#include "studies/drivers/validity_map.h"

namespace thinlayer {

void print_validity_map(const ValidityMapResult& r, const ValidityMapOptions& o);
void write_validity_map(H5Writer& out, const ValidityMapResult& r, const ValidityMapOptions& o);
// The CSV's text (header comments, then one row per cell).
std::string validity_map_csv(const ValidityMapResult& r, const ValidityMapOptions& o);

}  // namespace thinlayer
