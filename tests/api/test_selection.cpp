// Selection (GL_SELECT, picking): hit records, return values, the name stack and its errors,
// compared with OSMesa running the very same calls.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <mygl/glu.h>

#include <string_view>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

// What a selection pass leaves: glRenderMode's answer, the buffer and the errors on the way.
struct Selected {
    GLint hits = 0;
    std::vector<GLuint> buffer;
    std::vector<GLenum> errors;
    bool operator==(const Selected&) const = default;
};

void perspective() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void triangle(float nearZ) {
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.5f, -0.5f, nearZ);
    glVertex3f(0.5f, -0.5f, -3.0f);
    glVertex3f(0.0f, 0.5f, -4.3f);
    glEnd();
}

Selected select(void (*draw)(), GLsizei size = 64) {
    Selected s;
    s.buffer.assign(64, 0xDEADBEEF);
    perspective();
    glSelectBuffer(size, s.buffer.data());
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    draw();
    s.hits = glRenderMode(GL_RENDER);
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) s.errors.push_back(e);
    return s;
}

struct Case {
    const char* name;
    void (*draw)();
};

const Case kCases[] = {
    {"a triangle",
     [] {
         glLoadName(1);
         triangle(-2.0f);
     }},
    {"clipped by the near plane",
     [] {
         glLoadName(2);
         triangle(-0.5f);
     }},
    {"back face culled, then drawn without culling",
     [] {
         glEnable(GL_CULL_FACE);
         glLoadName(3);
         glBegin(GL_TRIANGLES);
         glVertex3f(-0.5f, -0.5f, -2.0f);
         glVertex3f(0.0f, 0.5f, -4.3f);
         glVertex3f(0.5f, -0.5f, -3.0f);
         glEnd();
         glDisable(GL_CULL_FACE);
         glLoadName(4);
         glBegin(GL_TRIANGLES);
         glVertex3f(-0.5f, -0.5f, -2.0f);
         glVertex3f(0.0f, 0.5f, -4.3f);
         glVertex3f(0.5f, -0.5f, -3.0f);
         glEnd();
     }},
    {"no area: a hit without culling, none with it",
     [] {
         glLoadName(5);
         glBegin(GL_TRIANGLES);
         glVertex3f(-0.5f, -0.5f, -2.0f);
         glVertex3f(0.0f, 0.0f, -2.0f);
         glVertex3f(0.5f, 0.5f, -2.0f);
         glEnd();
         glEnable(GL_CULL_FACE);
         glLoadName(6);
         glBegin(GL_TRIANGLES);
         glVertex3f(-0.5f, -0.5f, -2.5f);
         glVertex3f(0.0f, 0.0f, -2.5f);
         glVertex3f(0.5f, 0.5f, -2.5f);
         glEnd();
     }},
    {"points at the far and near planes (depth 1 wraps to 0)",
     [] {
         glLoadName(7);
         glBegin(GL_POINTS);
         glVertex3f(0.0f, 0.0f, -10.0f);
         glVertex3f(0.0f, 0.0f, -1.0f);
         glEnd();
         glLoadName(8);
         glBegin(GL_POINTS);
         glVertex3f(5.0f, 0.0f, -2.0f);  // outside
         glVertex3f(0.1f, 0.0f, -2.5f);
         glEnd();
     }},
    {"lines and strips, clipped",
     [] {
         glLoadName(9);
         glBegin(GL_LINES);
         glVertex3f(-5.0f, 0.0f, -2.0f);
         glVertex3f(0.3f, 0.2f, -7.0f);
         glEnd();
         glLoadName(10);
         glBegin(GL_LINE_LOOP);
         glVertex3f(-0.2f, -0.2f, -1.5f);
         glVertex3f(0.9f, 0.1f, -8.0f);
         glVertex3f(0.0f, 0.7f, -12.0f);
         glEnd();
     }},
    {"quads, strips and fans under a rotation",
     [] {
         glRotatef(30.0f, 0.3f, 1.0f, 0.2f);
         glLoadName(11);
         glBegin(GL_QUADS);
         glVertex3f(-1.0f, -1.0f, -3.0f);
         glVertex3f(1.0f, -1.0f, -3.5f);
         glVertex3f(1.0f, 1.0f, -4.0f);
         glVertex3f(-1.0f, 1.0f, -3.5f);
         glEnd();
         glLoadName(12);
         glBegin(GL_TRIANGLE_FAN);
         for (int i = 0; i < 8; ++i)
             glVertex3f(0.3f * static_cast<float>(i % 3), 0.2f * static_cast<float>(i),
                        -2.0f - 0.7f * static_cast<float>(i));
         glEnd();
     }},
    {"raster positions: a valid one hits, an invalid one does not",
     [] {
         glLoadName(13);
         glRasterPos3f(0.0f, 0.0f, -3.0f);
         glLoadName(14);
         glRasterPos3f(50.0f, 0.0f, -3.0f);
     }},
    {"nested names, then popped past the bottom",
     [] {
         glPushName(15);
         glPushName(16);
         triangle(-2.0f);
         glPopName();
         glPopName();
         glPopName();
         glPopName();    // GL_STACK_UNDERFLOW
         glLoadName(3);  // GL_INVALID_OPERATION: the stack is empty
     }},
    {"no hit at all",
     [] {
         glLoadName(17);
         glBegin(GL_TRIANGLES);
         glVertex3f(5.0f, 5.0f, -2.0f);
         glVertex3f(6.0f, 5.0f, -2.0f);
         glVertex3f(5.0f, 6.0f, -2.0f);
         glEnd();
     }},
};

}  // namespace

TEST(Selection, HitRecordsAsTheReference) {
    for (const Case& c : kCases) {
        const auto results = onBothBackends<Selected>([&] { return select(c.draw); });
        EXPECT_EQ(results.mygl, results.osmesa) << c.name;
        EXPECT_EQ(results.osmesa.hits != 0, c.name != std::string_view("no hit at all")) << c.name;
    }
}

TEST(Selection, OverflowStateAndErrorsAsTheReference) {
    const auto results = onBothBackends<std::vector<GLint>>([] {
        std::vector<GLint> out;
        const Selected small = select(kCases[0].draw, 2);  // a record of 4 values does not fit: -1
        out.push_back(small.hits);
        out.insert(out.end(), small.buffer.begin(), small.buffer.begin() + 3);
        GLuint buffer[8];
        glSelectBuffer(-1, buffer);
        out.push_back(static_cast<GLint>(glGetError()));
        glSelectBuffer(8, buffer);
        glRenderMode(GL_SELECT);
        glSelectBuffer(8, buffer);  // not while selecting
        out.push_back(static_cast<GLint>(glGetError()));
        for (int i = 0; i < 70; ++i) glPushName(static_cast<GLuint>(i));
        out.push_back(static_cast<GLint>(glGetError()));  // GL_STACK_OVERFLOW past 64
        for (GLenum name : {GL_RENDER_MODE, GL_NAME_STACK_DEPTH, GL_MAX_NAME_STACK_DEPTH, GL_SELECTION_BUFFER_SIZE}) {
            GLint value = -7;
            glGetIntegerv(name, &value);
            out.push_back(value);
        }
        out.push_back(glRenderMode(GL_RENDER));
        glLoadName(1);  // ignored outside GL_SELECT
        glPushName(1);
        out.push_back(static_cast<GLint>(glGetError()));
        out.push_back(glRenderMode(0x1234));
        out.push_back(static_cast<GLint>(glGetError()));
        glSelectBuffer(0, buffer);
        out.push_back(glRenderMode(GL_SELECT));  // no buffer: GL_INVALID_OPERATION, selecting all the same
        out.push_back(static_cast<GLint>(glGetError()));
        glPushName(4);
        glRasterPos2f(0.0f, 0.0f);
        out.push_back(glRenderMode(0x1234));  // ends selection before the enum is refused
        out.push_back(static_cast<GLint>(glGetError()));
        GLint mode = 0;
        glGetIntegerv(GL_RENDER_MODE, &mode);
        out.push_back(mode);
        out.push_back(glRenderMode(GL_RENDER));
        GLint depth = -7;
        glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
        out.push_back(depth);
        return out;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
}

TEST(Selection, PickingWithGluPickMatrixFindsTheObjectUnderTheCursor) {
    const auto results = onBothBackends<Selected>([] {
        Selected s;
        s.buffer.assign(64, 0);
        GLint viewport[4] = {0, 0, 16, 16};
        glSelectBuffer(64, s.buffer.data());
        glRenderMode(GL_SELECT);
        glInitNames();
        glPushName(0);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluPickMatrix(4.0, 4.0, 3.0, 3.0, viewport);
        glOrtho(-1, 1, -1, 1, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        for (GLuint i = 0; i < 4; ++i) {  // four squares, one per quadrant: the cursor is over the first
            glLoadName(i + 1);
            const float x = i % 2 ? 0.1f : -0.9f, y = i / 2 ? 0.1f : -0.9f;
            glRectf(x, y, x + 0.8f, y + 0.8f);
        }
        s.hits = glRenderMode(GL_RENDER);
        return s;
    });
    EXPECT_EQ(results.mygl, results.osmesa);
    EXPECT_EQ(results.osmesa.hits, 1);
    EXPECT_EQ(results.osmesa.buffer[3], 1u);
}
