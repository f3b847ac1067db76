// The GL 1.1 entry points: which are still on the not-implemented stub (an explicit list that
// shrinks as functions land), and the stub itself: it reports its function once and records
// GL_INVALID_OPERATION instead of crashing.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <glcalls/gl11_calls.h>
#include <mygl/context.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "not_implemented.h"

namespace {

// Every GL 1.1 function is implemented: a function dropped by mistake joins this list and fails
// the test below.
const std::vector<std::string> kStillToDo = {};

TEST(EntryPoints, ExactlyTheListedGl11FunctionsAreStillOnTheStub) {
    static const char* const kAll[] = {
#define MYGL_NAME(name, class_, count) #name,
        MYGL_GL11_CALLS(MYGL_NAME)
#undef MYGL_NAME
    };
    EXPECT_EQ(std::size(kAll), 336u);
    std::vector<std::string> stubbed;
    for (const char* name : kAll) {
        EXPECT_NE(mygl::getProcAddress(name), nullptr) << name << " has no entry point at all";
        if (!mygl::implements(name)) stubbed.emplace_back(name);
    }
    // A function that lands leaves the list; one that is dropped by mistake joins it: both fail here.
    std::vector<std::string> expected = kStillToDo;
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(stubbed, expected);
}

// The stub is called directly (every GL 1.1 function has one, implemented or not), so that the
// mechanism stays tested once no function is left on it.
mygl::ProcAddress stubOf(const std::vector<mygl::EntryPoint>& stubs, const char* name) {
    for (const mygl::EntryPoint& e : stubs) {
        if (std::strcmp(e.name, name) == 0) return e.proc;
    }
    return nullptr;
}

TEST(EntryPoints, TheStubReportsItsFunctionOnceAndRecordsInvalidOperation) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    const std::vector<mygl::EntryPoint> stubs = mygl::notImplementedEntryPoints({});
    ASSERT_EQ(stubs.size(), 336u);
    const auto accum = reinterpret_cast<PFNGLACCUMPROC>(stubOf(stubs, "glAccum"));
    const auto isList = reinterpret_cast<PFNGLISLISTPROC>(stubOf(stubs, "glIsList"));
    ASSERT_TRUE(accum && isList);
    testing::internal::CaptureStderr();
    accum(GL_ACCUM, 0.5f);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
    accum(GL_LOAD, 1.0f);  // named once per process
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
    EXPECT_EQ(isList(1), GL_FALSE);  // a value-returning one returns zero
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(said,
              "MyGL: glAccum is not implemented yet (GL_INVALID_OPERATION)\n"
              "MyGL: glIsList is not implemented yet (GL_INVALID_OPERATION)\n");
    // The program goes on drawing.
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT_EQ(context.readPixels()[1], 255);
}

}  // namespace
