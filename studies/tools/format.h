#pragma once
// Text forms shared by the studies' tables and checks.
#include <string>

#include "core/solvers/contact_problem.h"

namespace thinlayer {

// "gap/slide/stick", e.g. "3/14/15".
std::string counts_text(const StatusCount& c);
// Scientific notation with the given number of decimals, e.g. sci(1.5e-11, 2) = "1.50e-11".
std::string sci(double x, int decimals = 3);
// Fixed notation, e.g. fixed(2.345, 2) = "2.35".
std::string fixed(double x, int decimals);
// The shortest natural form (printf %g), e.g. plain(0.025) = "0.025", plain(1e-4) = "0.0001".
std::string plain(double x);
// `digits` significant digits, without exponent where printf %g has none, e.g. significant(0.1834, 2) = "0.18".
std::string significant(double x, int digits);

}  // namespace thinlayer
