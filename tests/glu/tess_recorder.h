#pragma once
// Records what the GLU tessellator sends to its callbacks (the _DATA forms, with the recorder as
// polygon data): primitives with their vertices, edge flags, combine calls and errors.
#include <mygl/glu.h>

#include <array>
#include <deque>
#include <vector>

namespace testing_support {

using Point3 = std::array<double, 3>;

struct TessPrimitive {
    GLenum mode;
    std::vector<const Point3*> vertices;
    std::vector<bool> edgeFlags;  // the flag in force at each vertex
};

class TessRecorder {
public:
    // A tessellator with every _DATA callback pointing here.
    explicit TessRecorder(GLUtesselator* tess);

    // Stable storage for a vertex the test gives (its address is the vertex data).
    Point3* keep(const Point3& p) { return &points_.emplace_back(p); }
    void clear();

    std::vector<TessPrimitive> primitives;
    std::vector<GLenum> errors;
    std::vector<Point3> combined;  // where combine was asked for a vertex
    bool insideBeginEnd = false;
    bool nestedBegin = false;

private:
    static void begin(GLenum mode, void* self);
    static void vertex(void* data, void* self);
    static void end(void* self);
    static void error(GLenum error, void* self);
    static void edgeFlag(GLboolean flag, void* self);
    static void combine(GLdouble coords[3], void* data[4], GLfloat weights[4], void** out, void* self);

    std::deque<Point3> points_;
    bool flag_ = true;
};

}  // namespace testing_support
