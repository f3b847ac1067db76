// GL errors on misuse, checked against what the GL spec says and against what OSMesa reports
// for the very same calls; the offending call must have no other effect.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "backends.h"

using testing_support::onBothBackends;

namespace {

struct Misuse {
    std::string name;
    GLenum expected;
    std::function<void()> calls;
    // Set where the reference departs from the spec: what it reports instead, and why.
    GLenum referenceReports = GL_NO_ERROR;
    const char* referenceDeparture = nullptr;
};

std::vector<Misuse> misuses() {
    return {
        {"glBegin with a bad mode", GL_INVALID_ENUM, [] { glBegin(0x20); }},
        {"glBegin inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_TRIANGLES);
             glBegin(GL_TRIANGLES);
             glEnd();
         }},
        {"glBegin with a bad mode inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_TRIANGLES);
             glBegin(0x20);
             glEnd();
         }},
        {"glEnd without glBegin", GL_INVALID_OPERATION, [] { glEnd(); }},
        {"glClear inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_POINTS);
             glClear(GL_COLOR_BUFFER_BIT);
             glEnd();
         }},
        {"glEnable inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_LINES);
             glEnable(GL_CULL_FACE);
             glEnd();
         }},
        {"glLoadIdentity inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_QUADS);
             glLoadIdentity();
             glEnd();
         }},
        {"glFinish inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_QUADS);
             glFinish();
             glEnd();
         }},
        {"glEnable of an unknown capability", GL_INVALID_ENUM, [] { glEnable(0x1234); }},
        {"glCullFace with a bad face", GL_INVALID_ENUM, [] { glCullFace(GL_TRIANGLES); }},
        {"glFrontFace with a bad mode", GL_INVALID_ENUM, [] { glFrontFace(GL_LINE); }},
        {"glDepthFunc with a bad function", GL_INVALID_ENUM, [] { glDepthFunc(GL_FRONT); }},
        {"glShadeModel with a bad mode", GL_INVALID_ENUM, [] { glShadeModel(GL_FILL); }},
        {"glPolygonMode with a bad mode", GL_INVALID_ENUM, [] { glPolygonMode(GL_FRONT_AND_BACK, GL_TRIANGLES); }},
        {"glMatrixMode with a bad mode", GL_INVALID_ENUM, [] { glMatrixMode(GL_LINE); }},
        {"glGetIntegerv of an unknown name", GL_INVALID_ENUM,
         [] {
             GLint v[16];
             glGetIntegerv(0x9999, v);
         }},
        {"glReadPixels with a bad format", GL_INVALID_ENUM,
         [] {
             GLubyte p[64];
             glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, p);
         }},
        {"glViewport with a negative width", GL_INVALID_VALUE, [] { glViewport(0, 0, -1, 5); }},
        {"glLineWidth of zero", GL_INVALID_VALUE, [] { glLineWidth(0.0f); }},
        {"glPointSize below zero", GL_INVALID_VALUE, [] { glPointSize(-1.0f); }},
        {"glFrustum with near = 0", GL_INVALID_VALUE, [] { glFrustum(-1, 1, -1, 1, 0, 10); }},
        {"glFrustum with left = right", GL_INVALID_VALUE, [] { glFrustum(1, 1, -1, 1, 1, 10); }},
        {"glOrtho with near = far", GL_INVALID_VALUE, [] { glOrtho(-1, 1, -1, 1, 2, 2); }},
        {"glFrustum with a near plane that is 0 in float", GL_INVALID_VALUE,
         [] { glFrustum(-1, 1, -1, 1, 1e-50, 10); }},
        {"glOrtho with left = right in float", GL_INVALID_VALUE, [] { glOrtho(0, 1e-46, -1, 1, -1, 1); }},
        {"glClear with unknown bits", GL_INVALID_VALUE, [] { glClear(0x1); }},
        {"glReadPixels with a negative size", GL_INVALID_VALUE,
         [] {
             GLubyte p[64];
             glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
         }},
        {"glReadPixels with a negative size and a bad format", GL_INVALID_VALUE,
         [] {
             GLubyte p[64];
             glReadPixels(0, 0, 1, -1, 0x1234, GL_UNSIGNED_BYTE, p);
         }},
        {"glReadPixels of colour indices from an RGBA buffer", GL_INVALID_OPERATION,
         [] {
             GLubyte p[64];
             glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, p);
         }},
        {"glReadPixels of colour indices from an RGBA buffer", GL_INVALID_OPERATION,
         [] {
             GLubyte p[64];
             glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, p);
         }},
        {"glLineWidth of NaN is stored, not an error", GL_NO_ERROR, [] { glLineWidth(std::nanf("")); }},
        {"glPointSize of NaN is stored, not an error", GL_NO_ERROR, [] { glPointSize(std::nanf("")); }},
        {"glPixelStorei with alignment 3", GL_INVALID_VALUE, [] { glPixelStorei(GL_PACK_ALIGNMENT, 3); }},
        {"glPopMatrix on an empty stack", GL_STACK_UNDERFLOW, [] { glPopMatrix(); }},
        {"glPushMatrix past the modelview depth", GL_STACK_OVERFLOW,
         [] {
             for (int i = 0; i < 32; ++i) glPushMatrix();
         }},
        {"glNewList with name 0", GL_INVALID_VALUE, [] { glNewList(0, GL_COMPILE); }},
        {"glNewList with a bad mode", GL_INVALID_ENUM, [] { glNewList(1, GL_FILL); }},
        {"glNewList while compiling", GL_INVALID_OPERATION,
         [] {
             glNewList(1, GL_COMPILE);
             glNewList(2, GL_COMPILE);
             glEndList();
         }},
        {"glNewList with name 0 while compiling", GL_INVALID_OPERATION,
         [] {
             glNewList(1, GL_COMPILE);
             glNewList(0, GL_COMPILE);
             glEndList();
         }},
        {"glNewList inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_POINTS);
             glNewList(1, GL_COMPILE);
             glEnd();
         }},
        {"glEndList without glNewList", GL_INVALID_OPERATION, [] { glEndList(); }},
        {"glGenLists of a negative range", GL_INVALID_VALUE, [] { glGenLists(-1); }},
        {"glDeleteLists of a negative range", GL_INVALID_VALUE, [] { glDeleteLists(1, -1); }},
        {"glCallLists with a bad type", GL_INVALID_ENUM,
         [] {
             const GLuint n[1] = {1};
             glCallLists(1, GL_DOUBLE, n);
         }},
        {"glCallLists with a negative count", GL_INVALID_VALUE,
         [] {
             const GLuint n[1] = {1};
             glCallLists(-1, GL_UNSIGNED_INT, n);
         }},
        {"glCallLists with a negative count and a bad type", GL_INVALID_ENUM,
         [] {
             const GLuint n[1] = {1};
             glCallLists(-1, GL_DOUBLE, n);
         }},
        {"glVertexPointer of size 1", GL_INVALID_VALUE, [] { glVertexPointer(1, GL_FLOAT, 0, nullptr); }},
        {"glVertexPointer of bytes", GL_INVALID_ENUM, [] { glVertexPointer(3, GL_UNSIGNED_BYTE, 0, nullptr); }},
        {"glColorPointer with a negative stride", GL_INVALID_VALUE, [] { glColorPointer(4, GL_FLOAT, -4, nullptr); }},
        {"glColorPointer of size 2 and a bad type", GL_INVALID_ENUM, [] { glColorPointer(2, GL_FALSE, 0, nullptr); }},
        {"glNormalPointer of unsigned bytes", GL_INVALID_ENUM, [] { glNormalPointer(GL_UNSIGNED_BYTE, 0, nullptr); }},
        {"glTexCoordPointer of size 5", GL_INVALID_VALUE, [] { glTexCoordPointer(5, GL_FLOAT, 0, nullptr); }},
        {"glEnableClientState of a capability", GL_INVALID_ENUM, [] { glEnableClientState(GL_DEPTH_TEST); }},
        {"glDrawArrays with a bad mode", GL_INVALID_ENUM, [] { glDrawArrays(0x20, 0, 3); }},
        {"glDrawArrays with a negative count", GL_INVALID_VALUE, [] { glDrawArrays(GL_TRIANGLES, 0, -3); }},
        // Compiled into a list, a draw's error is the list's when it runs (none at compile time).
        {"glDrawArrays with a bad mode run from a list", GL_INVALID_ENUM,
         [] {
             glNewList(1, GL_COMPILE);
             glDrawArrays(0x20, 0, 3);
             glEndList();
             glGetError();
             glCallList(1);
         }},
        {"glDrawElements with a negative count run from a list", GL_INVALID_VALUE,
         [] {
             const GLubyte i[1] = {0};
             glNewList(1, GL_COMPILE);
             glDrawElements(GL_POINTS, -1, GL_UNSIGNED_BYTE, i);
             glEndList();
             glGetError();
             glCallList(1);
         }},
        {"glDrawArrays inside glBegin", GL_INVALID_OPERATION,
         [] {
             glBegin(GL_POINTS);
             glDrawArrays(GL_POINTS, 0, 1);
             glEnd();
         }},
        {"glDrawElements with signed indices", GL_INVALID_ENUM,
         [] {
             const GLint i[3] = {0, 1, 2};
             glDrawElements(GL_TRIANGLES, 3, GL_INT, i);
         }},
        {"glDrawElements with a negative count", GL_INVALID_VALUE,
         [] {
             const GLuint i[3] = {0, 1, 2};
             glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_INT, i);
         }},
        {"glInterleavedArrays with a bad format", GL_INVALID_ENUM, [] { glInterleavedArrays(GL_RGBA, 0, nullptr); }},
        {"glGetPointerv of an unknown name", GL_INVALID_ENUM,
         [] {
             void* p;
             glGetPointerv(GL_VERTEX_ARRAY, &p);
         }},
        {"glHint of an unknown target", GL_INVALID_ENUM, [] { glHint(0, GL_NICEST); }},
        {"glHint with an unknown mode", GL_INVALID_ENUM, [] { glHint(GL_FOG_HINT, GL_FOG); }},
        {"the first error is kept", GL_INVALID_ENUM,
         [] {
             glEnable(0x1234);
             glViewport(0, 0, -1, -1);
         }},
    };
}

}  // namespace

TEST(GlErrors, MisuseReportsTheSpecErrorLikeTheReference) {
    for (const Misuse& misuse : misuses()) {
        const auto errors = onBothBackends<std::vector<GLenum>>([&] {
            const GLenum before = glGetError();
            misuse.calls();
            const GLenum first = glGetError();
            const GLenum second = glGetError();  // reading clears it
            return std::vector<GLenum>{before, first, second};
        });
        EXPECT_EQ(errors.mygl, (std::vector<GLenum>{GL_NO_ERROR, misuse.expected, GL_NO_ERROR})) << misuse.name;
        const GLenum referenceExpected = misuse.referenceDeparture ? misuse.referenceReports : misuse.expected;
        EXPECT_EQ(errors.osmesa, (std::vector<GLenum>{GL_NO_ERROR, referenceExpected, GL_NO_ERROR})) << misuse.name;
    }
}

TEST(GlErrors, OffendingCallsChangeNothing) {
    const auto state = onBothBackends<std::vector<GLint>>([] {
        glCullFace(GL_FRONT);
        glCullFace(GL_TRIANGLES);
        glDepthFunc(GL_GREATER);
        glDepthFunc(GL_FRONT);
        glViewport(1, 2, 3, 4);
        glViewport(0, 0, -1, 5);
        glMatrixMode(GL_PROJECTION);
        glMatrixMode(GL_LINE);
        glBegin(GL_TRIANGLES);
        glShadeModel(GL_FLAT);  // not allowed inside glBegin/glEnd
        glEnd();
        std::vector<GLint> v(8);
        glGetIntegerv(GL_CULL_FACE_MODE, &v[0]);
        glGetIntegerv(GL_DEPTH_FUNC, &v[1]);
        glGetIntegerv(GL_VIEWPORT, &v[2]);
        glGetIntegerv(GL_MATRIX_MODE, &v[6]);
        glGetIntegerv(GL_SHADE_MODEL, &v[7]);
        return v;
    });
    EXPECT_EQ(state.mygl, (std::vector<GLint>{GL_FRONT, GL_GREATER, 1, 2, 3, 4, GL_PROJECTION, GL_SMOOTH}));
    EXPECT_EQ(state.mygl, state.osmesa);
}

TEST(GlErrors, CallsWithoutACurrentContextDoNothing) {
    {
        mygl::Context context(8, 8);
        context.makeCurrent();
    }  // destroyed: the table still points at MyGL, but no context is current
    EXPECT_EQ(mygl::Context::current(), nullptr);
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, 0);
    glEnd();
    glClear(GL_COLOR_BUFFER_BIT);
    GLint viewport[4] = {7, 7, 7, 7};
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 7);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(GlErrors, UnknownEntryPointsAreNull) {
    EXPECT_EQ(mygl::getProcAddress("glNoSuchFunction"), nullptr);
    EXPECT_EQ(mygl::getProcAddress(nullptr), nullptr);
    EXPECT_NE(mygl::getProcAddress("glBegin"), nullptr);
}

namespace {
std::set<std::string> requested;
std::vector<std::string> unresolved;
GLADapiproc recordingLoader(const char* name) {
    requested.insert(name);
    const auto proc = reinterpret_cast<GLADapiproc>(mygl::getProcAddress(name));
    if (!proc) unresolved.emplace_back(name);
    return proc;
}
}  // namespace

TEST(GlErrors, EveryGl11FunctionHasAnEntryPoint) {
    mygl::Context context(8, 8);
    context.makeCurrent();
    requested.clear();
    unresolved.clear();
    ASSERT_NE(gladLoadGL(recordingLoader), 0);
    EXPECT_EQ(requested.size(), 336u);  // glad's GL 1.0 + 1.1, each once (glGetString is asked twice)
    EXPECT_EQ(unresolved, std::vector<std::string>{});
    context.makeCurrent();
}

TEST(Context, RejectsBadSizes) {
    EXPECT_THROW(mygl::Context(0, 10), std::invalid_argument);
    EXPECT_THROW(mygl::Context(10, -1), std::invalid_argument);
    EXPECT_THROW(mygl::Context(mygl::Context::kMaxSize + 1, 1), std::invalid_argument);
}
