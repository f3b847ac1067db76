// Quadric objects: creation, the draw style / orientation / normals / texture settings, errors.
#include "quadric.h"

#include <cmath>
#include <new>

namespace mygl::glu {

void quadricError(const GLUquadric& quadric, GLenum error) {
    if (quadric.errorCallback) quadric.errorCallback(error);
}

QuadricAttributes::QuadricAttributes(const GLUquadric& quadric)
    : hasNormals(quadric.normals != GLU_NONE),
      hasTexture(quadric.texture),
      sign(quadric.orientation == GLU_INSIDE ? -1.0f : 1.0f) {}

void QuadricAttributes::normal(float x, float y, float z) const {
    if (hasNormals) glNormal3f(sign * x, sign * y, sign * z);
}

void QuadricAttributes::texCoord(float s, float t) const {
    if (hasTexture) glTexCoord2f(s, t);
}

AngleTable::AngleTable(int count, double start, double step, bool closed) : sin(count + 1), cos(count + 1) {
    for (int i = 0; i <= count; ++i) {
        const double angle = closed && i == count ? start : start + step * i;
        sin[i] = static_cast<float>(std::sin(angle));
        cos[i] = static_cast<float>(std::cos(angle));
    }
}

}  // namespace mygl::glu

using mygl::glu::quadricError;

extern "C" {

GLUquadric* gluNewQuadric(void) { return new (std::nothrow) GLUquadric; }

void gluDeleteQuadric(GLUquadric* quad) { delete quad; }

void gluQuadricDrawStyle(GLUquadric* quad, GLenum draw) {
    if (!quad) return;
    if (draw != GLU_POINT && draw != GLU_LINE && draw != GLU_FILL && draw != GLU_SILHOUETTE) {
        quadricError(*quad, GLU_INVALID_ENUM);
        return;
    }
    quad->drawStyle = draw;
}

void gluQuadricOrientation(GLUquadric* quad, GLenum orientation) {
    if (!quad) return;
    if (orientation != GLU_OUTSIDE && orientation != GLU_INSIDE) {
        quadricError(*quad, GLU_INVALID_ENUM);
        return;
    }
    quad->orientation = orientation;
}

void gluQuadricNormals(GLUquadric* quad, GLenum normal) {
    if (!quad) return;
    if (normal != GLU_SMOOTH && normal != GLU_FLAT && normal != GLU_NONE) {
        quadricError(*quad, GLU_INVALID_ENUM);
        return;
    }
    quad->normals = normal;
}

void gluQuadricTexture(GLUquadric* quad, GLboolean texture) {
    if (quad) quad->texture = texture != GL_FALSE;
}

void gluQuadricCallback(GLUquadric* quad, GLenum which, _GLUfuncptr callback) {
    if (!quad) return;
    if (which != GLU_ERROR) {
        quadricError(*quad, GLU_INVALID_ENUM);
        return;
    }
    // GLU's documented signature for GLU_ERROR is void (GLenum); programs pass it cast.
    quad->errorCallback = reinterpret_cast<void (*)(GLenum)>(callback);
}

}  // extern "C"
