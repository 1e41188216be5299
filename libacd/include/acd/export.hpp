// What a decomposition is written as: report.json (report.hpp) and the simulators' files,
// URDF, MJCF, SDF and glTF (simulator_export.hpp).
#pragma once

#include <acd/report.hpp>
#include <acd/simulator_export.hpp>
