// GLUT's teapot: Newell's bicubic Bezier patches (public domain), evaluated on a grid with
// normals and texture coordinates, turned to stand on the xz plane and scaled as GLUT does
// (rotated 270 degrees about x, half of `size`, lowered by 1.5 before the turn). As in GLUT its
// front faces are wound clockwise.
#include <mygl/glut.h>

#include <array>
#include <cmath>

namespace {

using Vec = std::array<double, 3>;
using Patch = std::array<Vec, 16>;  // 4 rows of 4 control points

// Newell's teapot, one quarter of the rotationally symmetric parts (rim, body, lid, bottom:
// the other quarters are these turned by 90, 180 and 270 degrees about z) and one half of the
// handle and the spout (the other half mirrored in y).
constexpr int kQuarterPatches = 6, kHalfPatches = 4;
const Patch kQuarters[kQuarterPatches] = {
    {{{1.4, 0, 2.4},
      {1.4, -0.784, 2.4},
      {0.784, -1.4, 2.4},
      {0, -1.4, 2.4},  // rim
      {1.3375, 0, 2.53125},
      {1.3375, -0.749, 2.53125},
      {0.749, -1.3375, 2.53125},
      {0, -1.3375, 2.53125},
      {1.4375, 0, 2.53125},
      {1.4375, -0.805, 2.53125},
      {0.805, -1.4375, 2.53125},
      {0, -1.4375, 2.53125},
      {1.5, 0, 2.4},
      {1.5, -0.84, 2.4},
      {0.84, -1.5, 2.4},
      {0, -1.5, 2.4}}},
    {{{1.5, 0, 2.4},
      {1.5, -0.84, 2.4},
      {0.84, -1.5, 2.4},
      {0, -1.5, 2.4},  // upper body
      {1.75, 0, 1.875},
      {1.75, -0.98, 1.875},
      {0.98, -1.75, 1.875},
      {0, -1.75, 1.875},
      {2, 0, 1.35},
      {2, -1.12, 1.35},
      {1.12, -2, 1.35},
      {0, -2, 1.35},
      {2, 0, 0.9},
      {2, -1.12, 0.9},
      {1.12, -2, 0.9},
      {0, -2, 0.9}}},
    {{{2, 0, 0.9},
      {2, -1.12, 0.9},
      {1.12, -2, 0.9},
      {0, -2, 0.9},  // lower body
      {2, 0, 0.45},
      {2, -1.12, 0.45},
      {1.12, -2, 0.45},
      {0, -2, 0.45},
      {1.5, 0, 0.225},
      {1.5, -0.84, 0.225},
      {0.84, -1.5, 0.225},
      {0, -1.5, 0.225},
      {1.5, 0, 0.15},
      {1.5, -0.84, 0.15},
      {0.84, -1.5, 0.15},
      {0, -1.5, 0.15}}},
    {{{0, 0, 3.15},
      {0, 0, 3.15},
      {0, 0, 3.15},
      {0, 0, 3.15},  // lid knob
      {0.8, 0, 3.15},
      {0.8, -0.45, 3.15},
      {0.45, -0.8, 3.15},
      {0, -0.8, 3.15},
      {0, 0, 2.85},
      {0, 0, 2.85},
      {0, 0, 2.85},
      {0, 0, 2.85},
      {0.2, 0, 2.7},
      {0.2, -0.112, 2.7},
      {0.112, -0.2, 2.7},
      {0, -0.2, 2.7}}},
    {{{0.2, 0, 2.7},
      {0.2, -0.112, 2.7},
      {0.112, -0.2, 2.7},
      {0, -0.2, 2.7},  // lid
      {0.4, 0, 2.55},
      {0.4, -0.224, 2.55},
      {0.224, -0.4, 2.55},
      {0, -0.4, 2.55},
      {1.3, 0, 2.55},
      {1.3, -0.728, 2.55},
      {0.728, -1.3, 2.55},
      {0, -1.3, 2.55},
      {1.3, 0, 2.4},
      {1.3, -0.728, 2.4},
      {0.728, -1.3, 2.4},
      {0, -1.3, 2.4}}},
    {{{0, 0, 0},
      {0, 0, 0},
      {0, 0, 0},
      {0, 0, 0},  // bottom
      {1.425, 0, 0},
      {1.425, 0.798, 0},
      {0.798, 1.425, 0},
      {0, 1.425, 0},
      {1.5, 0, 0.075},
      {1.5, 0.84, 0.075},
      {0.84, 1.5, 0.075},
      {0, 1.5, 0.075},
      {1.5, 0, 0.15},
      {1.5, 0.84, 0.15},
      {0.84, 1.5, 0.15},
      {0, 1.5, 0.15}}},
};
const Patch kHalves[kHalfPatches] = {
    {{{-1.6, 0, 2.025},
      {-1.6, -0.3, 2.025},
      {-1.5, -0.3, 2.25},
      {-1.5, 0, 2.25},  // upper handle
      {-2.3, 0, 2.025},
      {-2.3, -0.3, 2.025},
      {-2.5, -0.3, 2.25},
      {-2.5, 0, 2.25},
      {-2.7, 0, 2.025},
      {-2.7, -0.3, 2.025},
      {-3, -0.3, 2.25},
      {-3, 0, 2.25},
      {-2.7, 0, 1.8},
      {-2.7, -0.3, 1.8},
      {-3, -0.3, 1.8},
      {-3, 0, 1.8}}},
    {{{-2.7, 0, 1.8},
      {-2.7, -0.3, 1.8},
      {-3, -0.3, 1.8},
      {-3, 0, 1.8},  // lower handle
      {-2.7, 0, 1.575},
      {-2.7, -0.3, 1.575},
      {-3, -0.3, 1.35},
      {-3, 0, 1.35},
      {-2.5, 0, 1.125},
      {-2.5, -0.3, 1.125},
      {-2.65, -0.3, 0.9375},
      {-2.65, 0, 0.9375},
      {-2, 0, 0.9},
      {-2, -0.3, 0.9},
      {-1.9, -0.3, 0.6},
      {-1.9, 0, 0.6}}},
    {{{1.7, 0, 1.425},
      {1.7, -0.66, 1.425},
      {1.7, -0.66, 0.6},
      {1.7, 0, 0.6},  // spout body
      {2.6, 0, 1.425},
      {2.6, -0.66, 1.425},
      {3.1, -0.66, 0.825},
      {3.1, 0, 0.825},
      {2.3, 0, 2.1},
      {2.3, -0.25, 2.1},
      {2.4, -0.25, 2.025},
      {2.4, 0, 2.025},
      {2.7, 0, 2.4},
      {2.7, -0.25, 2.4},
      {3.3, -0.25, 2.4},
      {3.3, 0, 2.4}}},
    {{{2.7, 0, 2.4},
      {2.7, -0.25, 2.4},
      {3.3, -0.25, 2.4},
      {3.3, 0, 2.4},  // spout tip
      {2.8, 0, 2.475},
      {2.8, -0.25, 2.475},
      {3.525, -0.25, 2.49375},
      {3.525, 0, 2.49375},
      {2.9, 0, 2.475},
      {2.9, -0.15, 2.475},
      {3.45, -0.15, 2.5125},
      {3.45, 0, 2.5125},
      {2.8, 0, 2.4},
      {2.8, -0.15, 2.4},
      {3.2, -0.15, 2.4},
      {3.2, 0, 2.4}}},
};

// The quarter turned by `quarters` * -90 degrees about z, or the half mirrored in y (columns
// reversed, so that the mirrored patch keeps its winding).
Patch turned(const Patch& p, int quarters) {
    Patch r = p;
    for (Vec& c : r)
        for (int q = 0; q < quarters; ++q) c = {c[1], -c[0], c[2]};
    return r;
}
Patch mirrored(const Patch& p) {
    Patch r;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
            const Vec& c = p[static_cast<std::size_t>(row * 4 + 3 - column)];
            r[static_cast<std::size_t>(row * 4 + column)] = {c[0], -c[1], c[2]};
        }
    return r;
}

// Bernstein weights of a cubic and their derivatives at t.
void bernstein(double t, double b[4], double d[4]) {
    const double s = 1 - t;
    b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
    d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
}

struct Sample {
    Vec position, normal;
};

// The point at (u along a row, v down the rows) and its normal. Where the patch folds to a
// point (the lid's knob, the bottom's centre) the normal is taken a little way in.
Sample evaluate(const Patch& p, double u, double v) {
    double bu[4], du[4], bv[4], dv[4];
    bernstein(u, bu, du);
    bernstein(v, bv, dv);
    Sample s{{0, 0, 0}, {0, 0, 0}};
    Vec tu{0, 0, 0}, tv{0, 0, 0};
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) {
            const Vec& c = p[static_cast<std::size_t>(row * 4 + column)];
            for (int k = 0; k < 3; ++k) {
                s.position[static_cast<std::size_t>(k)] += bv[row] * bu[column] * c[static_cast<std::size_t>(k)];
                tu[static_cast<std::size_t>(k)] += bv[row] * du[column] * c[static_cast<std::size_t>(k)];
                tv[static_cast<std::size_t>(k)] += dv[row] * bu[column] * c[static_cast<std::size_t>(k)];
            }
        }
    Vec n{tu[1] * tv[2] - tu[2] * tv[1], tu[2] * tv[0] - tu[0] * tv[2], tu[0] * tv[1] - tu[1] * tv[0]};
    double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length < 1e-9) {
        const Sample inside = evaluate(p, u, v < 0.5 ? v + 1e-3 : v - 1e-3);
        s.normal = inside.normal;
        return s;
    }
    for (double& x : n) x /= length;
    s.normal = n;
    return s;
}

// GLUT's placement: x stays, y = z - 1.5 (up), z = -y; all times size / 2.
void vertex(const Sample& s, double size, double u, double v) {
    const double h = size / 2;
    glTexCoord2d(u, v);
    glNormal3d(s.normal[0], s.normal[2], -s.normal[1]);
    glVertex3d(h * s.position[0], h * (s.position[2] - 1.5), -h * s.position[1]);
}

void drawPatch(const Patch& p, double size, int grid, bool wire) {
    auto at = [grid](int i) { return static_cast<double>(i) / grid; };
    if (wire) {
        for (int j = 0; j <= grid; ++j) {  // lines of constant v, then of constant u
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i <= grid; ++i) vertex(evaluate(p, at(i), at(j)), size, at(i), at(j));
            glEnd();
        }
        for (int i = 0; i <= grid; ++i) {
            glBegin(GL_LINE_STRIP);
            for (int j = 0; j <= grid; ++j) vertex(evaluate(p, at(i), at(j)), size, at(i), at(j));
            glEnd();
        }
        return;
    }
    for (int j = 0; j < grid; ++j) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= grid; ++i) {
            vertex(evaluate(p, at(i), at(j)), size, at(i), at(j));
            vertex(evaluate(p, at(i), at(j + 1)), size, at(i), at(j + 1));
        }
        glEnd();
    }
}

void teapot(double size, int grid, bool wire) {
    for (const Patch& quarter : kQuarters)
        for (int q = 0; q < 4; ++q) drawPatch(turned(quarter, q), size, grid, wire);
    for (const Patch& half : kHalves) {
        drawPatch(half, size, grid, wire);
        drawPatch(mirrored(half), size, grid, wire);
    }
}

// GLUT's grids: 14 steps a patch for the solid teapot, 10 for the wire one.
constexpr int kSolidGrid = 14, kWireGrid = 10;

}  // namespace

void glutSolidTeapot(double size) { teapot(size, kSolidGrid, false); }
void glutWireTeapot(double size) { teapot(size, kWireGrid, true); }
