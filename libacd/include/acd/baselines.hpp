// The exact baselines, the entry header of the acd::baselines library (link it): exact solid
// decomposition with CGAL's Nef polyhedra and exact surface decomposition. They run in the
// calling process and can take long; the `acd exact` command runs them in a child process.
#pragma once

#include <acd/exact_decomposition.hpp>
#include <acd/surface_exact.hpp>
