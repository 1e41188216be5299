// Moved to acd/algo/knots.hpp (the steps of the method, internal but exposed; docs/ARCHITECTURE.md).
// This forwarding header keeps the old path working for one release and then goes away.
#pragma once

#include <acd/algo/knots.hpp>
