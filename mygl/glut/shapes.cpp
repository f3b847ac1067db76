// GLUT's shapes from glBegin/glEnd, with outward normals and counter-clockwise front faces.
#include <mygl/glut.h>

#include <cmath>
#include <initializer_list>

namespace {

constexpr double kPi = 3.14159265358979323846;

void cube(GLdouble size, GLenum mode) {
    const GLdouble h = size / 2;
    static const GLdouble normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    const GLdouble corners[8][3] = {{-h, -h, -h}, {h, -h, -h}, {h, h, -h}, {-h, h, -h},
                                    {-h, -h, h},  {h, -h, h},  {h, h, h},  {-h, h, h}};
    for (int f = 0; f < 6; ++f) {
        glBegin(mode);
        glNormal3dv(normals[f]);
        for (int corner : faces[f]) glVertex3dv(corners[corner]);
        glEnd();
    }
}

// A surface of revolution sampled on a (slices x stacks) grid, point(u, v) with its normal.
template <class Point>
void grid(GLint slices, GLint stacks, bool wire, Point point) {
    for (GLint j = 0; j < stacks; ++j) {
        glBegin(wire ? GL_LINE_LOOP : GL_QUAD_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
            for (GLint k : {j + 1, j}) {  // counter-clockwise seen from outside
                double p[3], n[3];
                point(static_cast<double>(i) / slices, static_cast<double>(k) / stacks, p, n);
                glNormal3dv(n);
                glVertex3dv(p);
            }
        }
        glEnd();
    }
}

void sphere(GLdouble radius, GLint slices, GLint stacks, bool wire) {
    grid(slices, stacks, wire, [radius](double u, double v, double* p, double* n) {
        const double theta = 2 * kPi * u, phi = kPi * v;
        n[0] = std::sin(phi) * std::cos(theta), n[1] = std::sin(phi) * std::sin(theta), n[2] = std::cos(phi);
        for (int i = 0; i < 3; ++i) p[i] = radius * n[i];
    });
}

void torus(GLdouble inner, GLdouble outer, GLint sides, GLint rings, bool wire) {
    grid(rings, sides, wire, [inner, outer](double u, double v, double* p, double* n) {
        const double theta = 2 * kPi * u, phi = 2 * kPi * v;
        n[0] = std::cos(theta) * std::cos(phi), n[1] = std::sin(theta) * std::cos(phi), n[2] = std::sin(phi);
        p[0] = (outer + inner * std::cos(phi)) * std::cos(theta);
        p[1] = (outer + inner * std::cos(phi)) * std::sin(theta);
        p[2] = inner * std::sin(phi);
    });
}

void cone(GLdouble base, GLdouble height, GLint slices, GLint stacks, bool wire) {
    const double slant = std::sqrt(height * height + base * base);
    grid(slices, stacks, wire, [=](double u, double v, double* p, double* n) {
        const double theta = 2 * kPi * u, r = base * (1 - v);
        p[0] = r * std::cos(theta), p[1] = r * std::sin(theta), p[2] = height * v;
        n[0] = height / slant * std::cos(theta), n[1] = height / slant * std::sin(theta), n[2] = base / slant;
    });
}

}  // namespace

void glutSolidCube(GLdouble size) { cube(size, GL_QUADS); }
void glutWireCube(GLdouble size) { cube(size, GL_LINE_LOOP); }
void glutSolidSphere(GLdouble r, GLint slices, GLint stacks) { sphere(r, slices, stacks, false); }
void glutWireSphere(GLdouble r, GLint slices, GLint stacks) { sphere(r, slices, stacks, true); }
void glutSolidTorus(GLdouble in, GLdouble out, GLint sides, GLint rings) { torus(in, out, sides, rings, false); }
void glutWireTorus(GLdouble in, GLdouble out, GLint sides, GLint rings) { torus(in, out, sides, rings, true); }
void glutSolidCone(GLdouble base, GLdouble h, GLint slices, GLint stacks) { cone(base, h, slices, stacks, false); }
void glutWireCone(GLdouble base, GLdouble h, GLint slices, GLint stacks) { cone(base, h, slices, stacks, true); }
