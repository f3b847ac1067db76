#include "entry_points.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "not_implemented.h"

namespace mygl {
namespace {

bool byName(const EntryPoint& a, const EntryPoint& b) { return std::strcmp(a.name, b.name) < 0; }

// The implemented entry points by name.
const std::vector<EntryPoint>& implementedTable() {
    static const std::vector<EntryPoint> table = [] {
        std::vector<EntryPoint> all;
        for (
            auto area :
            {beginEndEntryPoints(),         matrixEntryPoints(),    stateEntryPoints(),        getEntryPoints(),
             bufferEntryPoints(),           listEntryPoints(),      arrayEntryPoints(),        rasterPosEntryPoints(),
             pixelRectangleEntryPoints(),   pixelModeEntryPoints(), selectionEntryPoints(),    attribStackEntryPoints(),
             lightingEntryPoints(),         clipPlaneEntryPoints(), evaluatorEntryPoints(),    fogEntryPoints(),
             polygonOffsetEntryPoints(),    stippleEntryPoints(),   accumulationEntryPoints(), colorIndexEntryPoints(),
             drawBufferEntryPoints(),       feedbackEntryPoints(),  fragmentOpsEntryPoints(),  textureEntryPoints(),
             textureParameterEntryPoints(), textureGenEntryPoints()}) {
            all.insert(all.end(), area.begin(), area.end());
        }
        std::sort(all.begin(), all.end(), byName);
        return all;
    }();
    return table;
}

// Every entry point by name: the implemented ones, and a stub for each GL 1.1 function that
// is not (yet).
std::vector<EntryPoint> sortedTable() {
    std::vector<EntryPoint> table = implementedTable();
    const std::vector<EntryPoint> missing = notImplementedEntryPoints(table);
    table.insert(table.end(), missing.begin(), missing.end());
    std::sort(table.begin(), table.end(), byName);
    return table;
}

const EntryPoint* findIn(const std::vector<EntryPoint>& table, const char* name) {
    if (!name) return nullptr;
    const auto found = std::lower_bound(table.begin(), table.end(), name,
                                        [](const EntryPoint& e, const char* n) { return std::strcmp(e.name, n) < 0; });
    return found != table.end() && std::strcmp(found->name, name) == 0 ? &*found : nullptr;
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
    const EntryPoint* found = findIn(table, name);
    return found ? found->proc : nullptr;
}

bool implements(const char* name) { return findIn(implementedTable(), name) != nullptr; }

}  // namespace mygl
