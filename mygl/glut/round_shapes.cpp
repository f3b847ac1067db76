// GLUT's round shapes from glBegin/glEnd, with outward unit normals: sphere, cone, torus and
// cylinder, in freeglut's placement (axes along z, cone and cylinder from z = 0 up to the
// height, torus around the z axis). Solids are quad strips between neighbouring circles, with
// fans for the caps; wire shapes draw the circles and the lines across them.
#include <mygl/glut.h>

#include <cmath>
#include <initializer_list>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct SurfacePoint {
    double p[3], n[3];
};

// A surface sampled at u = i / slices (around the z axis, counter-clockwise seen from +z) and
// v = j / stacks (along, going up).
template <class Point>
void solidSurface(GLint slices, GLint stacks, Point point) {
    for (GLint j = 0; j < stacks; ++j) {
        glBegin(GL_QUAD_STRIP);
        for (GLint i = 0; i <= slices; ++i) {
            for (GLint k : {j + 1, j}) {  // counter-clockwise seen from outside
                const SurfacePoint s = point(static_cast<double>(i) / slices, static_cast<double>(k) / stacks);
                glNormal3dv(s.n);
                glVertex3dv(s.p);
            }
        }
        glEnd();
    }
}

// The circles v = j / stacks for j in [firstStack, lastStack], and the lines u = i / slices
// from v = 0 to 1 (closed when `closedLines`).
template <class Point>
void wireSurface(GLint slices, GLint stacks, GLint firstStack, GLint lastStack, bool closedLines, Point point) {
    for (GLint j = firstStack; j <= lastStack; ++j) {
        glBegin(GL_LINE_LOOP);
        for (GLint i = 0; i < slices; ++i) {
            const SurfacePoint s = point(static_cast<double>(i) / slices, static_cast<double>(j) / stacks);
            glNormal3dv(s.n);
            glVertex3dv(s.p);
        }
        glEnd();
    }
    for (GLint i = 0; i < slices; ++i) {
        glBegin(closedLines ? GL_LINE_LOOP : GL_LINE_STRIP);
        for (GLint j = 0; j < (closedLines ? stacks : stacks + 1); ++j) {
            const SurfacePoint s = point(static_cast<double>(i) / slices, static_cast<double>(j) / stacks);
            glNormal3dv(s.n);
            glVertex3dv(s.p);
        }
        glEnd();
    }
}

// A flat disk at height z facing +z (up) or -z, as a fan around its centre.
void cap(double radius, double z, GLint slices, bool up) {
    glBegin(GL_TRIANGLE_FAN);
    glNormal3d(0, 0, up ? 1 : -1);
    glVertex3d(0, 0, z);
    for (GLint i = 0; i <= slices; ++i) {
        const double a = 2 * kPi * (up ? i : slices - i) / slices;
        glVertex3d(radius * std::cos(a), radius * std::sin(a), z);
    }
    glEnd();
}

bool valid(GLint slices, GLint stacks) { return slices >= 1 && stacks >= 1; }

auto spherePoint(double radius) {
    return [radius](double u, double v) {
        const double theta = 2 * kPi * u, phi = kPi * (1 - v);  // v = 0 at the -z pole, going up
        SurfacePoint s{{}, {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)}};
        for (int i = 0; i < 3; ++i) s.p[i] = radius * s.n[i];
        return s;
    };
}

auto conePoint(double base, double height) {
    const double slant = std::sqrt(height * height + base * base);
    return [=](double u, double v) {
        const double theta = 2 * kPi * u, r = base * (1 - v);
        return SurfacePoint{{r * std::cos(theta), r * std::sin(theta), height * v},
                            {height / slant * std::cos(theta), height / slant * std::sin(theta), base / slant}};
    };
}

auto torusPoint(double inner, double outer) {
    return [=](double u, double v) {
        const double theta = 2 * kPi * u, phi = 2 * kPi * v;
        const double ring = outer + inner * std::cos(phi);
        return SurfacePoint{{ring * std::cos(theta), ring * std::sin(theta), inner * std::sin(phi)},
                            {std::cos(theta) * std::cos(phi), std::sin(theta) * std::cos(phi), std::sin(phi)}};
    };
}

auto cylinderPoint(double radius, double height) {
    return [=](double u, double v) {
        const double theta = 2 * kPi * u;
        return SurfacePoint{{radius * std::cos(theta), radius * std::sin(theta), height * v},
                            {std::cos(theta), std::sin(theta), 0}};
    };
}

}  // namespace

void glutSolidSphere(double radius, GLint slices, GLint stacks) {
    if (valid(slices, stacks)) solidSurface(slices, stacks, spherePoint(radius));
}
void glutWireSphere(double radius, GLint slices, GLint stacks) {
    if (valid(slices, stacks)) wireSurface(slices, stacks, 1, stacks - 1, false, spherePoint(radius));
}

void glutSolidCone(double base, double height, GLint slices, GLint stacks) {
    if (!valid(slices, stacks)) return;
    solidSurface(slices, stacks, conePoint(base, height));
    cap(base, 0, slices, false);
}
void glutWireCone(double base, double height, GLint slices, GLint stacks) {
    if (valid(slices, stacks)) wireSurface(slices, stacks, 0, stacks - 1, false, conePoint(base, height));
}

// The torus's sides go around its tube (v), its rings around the z axis (u).
void glutSolidTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
    if (valid(rings, sides)) solidSurface(rings, sides, torusPoint(innerRadius, outerRadius));
}
void glutWireTorus(double innerRadius, double outerRadius, GLint sides, GLint rings) {
    if (valid(rings, sides)) wireSurface(rings, sides, 0, sides - 1, true, torusPoint(innerRadius, outerRadius));
}

void glutSolidCylinder(double radius, double height, GLint slices, GLint stacks) {
    if (!valid(slices, stacks)) return;
    solidSurface(slices, stacks, cylinderPoint(radius, height));
    cap(radius, 0, slices, false);
    cap(radius, height, slices, true);
}
void glutWireCylinder(double radius, double height, GLint slices, GLint stacks) {
    if (valid(slices, stacks)) wireSurface(slices, stacks, 0, stacks, false, cylinderPoint(radius, height));
}
