#pragma once
// The state of a GLU tessellator object: the callbacks, the properties and the polygon being
// given contour by contour. tess_api.cpp holds the GLU calls; tess_polygon.cpp turns a finished
// polygon into triangles or boundary loops through the callbacks.
#include <mygl/glu.h>

#include <vector>

#include "tess_arrangement.h"

struct GLUtesselator {
    enum class State { Dormant, InPolygon, InContour };
    State state = State::Dormant;

    // Each callback has a plain and a _DATA form; the _DATA one, when set, is called instead.
    void (*begin)(GLenum) = nullptr;
    void (*beginData)(GLenum, void*) = nullptr;
    void (*vertex)(void*) = nullptr;
    void (*vertexData)(void*, void*) = nullptr;
    void (*end)() = nullptr;
    void (*endData)(void*) = nullptr;
    void (*error)(GLenum) = nullptr;
    void (*errorData)(GLenum, void*) = nullptr;
    void (*edgeFlag)(GLboolean) = nullptr;
    void (*edgeFlagData)(GLboolean, void*) = nullptr;
    void (*combine)(GLdouble[3], void* [4], GLfloat[4], void**) = nullptr;
    void (*combineData)(GLdouble[3], void* [4], GLfloat[4], void**, void*) = nullptr;

    GLenum windingRule = GLU_TESS_WINDING_ODD;
    bool boundaryOnly = false;
    double tolerance = 0.0;
    double normal[3] = {0.0, 0.0, 0.0};  // 0, 0, 0: computed from the vertices

    void* polygonData = nullptr;
    std::vector<mygl::glu::tess::Vertex> vertices;  // object coordinates and data; p set at the end
    std::vector<std::vector<int>> contours;
};

namespace mygl::glu::tess {

void reportError(GLUtesselator& tess, GLenum error);
// Tessellates the polygon given since gluTessBeginPolygon and sends the result to the callbacks.
void tessellatePolygon(GLUtesselator& tess);

}  // namespace mygl::glu::tess
