// Interned draw states: equal states share one object, so that a batch compares its state with
// the next primitive's by address, and a queued batch's state cannot change under it.
#include <gtest/gtest.h>

#include "glrenderer/pipeline.h"
#include "glrenderer/state_interner.h"

namespace {

using glrenderer::DrawState;
using glrenderer::StateInterner;

DrawState withDepthFunc(int i) {
    DrawState state;
    state.depthFunc = static_cast<glrenderer::CompareFunc>(i % 8);
    state.lineWidth = 1.0f + static_cast<float>(i);
    return state;
}

TEST(StateInterner, EqualStatesShareOneObjectAndUnequalOnesDoNot) {
    StateInterner interner;
    const auto a = interner.intern(withDepthFunc(1));
    const auto b = interner.intern(withDepthFunc(2));
    EXPECT_NE(a, b);
    EXPECT_EQ(interner.intern(withDepthFunc(1)), a);
    EXPECT_EQ(interner.intern(withDepthFunc(2)), b);
    EXPECT_EQ(*a, withDepthFunc(1));
}

TEST(StateInterner, AStatePushedOutLivesOnAndComesBackAsAnEqualObject) {
    StateInterner interner;
    const auto first = interner.intern(withDepthFunc(0));
    for (int i = 1; i <= 40; ++i) interner.intern(withDepthFunc(i));  // more than the recent list holds
    const auto again = interner.intern(withDepthFunc(0));
    EXPECT_EQ(*first, withDepthFunc(0));  // still alive, unchanged
    EXPECT_EQ(*again, *first);
}

TEST(StateInterner, AFrameAlternatingAFewStatesAllocatesNoNewObjects) {
    StateInterner interner;
    std::vector<glrenderer::StateRef> firstFrame;
    for (int i = 0; i < 6; ++i) firstFrame.push_back(interner.intern(withDepthFunc(i)));
    for (int frame = 0; frame < 3; ++frame) {
        for (int i = 0; i < 6; ++i)
            EXPECT_EQ(interner.intern(withDepthFunc(i)), firstFrame[static_cast<std::size_t>(i)]);
    }
}

TEST(StateInterner, ThePipelineInternsTheStateAsItDrawsIt) {
    // With back faces culled, the reference draws back faces in the front faces' mode: the
    // interned state says so, and equal drawn states are one object.
    glrenderer::Framebuffer framebuffer(4, 4);
    glrenderer::Pipeline pipeline(framebuffer);
    DrawState lineBack;
    lineBack.cullEnabled = true;
    lineBack.polygonBack = glrenderer::PolygonMode::Line;
    const auto drawn = pipeline.intern(lineBack);
    EXPECT_EQ(drawn->polygonBack, glrenderer::PolygonMode::Fill);
    EXPECT_EQ(pipeline.intern(lineBack), drawn);
    DrawState fillBack = lineBack;
    fillBack.polygonBack = glrenderer::PolygonMode::Fill;
    EXPECT_EQ(pipeline.intern(fillBack), drawn);
}

}  // namespace
