#include "entry_points.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace mygl {
namespace {

std::vector<EntryPoint> sortedTable() {
    std::vector<EntryPoint> table;
    for (auto area : {beginEndEntryPoints(), matrixEntryPoints(), stateEntryPoints(), getEntryPoints(),
                      bufferEntryPoints(), rasterPosEntryPoints()}) {
        table.insert(table.end(), area.begin(), area.end());
    }
    std::sort(table.begin(), table.end(),
              [](const EntryPoint& a, const EntryPoint& b) { return std::strcmp(a.name, b.name) < 0; });
    return table;
}

}  // namespace

Context::State* stateOutsideBeginEnd() {
    Context::State* state = currentState();
    if (state && state->insideBeginEnd) {
        setError(*state, GL_INVALID_OPERATION);
        return nullptr;
    }
    return state;
}

ProcAddress getProcAddress(const char* name) {
    static const std::vector<EntryPoint> table = sortedTable();
    if (!name) return nullptr;
    const auto found = std::lower_bound(table.begin(), table.end(), name, [](const EntryPoint& e, const char* n) {
        return std::strcmp(e.name, n) < 0;
    });
    return found != table.end() && std::strcmp(found->name, name) == 0 ? found->proc : nullptr;
}

}  // namespace mygl
