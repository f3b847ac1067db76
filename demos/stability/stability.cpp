#include "stability.h"

#include <glad/gl.h>
#include <mygl/context.h>
#include <mygl/glu.h>
#include <reference/compare.h>
#include <reference/osmesa_context.h>
#include <scene.h>

#include <cmath>
#include <initializer_list>
#include <random>

namespace stability {
namespace {

constexpr int kWidth = 96, kHeight = 72;

using glrenderer::CullMethod;
using glrenderer::HiddenSurface;
using glrenderer::Interpolation;
using glrenderer::RasterMethod;

// Flat shading unless a check asks for colors.
void reset(int width, int height) {
    scenes::resetState(width, height);
    glShadeModel(GL_FLAT);
}

using scenes::pixelOrtho;

void color(int i) {
    const float t = static_cast<float>(i) * 0.77f;
    glColor3f(0.5f + 0.45f * std::sin(t), 0.5f + 0.45f * std::sin(t + 2.1f), 0.5f + 0.45f * std::sin(t + 4.2f));
}

// A mesh whose vertices sit on pixel centers and half-pixel jitters: shared edges run exactly
// through pixel centers, where a fill rule must give each center to exactly one triangle.
// Drawn with a constant color, so a double hit is invisible: the fragment count shows it.
void sharedEdges(int w, int h) {
    reset(w, h);
    pixelOrtho(w, h);
    std::mt19937 random(3);
    std::uniform_int_distribution<int> jitter(-2, 2);
    constexpr int kGrid = 6;
    float x[kGrid + 1][kGrid + 1], y[kGrid + 1][kGrid + 1];
    for (int j = 0; j <= kGrid; ++j)
        for (int i = 0; i <= kGrid; ++i) {
            const bool border = i == 0 || j == 0 || i == kGrid || j == kGrid;
            x[j][i] = 4.5f + static_cast<float>(i * 14) + (border ? 0.0f : static_cast<float>(jitter(random)) * 0.5f);
            y[j][i] = 4.5f + static_cast<float>(j * 10) + (border ? 0.0f : static_cast<float>(jitter(random)) * 0.5f);
        }
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i) {
            color(i + j * 7);
            glVertex2f(x[j][i], y[j][i]);
            glVertex2f(x[j][i + 1], y[j][i + 1]);
            glVertex2f(x[j + 1][i + 1], y[j + 1][i + 1]);
            color(i + j * 7 + 3);
            glVertex2f(x[j][i], y[j][i]);
            glVertex2f(x[j + 1][i + 1], y[j + 1][i + 1]);
            glVertex2f(x[j + 1][i], y[j + 1][i]);
        }
    glEnd();
}

void slivers(int w, int h) {
    reset(w, h);
    pixelOrtho(w, h);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 40; ++i) {
        color(i);
        const float x0 = u(random) * static_cast<float>(w), y0 = u(random) * static_cast<float>(h);
        const float a = u(random) * 6.2832f, length = 30.0f + 40.0f * u(random), thickness = 0.02f + 0.3f * u(random);
        glVertex2f(x0, y0);
        glVertex2f(x0 + length * std::cos(a), y0 + length * std::sin(a));
        glVertex2f(x0 + 0.5f * length * std::cos(a) - thickness * std::sin(a),
                   y0 + 0.5f * length * std::sin(a) + thickness * std::cos(a));
    }
    glEnd();
}

// Triangles smaller than a pixel, most covering no pixel center at all.
void tinyTriangles(int w, int h) {
    reset(w, h);
    pixelOrtho(w, h);
    std::mt19937 random(8);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 400; ++i) {
        color(i);
        const float x0 = u(random) * static_cast<float>(w), y0 = u(random) * static_cast<float>(h),
                    s = 0.1f + 0.6f * u(random);
        glVertex2f(x0, y0);
        glVertex2f(x0 + s, y0 + 0.2f * s);
        glVertex2f(x0 + 0.3f * s, y0 + s);
    }
    glEnd();
}

// The same small triangles far from the origin: the projection follows them, so the picture
// should not change; float precision at the offset is what may move edges.
void offsetTriangles(int w, int h, double offset) {
    reset(w, h);
    glMatrixMode(GL_PROJECTION);
    glOrtho(offset, offset + w, offset, offset + h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glTranslated(offset, offset, 0.0);
    std::mt19937 random(13);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 30; ++i) {
        color(i);
        const float x0 = u(random) * static_cast<float>(w), y0 = u(random) * static_cast<float>(h);
        glVertex2f(x0, y0);
        glVertex2f(x0 + 9.3f * u(random) + 2.0f, y0 + 3.1f * u(random));
        glVertex2f(x0 + 2.2f * u(random), y0 + 8.7f * u(random) + 2.0f);
    }
    glEnd();
}

// One scene at ten sub-pixel shifts, overlaid: every shift must cover what the reference covers.
void subpixelJitter(int w, int h) {
    reset(w, h);
    pixelOrtho(w, h);
    for (int k = 0; k < 10; ++k) {
        glLoadIdentity();
        glTranslatef(0.1f * static_cast<float>(k) + 0.013f, 0.07f * static_cast<float>(k), 0.0f);
        glBegin(GL_TRIANGLES);
        color(k);
        glVertex2f(5.0f + 8.0f * static_cast<float>(k), 10.0f);
        glVertex2f(11.0f + 8.0f * static_cast<float>(k), 12.3f);
        glVertex2f(7.6f + 8.0f * static_cast<float>(k), 60.0f);
        glEnd();
    }
}

void nearPlane(int w, int h) {
    reset(w, h);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(70.0, static_cast<double>(w) / h, 0.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLES);  // from behind the eye to well in front of it
    glColor3f(1, 0, 0);
    glVertex3f(-2.0f, -1.0f, 1.0f);
    glColor3f(0, 1, 0);
    glVertex3f(2.0f, -1.0f, -3.0f);
    glColor3f(0, 0, 1);
    glVertex3f(0.0f, 1.5f, -6.0f);
    glColor3f(1, 1, 0);
    glVertex3f(-1.0f, 0.5f, 3.0f);
    glColor3f(0, 1, 1);
    glVertex3f(1.5f, 0.8f, -2.0f);
    glColor3f(1, 0, 1);
    glVertex3f(-1.5f, -0.8f, -1.0f);
    glEnd();
}

// A concave polygon: GL defines it as the fan from v0, which covers outside the outline.
void concavePolygon(int w, int h) {
    reset(w, h);
    pixelOrtho(w, h);
    glColor3f(1, 0.3f, 0.2f);
    glBegin(GL_POLYGON);
    const float points[6][2] = {{10, 8}, {80, 10}, {40, 30}, {85, 62}, {12, 60}, {30, 35}};
    for (const auto& p : points) glVertex2f(p[0], p[1]);
    glEnd();
}

// Two quads crossing each other, with GL_DEPTH_TEST on: only per-pixel depth orders them.
void intersectingQuads(int w, int h) {
    reset(w, h);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(45.0, static_cast<double>(w) / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -6);
    glBegin(GL_QUADS);
    glColor3f(0.95f, 0.45f, 0.1f);
    glVertex3f(-2, -1, -1.5f);
    glVertex3f(2, -1, 1.5f);
    glVertex3f(2, 1, 1.5f);
    glVertex3f(-2, 1, -1.5f);
    glColor3f(0.15f, 0.55f, 0.95f);
    glVertex3f(-2, -0.7f, 1.5f);
    glVertex3f(2, -0.7f, -1.5f);
    glVertex3f(2, 1.3f, -1.5f);
    glVertex3f(-2, 1.3f, 1.5f);
    glEnd();
}

// The seed's concave hexahedron (a cube with one corner pushed inside), depth test on and no
// culling: its faces overlap each other, so drawing whole faces far to near cannot be right.
void concaveHexahedron(int w, int h) {
    reset(w, h);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(45.0, static_cast<double>(w) / h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -5.5f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-60.0f, 0.0f, 1.0f, 0.0f);
    static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},          {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {0.3f, 0.4f, -0.7f}, {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    glBegin(GL_TRIANGLES);
    for (int f = 0; f < 6; ++f) {
        color(f * 2);
        const int* q = faces[f];
        for (int i : {q[0], q[1], q[2], q[0], q[2], q[3]}) glVertex3fv(corners[i]);
    }
    glEnd();
}

// A ring of outward-facing quads around the eye under a 120-degree field of view, culled:
// which faces are front depends on the direction to each face, not only on the look vector.
void widePerspectiveCulling(int w, int h) {
    reset(w, h);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(120.0, static_cast<double>(w) / h, 0.5, 50.0);
    glMatrixMode(GL_MODELVIEW);
    for (int i = 0; i < 9; ++i) {  // boxes spread across the wide view, seen from inside the cone
        glPushMatrix();
        glTranslatef(-8.0f + 2.0f * static_cast<float>(i), -1.0f, -4.0f);
        glBegin(GL_QUADS);
        const float faces[3][3] = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}};  // front, right, left faces
        for (int f = 0; f < 3; ++f) {
            color(i * 3 + f);
            const float* n = faces[f];
            glNormal3fv(n);
            const float ux = n[2] != 0 ? 1.0f : 0.0f, uz = n[0];  // a tangent of the face
            for (const auto& [s, t] :
                 {std::pair{-0.5f, -0.5f}, std::pair{0.5f, -0.5f}, std::pair{0.5f, 0.5f}, std::pair{-0.5f, 0.5f}}) {
                const float sx = n[0] != 0 ? 0.0f : s * ux * (n[2] > 0 ? 1.0f : -1.0f);
                const float sz = n[0] != 0 ? -s * uz : 0.0f;
                glVertex3f(0.5f * n[0] + sx, t, 0.5f * n[2] + sz);
            }
        }
        glEnd();
        glPopMatrix();
    }
}

struct Frame {
    reference::Image image;
    std::vector<std::uint32_t> depth;
};

// The current context's frame: colors from `rgba`, depth through the GL table.
Frame currentFrame(std::vector<std::uint8_t> rgba) {
    Frame frame;
    frame.image.width = kWidth;
    frame.image.height = kHeight;
    frame.image.rgba = std::move(rgba);
    frame.depth = scenes::readDepth(kWidth, kHeight);
    return frame;
}

}  // namespace

std::vector<Method> allMethods() {
    using M = glrenderer::Methods;
    return {
        {"exact", M{}},
        {"scanline", M{RasterMethod::Scanline, Interpolation::PerspectiveCorrect, CullMethod::WindowArea,
                       HiddenSurface::AsEnabled}},
        {"bbox-float", M{RasterMethod::BoundingBoxFloat, Interpolation::PerspectiveCorrect, CullMethod::WindowArea,
                         HiddenSurface::AsEnabled}},
        {"screen-linear",
         M{RasterMethod::Exact, Interpolation::ScreenLinear, CullMethod::WindowArea, HiddenSurface::AsEnabled}},
        {"view-space-cull", M{RasterMethod::Exact, Interpolation::PerspectiveCorrect, CullMethod::ViewSpaceNormal,
                              HiddenSurface::AsEnabled}},
        {"look-vector-cull",
         M{RasterMethod::Exact, Interpolation::PerspectiveCorrect, CullMethod::LookVector, HiddenSurface::AsEnabled}},
        {"painters-sort", M{RasterMethod::Exact, Interpolation::PerspectiveCorrect, CullMethod::WindowArea,
                            HiddenSurface::PaintersSort}},
    };
}

std::vector<Check> allChecks() {
    return {
        {"shared edges", sharedEdges},
        {"slivers", slivers},
        {"tiny triangles", tinyTriangles},
        {"offset 1e3", [](int w, int h) { offsetTriangles(w, h, 1e3); }},
        {"offset 1e5", [](int w, int h) { offsetTriangles(w, h, 1e5); }},
        {"offset 1e7", [](int w, int h) { offsetTriangles(w, h, 1e7); }},
        {"sub-pixel jitter", subpixelJitter},
        {"near plane", nearPlane},
        {"concave polygon", concavePolygon},
        {"intersecting quads", intersectingQuads},
        {"concave hexahedron", concaveHexahedron},
        {"wide perspective culling", widePerspectiveCulling},
    };
}

Outcome run(const Check& check, const Method& method) {
    mygl::Context ours(kWidth, kHeight);
    ours.setMethods(method.methods);
    ours.makeCurrent();
    check.draw(kWidth, kHeight);
    const Frame mine = currentFrame(ours.readPixels());
    const std::uint64_t fragments = ours.stats().fragments;
    reference::OsmesaContext theirs(kWidth, kHeight);
    theirs.makeCurrent();
    check.draw(kWidth, kHeight);
    const Frame ref = currentFrame(theirs.readPixels());
    const reference::Comparison c = reference::compareImages(mine.image, ref.image);
    const long long over = c.differingMoreThan1 - reference::depthTies(mine.image, ref.image, mine.depth, ref.depth, 1);
    // Without the depth test every fragment is written: more fragments than the reference has
    // covered pixels means some pixel was drawn twice (a double hit on a shared edge).
    long long covered = 0;
    for (std::size_t i = 3; i < ref.image.rgba.size(); i += 4) covered += ref.image.rgba[i] != 0;
    const bool doubleHits = check.name == "shared edges" && static_cast<long long>(fragments) > covered;
    return {over == 0 && !doubleHits, over};
}

}  // namespace stability
