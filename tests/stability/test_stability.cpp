// The stability table, asserted both ways: the exact method holds everywhere; each method known
// to fail somewhere is asserted to fail there, so the published table stays true.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "stability.h"

namespace {

// One letter per method, in allMethods() order: exact, scanline, bbox-float, screen-linear,
// view-space-cull, look-vector-cull, painters-sort. H = holds, B = breaks.
const std::map<std::string, std::string> kExpected = {
    {"shared edges", "HBBHHHH"},  // the seeds' rule owns top edges; bbox-float owns both sides
    {"slivers", "HBBHHHH"},       // float edges miss or add pixel centers of thin triangles
    {"tiny triangles", "HHHHHHH"},
    {"offset 1e3", "HHHHHHH"},
    {"offset 1e5", "HBBHHHH"},  // float slopes at large coordinates move an edge
    {"offset 1e7", "HHHHHHH"},  // float positions are whole pixels there, for everyone
    {"sub-pixel jitter", "HHHHHHH"},
    {"near plane", "HHHBHHB"},  // screen-linear colors bend; the sort reorders overlaps
    {"concave polygon", "HHBHHHH"},
    {"intersecting quads", "HHHHHHB"},        // no order of whole triangles resolves a crossing
    {"concave hexahedron", "HHHHHHH"},        // its overlapping faces happen to sort right by mean depth
    {"wide perspective culling", "HBBHHBH"},  // the look vector is not the direction to off-axis faces
};

}  // namespace

TEST(Stability, EachMethodHoldsAndBreaksWhereTheTableSays) {
    const auto methods = stability::allMethods();
    for (const stability::Check& check : stability::allChecks()) {
        ASSERT_TRUE(kExpected.contains(check.name)) << check.name;
        const std::string& expected = kExpected.at(check.name);
        ASSERT_EQ(expected.size(), methods.size());
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const stability::Outcome outcome = stability::run(check, methods[m]);
            EXPECT_EQ(outcome.holds, expected[m] == 'H') << check.name << " with " << methods[m].name << ": "
                                                         << outcome.pixelsOver1 << " pixels differ by more than 1";
        }
    }
}
