#pragma once
#include <span>
#include <vector>

#include "entry_points.h"

namespace mygl {

// An entry point for every GL 1.1 function MyGL does not implement yet: it records
// GL_INVALID_OPERATION and says once per process on stderr which function is missing, so a
// program that calls it keeps running instead of jumping to a null pointer. `implemented` is
// sorted by name.
// Records GL_INVALID_OPERATION and says once per process on stderr that `name` (a function, or
// a function with an argument) is not implemented yet.
void reportNotImplemented(const char* name);

std::vector<EntryPoint> notImplementedEntryPoints(std::span<const EntryPoint> implemented);

}  // namespace mygl
