// Transitional (see scene_reader.hpp): the reader is sandbox/src/scene_reader.cpp, in acd_sandbox.
#include "scene_reader.hpp"
