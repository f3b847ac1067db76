// The API cases' coverage, proven by counting calls: every one of GL 1.1's 336 entry points is
// wrapped in the loaded GL table while the cases run on MyGL, and each must be called, and called
// by an error call of the table unless the spec defines no error for it.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <glcalls/gl11_calls.h>
#include <mygl/context.h>

#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "api_table.h"
#include "cases.h"

namespace {

struct Tally {
    const char* name;
    long calls = 0, errorCalls = 0;
};
std::vector<Tally> tallies;

// The wrapper of the table entry `Slot`: counts, then calls what the table held before.
template <auto& Slot, class Signature = std::remove_reference_t<decltype(Slot)>>
struct Counter;

template <auto& Slot, class R, class... Args>
struct Counter<Slot, R(GLAD_API_PTR*)(Args...)> {
    static inline R(GLAD_API_PTR* original)(Args...) = nullptr;
    static inline std::size_t index = 0;
    static R GLAD_API_PTR call(Args... args) {
        ++tallies[index].calls;
        if (conformance::inErrorCall()) ++tallies[index].errorCalls;
        return original(args...);
    }
    static void install(std::size_t i) {
        index = i;
        original = Slot;
        Slot = &call;
    }
    static void uninstall() { Slot = original; }
};

struct Wrapped {
    const char* name;
    void (*install)(std::size_t);
    void (*uninstall)();
};

const Wrapped kWrapped[] = {
#define MYGL_COUNTER(name, class_, count) {#name, &Counter<glad_##name>::install, &Counter<glad_##name>::uninstall},
    MYGL_GL11_CALLS(MYGL_COUNTER)
#undef MYGL_COUNTER
};

// The spec allows these between glBegin and glEnd and defines no error of their own (GL 1.1,
// section 2.6.3): glVertex, glColor, glNormal, glTexCoord, glIndex, glEdgeFlag, glEvalCoord,
// glEvalPoint, glArrayElement, glCallList. glMaterial and glCallLists have errors of their own.
bool hasNoSpecError(std::string_view name) {
    auto starts = [&](std::string_view prefix) { return name.substr(0, prefix.size()) == prefix; };
    if (name == "glVertexPointer" || name == "glColorPointer" || name == "glColorMask" || name == "glColorMaterial" ||
        name == "glNormalPointer" || name == "glTexCoordPointer" || name == "glIndexPointer" || name == "glIndexMask" ||
        name == "glEdgeFlagPointer")
        return false;
    return starts("glVertex") || starts("glColor") || starts("glNormal3") || starts("glTexCoord") ||
           starts("glIndex") || starts("glEdgeFlag") || starts("glEvalCoord") || starts("glEvalPoint") ||
           name == "glArrayElement" || name == "glCallList";
}

TEST(ApiCoverage, EveryGl11FunctionIsCalledAndEveryErrorOfTheSpecIsTried) {
    ASSERT_EQ(std::size(kWrapped), 336u);
    tallies.clear();
    for (const Wrapped& w : kWrapped) tallies.push_back({w.name});
    mygl::Context context(conformance::kWidth, conformance::kHeight);
    context.makeCurrent();
    const std::vector<conformance::Case> cases = conformance::apiCases();
    for (const conformance::Case& c : cases) {
        c.draw(conformance::kWidth, conformance::kHeight);
        for (std::size_t i = 0; i < std::size(kWrapped); ++i) kWrapped[i].install(i);
        conformance::Observations observations;
        c.observe(observations);
        for (const Wrapped& w : kWrapped) w.uninstall();
    }
    int withoutError = 0;
    for (const Tally& t : tallies) {
        EXPECT_GT(t.calls, 0) << t.name << " is never called by the API cases";
        if (hasNoSpecError(t.name)) {
            ++withoutError;
        } else {
            EXPECT_GT(t.errorCalls, 0) << t.name << " has errors in the spec but no error call in the API table";
        }
    }
    EXPECT_EQ(withoutError, 24 + 32 + 10 + 32 + 10 + 2 + 8 + 2 + 1 + 1);
}

// The API cases are part of the table the conformance test and mygl-accuracy run.
TEST(ApiCoverage, TheApiCasesAreInTheGeneratedTable) {
    std::size_t api = 0;
    for (const conformance::Case& c : conformance::allCases()) api += c.category.starts_with("api-");
    EXPECT_EQ(api, conformance::apiCases().size());
    EXPECT_GE(api, 336u);
}

}  // namespace
