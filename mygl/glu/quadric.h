#pragma once
// The state of a GLU quadric object and what the shapes (sphere.cpp, cylinder.cpp, disk.cpp)
// share: error reporting, optional normals and texture coordinates, tables of angles.
#include <mygl/glu.h>

#include <vector>

struct GLUquadric {
    GLenum drawStyle = GLU_FILL;
    GLenum orientation = GLU_OUTSIDE;
    GLenum normals = GLU_SMOOTH;
    bool texture = false;
    void (*errorCallback)(GLenum) = nullptr;
};

namespace mygl::glu {

// GLU caps slices (and a sphere's stacks) at this many, which also bounds the work of one call.
inline constexpr int kMaxQuadricDivisions = 239;

void quadricError(const GLUquadric& quadric, GLenum error);

// k / n in float, as GLU computes its texture coordinates and radii.
inline float fraction(int k, int n) { return static_cast<float>(k) / static_cast<float>(n); }

// glNormal3f / glTexCoord2f, sent only when the quadric asks for normals / texture coordinates.
// `sign` is -1 for GLU_INSIDE, so normals point into the shape.
struct QuadricAttributes {
    explicit QuadricAttributes(const GLUquadric& quadric);
    void normal(float x, float y, float z) const;
    void texCoord(float s, float t) const;
    bool hasNormals;
    bool hasTexture;
    float sign;
};

// sin and cos of start + step * i for i = 0..count; with `closed` the last entry repeats the first
// exactly, so a ring closes without a crack.
struct AngleTable {
    AngleTable(int count, double start, double step, bool closed);
    std::vector<float> sin;
    std::vector<float> cos;
};

// A sphere's or cylinder's grid of slices (around) x rings (along) as lines: line strips round
// the rings firstRing, firstRing + ringStep, ... up to lastRing, then one strip along each slice
// through every ring. `vertex(slice, ring)` sends one grid vertex.
template <class Vertex>
void gridLines(int slices, int rings, int firstRing, int lastRing, int ringStep, const Vertex& vertex) {
    for (int j = firstRing; j <= lastRing; j += ringStep) {
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i <= slices; ++i) vertex(i, j);
        glEnd();
    }
    for (int i = 0; i < slices; ++i) {
        glBegin(GL_LINE_STRIP);
        for (int j = 0; j <= rings; ++j) vertex(i, j);
        glEnd();
    }
}

// The same grid's vertices as points (each slice once: the last repeats the first).
template <class Vertex>
void gridPoints(int slices, int rings, const Vertex& vertex) {
    glBegin(GL_POINTS);
    for (int j = 0; j <= rings; ++j) {
        for (int i = 0; i < slices; ++i) vertex(i, j);
    }
    glEnd();
}

}  // namespace mygl::glu
