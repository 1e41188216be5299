// Moved to acd/algo/cut_plane.hpp (the steps of the method, internal but exposed; docs/ARCHITECTURE.md).
// This forwarding header keeps the old path working for one release and then goes away.
#pragma once

#include <acd/algo/cut_plane.hpp>
