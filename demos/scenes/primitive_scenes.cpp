// Small scenes that exercise each glBegin mode, shading, clipping at the near plane, lines,
// points and polygon mode.
#include <glad/gl.h>
#include <mygl/glu.h>

#include <cmath>

#include "primitive_scenes.h"
#include "scene.h"

namespace scenes {
namespace {

void hue(int i) {
    const float t = static_cast<float>(i) * 0.37f;
    glColor3f(0.5f + 0.5f * std::sin(t), 0.5f + 0.5f * std::sin(t + 2.1f), 0.5f + 0.5f * std::sin(t + 4.2f));
}

// The six triangle modes in a 3x2 grid, each in a cell of the window.
void allModes(int width, int height, bool smooth) {
    beginFrame(width, height, false, false);
    glShadeModel(smooth ? GL_SMOOTH : GL_FLAT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 3.0, 0.0, 2.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    const GLenum modes[6] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
    for (int cell = 0; cell < 6; ++cell) {
        glPushMatrix();
        glTranslatef(static_cast<float>(cell % 3) + 0.5f, static_cast<float>(cell / 3) + 0.5f, 0.0f);
        glScalef(0.43f, 0.43f, 1.0f);
        glBegin(modes[cell]);
        for (int i = 0; i < 8; ++i) {
            hue(i + cell);
            const float angle = static_cast<float>(i) * 0.785398f + 0.13f * static_cast<float>(cell);
            const float radius =
                (modes[cell] == GL_TRIANGLE_STRIP || modes[cell] == GL_QUAD_STRIP) ? 1.0f : (i % 2 ? 0.62f : 1.0f);
            if (modes[cell] == GL_TRIANGLE_STRIP || modes[cell] == GL_QUAD_STRIP) {
                glVertex2f(-1.0f + 0.29f * static_cast<float>(i), i % 2 ? 0.8f : -0.7f + 0.05f * static_cast<float>(i));
            } else {
                glVertex2f(radius * std::cos(angle), radius * std::sin(angle));
            }
        }
        glEnd();
        glPopMatrix();
    }
}

}  // namespace

void drawSmoothFan(int width, int height, int) {
    beginFrame(width, height, false, false);
    pixelOrtho(width, height);
    const float cx = static_cast<float>(width) * 0.5f, cy = static_cast<float>(height) * 0.5f;
    const float r = 0.45f * static_cast<float>(std::min(width, height));
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(cx + 0.3f, cy - 0.2f);
    for (int i = 0; i <= 12; ++i) {
        hue(i);
        const float a = static_cast<float>(i) * 6.2831853f / 12.0f;
        glVertex2f(cx + r * std::cos(a), cy + r * std::sin(a));
    }
    glEnd();
}

void drawPolygon5(int width, int height, int) {
    beginFrame(width, height, false, false);
    pixelOrtho(width, height);
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    glShadeModel(GL_FLAT);
    glColor3f(1.0f, 0.0f, 0.0f);
    glBegin(GL_POLYGON);
    glVertex2f(0.2f * w, 0.15f * h);
    glVertex2f(0.8f * w, 0.2f * h);
    glVertex2f(0.9f * w, 0.6f * h);
    glVertex2f(0.5f * w, 0.9f * h);
    glVertex2f(0.12f * w, 0.55f * h);
    glEnd();
}

void drawNearPlaneMesh(int width, int height, int) {
    beginFrame(width, height, true, false);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(60.0, static_cast<double>(width) / height, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(0.0, 1.0, 0.5, 0.0, 0.6, -3.0, 0.0, 1.0, 0.0);
    // A floor from behind the eye to far ahead: rows cross the near plane and the sides.
    glBegin(GL_QUADS);
    for (int z = 0; z < 12; ++z) {
        for (int x = -6; x < 6; ++x) {
            hue(x * 3 + z);
            const float x0 = static_cast<float>(x), z0 = 2.0f - static_cast<float>(z);
            glVertex3f(x0, 0.0f, z0);
            glVertex3f(x0 + 1.0f, 0.0f, z0);
            hue(x * 3 + z + 5);
            glVertex3f(x0 + 1.0f, 0.0f, z0 - 1.0f);
            glVertex3f(x0, 0.0f, z0 - 1.0f);
        }
    }
    glEnd();
}

void drawAllModesFlat(int width, int height, int) { allModes(width, height, false); }
void drawAllModesSmooth(int width, int height, int) { allModes(width, height, true); }

void drawLinesAndPoints(int width, int height, int) {
    beginFrame(width, height, false, false);
    pixelOrtho(width, height);
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    for (int width_px = 1; width_px <= 3; ++width_px) {
        glLineWidth(static_cast<float>(width_px));
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= 10; ++i) {
            hue(i + width_px);
            glVertex2f(0.05f * w + 0.09f * w * static_cast<float>(i),
                       h * (0.2f * static_cast<float>(width_px) + 0.08f * std::sin(static_cast<float>(i))));
        }
        glEnd();
    }
    glLineWidth(1.0f);
    glBegin(GL_LINE_LOOP);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(0.1f * w, 0.85f * h);
    glVertex2f(0.4f * w, 0.95f * h);
    glVertex2f(0.3f * w, 0.75f * h);
    glEnd();
    for (int size = 1; size <= 4; ++size) {
        glPointSize(static_cast<float>(size));
        glBegin(GL_POINTS);
        for (int i = 0; i < 8; ++i) {
            hue(i * size);
            glVertex2f(0.55f * w + 0.05f * w * static_cast<float>(i) + 0.3f,
                       0.8f * h + 0.04f * h * static_cast<float>(size) + 0.2f);
        }
        glEnd();
    }
    glPointSize(1.0f);
}

void drawWireframeCube(int width, int height, int frame) {
    static const float colors[6][3] = {{0.9f, 0.2f, 0.2f},   {0.2f, 0.8f, 0.3f},   {0.25f, 0.35f, 0.95f},
                                       {0.95f, 0.85f, 0.2f}, {0.85f, 0.3f, 0.85f}, {0.2f, 0.85f, 0.85f}};
    beginFrame(width, height, true, true);
    glShadeModel(GL_FLAT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glMatrixMode(GL_PROJECTION);
    gluPerspective(45.0, static_cast<double>(width) / height, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(0.0, 1.5, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(static_cast<float>(frame) * 7.0f + 20.0f, 0.0f, 1.0f, 0.0f);
    drawCube(colors);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

}  // namespace scenes
