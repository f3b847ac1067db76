// Probe: which diagonal does OSMesa split a quad along, per primitive and state?
// A 32x32 quad (4,4)-(28,28) whose depth is near at v0 and v2 and far at v1 and v3: the depth at
// pixel (16,16), on the v0-v2 diagonal, is near (< 0.5) when the quad is split v0-v2 and far when
// split v1-v3. glRect (whose z is flat) shows it with linear fog instead: tilted so that |eye z|
// is 1.5 at v0 and v2 and 0.5 at v1 and v3, the fogged white at (16,16) is dark for v0-v2.
// Columns: the primitive, the state, the shading and whether each vertex has its own colour, then
// OSMesa's split and MyGL's ("v0v2" / "v1v3"), and how many of the 32x32 pixels differ in colour
// or depth.
#include "backends.h"

#include <algorithm>
#include <cstdio>

using testing_support::Frame;
using testing_support::onBothBackends;
using testing_support::readFrame;

namespace {

enum class Prim { Quads, QuadStrip, Rect };
const char* const kPrimNames[] = {"GL_QUADS", "GL_QUAD_STRIP", "glRect+fog"};
const char* const kStateNames[] = {"plain",
                                   "polygon stipple",
                                   "line stipple 0x5555",
                                   "offset fill",
                                   "offset fill + line stipple 0x5555",
                                   "offset fill + line stipple 0xffff",
                                   "offset fill + line stipple 0",
                                   "offset fill + line stipple 0x0001",
                                   "line stipple 0",
                                   "offset fill + polygon stipple",
                                   "offset fill + line smooth",
                                   "offset fill + point smooth",
                                   "line smooth",
                                   "offset line",
                                   "cull back",
                                   "offset line + line stipple 0x5555",
                                   "offset point + point smooth"};
constexpr int kStates = 17;

void setState(int state) {
    const GLushort patterns[] = {0x5555, 0x5555, 0xffff, 0, 0x0001, 0};
    if (state == 2 || (state >= 4 && state <= 8)) {
        glLineStipple(1, patterns[state == 2 ? 0 : state - 3]);
        glEnable(GL_LINE_STIPPLE);
    }
    if (state == 1 || state == 9) glEnable(GL_POLYGON_STIPPLE);
    if ((state >= 3 && state <= 7) || (state >= 9 && state <= 11)) glEnable(GL_POLYGON_OFFSET_FILL);
    if (state == 10 || state == 12) glEnable(GL_LINE_SMOOTH);
    if (state == 11) glEnable(GL_POINT_SMOOTH);
    if (state == 13 || state == 15) glEnable(GL_POLYGON_OFFSET_LINE);
    if (state == 14) glEnable(GL_CULL_FACE);
    if (state == 15) {
        glLineStipple(1, 0x5555);
        glEnable(GL_LINE_STIPPLE);
    }
    if (state == 16) {
        glEnable(GL_POLYGON_OFFSET_POINT);
        glEnable(GL_POINT_SMOOTH);
    }
}

// The quad's corners in GL_QUADS order, z near on v0 and v2.
const float kCorner[4][3] = {{4, 4, 0.5f}, {28, 4, -0.5f}, {28, 28, 0.5f}, {4, 28, -0.5f}};

void vertex(int i, bool ownColors) {
    if (ownColors) glColor3f(i % 2 == 0 ? 1.0f : 0.0f, 0.5f, 0.5f);
    glVertex3fv(kCorner[i]);
}

Frame draw(Prim prim, int state, bool flat, bool ownColors) {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 32, 0, 32, -1, 1);  // z = 0.5 is window depth 0.25
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    setState(state);
    glColor3f(1, 1, 1);
    if (prim == Prim::Quads) {
        glBegin(GL_QUADS);
        for (int i = 0; i < 4; ++i) vertex(i, ownColors);
        glEnd();
    } else if (prim == Prim::QuadStrip) {
        glBegin(GL_QUAD_STRIP);  // strip order v0, v1, v3, v2
        for (int i : {0, 1, 3, 2}) vertex(i, ownColors);
        glEnd();
    } else {
        // Eye z = x + 0.5 y on [-1, 1]^2: |z| 1.5, 0.5, 1.5, 0.5 at the rect's corners.
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-1.2, 1.2, -1.2, 1.2, -3, 3);
        glMatrixMode(GL_MODELVIEW);
        const GLfloat m[16] = {1, 0, 1, 0, 0, 1, 0.5f, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        glLoadMatrixf(m);
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, 0);
        glFogf(GL_FOG_END, 2);
        glRectf(-1, -1, 1, 1);
    }
    return readFrame(32, 32);
}

// The split pixel (16, 16) shows: its depth for quads and strips, its fogged red for glRect.
const char* split(Prim prim, const Frame& frame) {
    constexpr int kCentre = 16 * 32 + 16;
    if (prim == Prim::Rect) {
        const int red = frame.color[kCentre * 4];
        return red == 0 ? "none" : red < 128 ? "v0v2" : "v1v3";
    }
    const double depth = (frame.depth[kCentre] >> 8) / 16777215.0;
    return depth >= 1.0 ? "none" : depth < 0.5 ? "v0v2" : "v1v3";
}

int differing(const Frame& a, const Frame& b) {
    int count = 0;
    for (std::size_t i = 0; i < a.depth.size(); ++i)
        count += a.depth[i] != b.depth[i] || !std::equal(&a.color[i * 4], &a.color[i * 4 + 4], &b.color[i * 4]);
    return count;
}

}  // namespace

int main() {
    for (Prim prim : {Prim::Quads, Prim::QuadStrip, Prim::Rect})
        for (int state = 0; state < kStates; ++state)
            for (bool flat : {false, true})
                for (bool own : {false, true}) {
                    if (prim == Prim::Rect && own) continue;
                    const auto r = onBothBackends<Frame>([&] { return draw(prim, state, flat, own); }, 32, 32);
                    std::printf("%-14s %-34s %-6s %-10s osmesa %s mygl %s, %d px differ\n",
                                kPrimNames[static_cast<int>(prim)], kStateNames[state], flat ? "flat" : "smooth",
                                own ? "own colors" : "one color", split(prim, r.osmesa), split(prim, r.mygl),
                                differing(r.mygl, r.osmesa));
                }
}
