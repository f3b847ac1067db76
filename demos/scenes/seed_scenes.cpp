// The course's rotating cube and the seed documents' occlusion scenes (../shared/seeds/000):
// two cubes at different depths, a concave hexahedron whose own faces overlap, and two
// intersecting quads that neither culling nor sorting can order. Each with depth on and off.
#include <glad/gl.h>
#include <mygl/glu.h>

#include <initializer_list>

#include "scene.h"
#include "seed_scenes.h"

namespace scenes {
namespace {

constexpr float kFaceColors[6][3] = {{0.9f, 0.2f, 0.2f},   {0.2f, 0.8f, 0.3f},   {0.25f, 0.35f, 0.95f},
                                     {0.95f, 0.85f, 0.2f}, {0.85f, 0.3f, 0.85f}, {0.2f, 0.85f, 0.85f}};

// The seed scenes color each face: flat shading, as the course drew them.
void perspective(int width, int height) {
    glShadeModel(GL_FLAT);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(45.0, static_cast<double>(width) / height, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(0.0, 1.5, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

// The near cube is drawn first: without the depth test the far one paints over it.
void twoCubes(int width, int height, bool depth) {
    beginFrame(width, height, depth, true);
    perspective(width, height);
    static const float white[1][3] = {{0.85f, 0.85f, 0.85f}};
    glPushMatrix();
    glTranslatef(-0.2f, -0.3f, 1.2f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    glScalef(0.6f, 0.6f, 0.6f);
    drawCube(kFaceColors);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.4f, 0.2f, -2.0f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
    drawCube(white, true);
    glPopMatrix();
}

// A cube with one corner pushed through to the inside: a hexahedron whose faces fold over
// each other, so back-face culling alone draws a wrong picture.
void concaveHexahedron(int width, int height, bool depth) {
    beginFrame(width, height, depth, true);
    perspective(width, height);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-60.0f, 0.0f, 1.0f, 0.0f);
    static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},          {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {0.3f, 0.4f, -0.7f}, {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    glBegin(GL_TRIANGLES);  // each face as two triangles: the faces are not planar any more
    for (int f = 0; f < 6; ++f) {
        glColor3fv(kFaceColors[f]);
        const int* q = faces[f];
        for (int i : {q[0], q[1], q[2], q[0], q[2], q[3]}) glVertex3fv(corners[i]);
    }
    glEnd();
}

// XMutual: two quads crossing each other in depth.
void intersectingQuads(int width, int height, bool depth) {
    beginFrame(width, height, depth, false);
    perspective(width, height);
    glBegin(GL_QUADS);
    glColor3f(0.95f, 0.45f, 0.1f);
    glVertex3f(-2.0f, -1.0f, -1.5f);
    glVertex3f(2.0f, -1.0f, 1.5f);
    glVertex3f(2.0f, 1.0f, 1.5f);
    glVertex3f(-2.0f, 1.0f, -1.5f);
    glColor3f(0.15f, 0.55f, 0.95f);
    glVertex3f(-2.0f, -0.7f, 1.5f);
    glVertex3f(2.0f, -0.7f, -1.5f);
    glVertex3f(2.0f, 1.3f, -1.5f);
    glVertex3f(-2.0f, 1.3f, 1.5f);
    glEnd();
}

}  // namespace

void drawRotatingCube(int width, int height, int frame) {
    beginFrame(width, height, true, true);
    perspective(width, height);
    glRotatef(static_cast<float>(frame) * 7.0f + 20.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(static_cast<float>(frame) * 3.0f + 15.0f, 1.0f, 0.0f, 0.0f);
    drawCube(kFaceColors);
}

void drawTwoCubesDepth(int w, int h, int) { twoCubes(w, h, true); }
void drawTwoCubesNoDepth(int w, int h, int) { twoCubes(w, h, false); }
void drawConcaveHexahedronDepth(int w, int h, int) { concaveHexahedron(w, h, true); }
void drawConcaveHexahedronNoDepth(int w, int h, int) { concaveHexahedron(w, h, false); }
void drawIntersectingQuadsDepth(int w, int h, int) { intersectingQuads(w, h, true); }
void drawIntersectingQuadsNoDepth(int w, int h, int) { intersectingQuads(w, h, false); }

}  // namespace scenes
