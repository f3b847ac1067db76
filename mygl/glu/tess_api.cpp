// The GLU tessellator calls. Out-of-order calls report GLU_TESS_MISSING_* through the error
// callback and then carry on as GLU does: a missing begin is supplied, an unfinished contour is
// closed, an unfinished polygon is dropped.
#include <cmath>
#include <new>

#include "tessellator.h"

using mygl::glu::tess::reportError;
using State = GLUtesselator::State;

namespace {

void beginPolygon(GLUtesselator& tess, void* data) {
    tess.state = State::InPolygon;
    tess.polygonData = data;
    tess.vertices.clear();
    tess.contours.clear();
}

// Brings the tessellator into `wanted`, reporting each step the program left out.
void requireState(GLUtesselator& tess, State wanted) {
    while (tess.state != wanted) {
        if (tess.state < wanted) {
            if (tess.state == State::Dormant) {
                reportError(tess, GLU_TESS_MISSING_BEGIN_POLYGON);
                beginPolygon(tess, nullptr);
            } else {
                reportError(tess, GLU_TESS_MISSING_BEGIN_CONTOUR);
                tess.state = State::InContour;
                tess.contours.emplace_back();
            }
        } else if (tess.state == State::InContour) {
            reportError(tess, GLU_TESS_MISSING_END_CONTOUR);
            tess.state = State::InPolygon;
        } else {
            reportError(tess, GLU_TESS_MISSING_END_POLYGON);
            tess.state = State::Dormant;
            tess.vertices.clear();
            tess.contours.clear();
        }
    }
}

template <class Function>
void set(Function& slot, _GLUfuncptr callback) {
    slot = reinterpret_cast<Function>(callback);
}

}  // namespace

extern "C" {

GLUtesselator* gluNewTess(void) { return new (std::nothrow) GLUtesselator; }

void gluDeleteTess(GLUtesselator* tess) {
    if (!tess) return;
    requireState(*tess, State::Dormant);
    delete tess;
}

void gluTessBeginPolygon(GLUtesselator* tess, GLvoid* data) {
    if (!tess) return;
    requireState(*tess, State::Dormant);
    beginPolygon(*tess, data);
}

void gluTessBeginContour(GLUtesselator* tess) {
    if (!tess) return;
    requireState(*tess, State::InPolygon);
    tess->state = State::InContour;
    tess->contours.emplace_back();
}

void gluTessVertex(GLUtesselator* tess, GLdouble* location, GLvoid* data) {
    if (!tess) return;
    requireState(*tess, State::InContour);
    if (!location) return;
    mygl::glu::tess::Vertex vertex{{0.0, 0.0}, {}, data};
    bool tooLarge = false;
    for (int k = 0; k < 3; ++k) {
        // GLU clamps coordinates beyond GLU_TESS_MAX_COORD; a NaN has no place to be clamped to.
        const double c = location[k];
        tooLarge = tooLarge || !(std::fabs(c) <= GLU_TESS_MAX_COORD);
        vertex.coords[k] = std::isnan(c) ? 0.0 : std::fmax(-GLU_TESS_MAX_COORD, std::fmin(GLU_TESS_MAX_COORD, c));
    }
    if (tooLarge) {
        reportError(*tess, GLU_TESS_COORD_TOO_LARGE);
        if (std::isnan(location[0]) || std::isnan(location[1]) || std::isnan(location[2])) return;
    }
    tess->contours.back().push_back(static_cast<int>(tess->vertices.size()));
    tess->vertices.push_back(vertex);
}

void gluTessEndContour(GLUtesselator* tess) {
    if (!tess) return;
    requireState(*tess, State::InContour);
    tess->state = State::InPolygon;
}

void gluTessEndPolygon(GLUtesselator* tess) {
    if (!tess) return;
    requireState(*tess, State::InPolygon);
    mygl::glu::tess::tessellatePolygon(*tess);
    tess->state = State::Dormant;
    tess->vertices.clear();
    tess->contours.clear();
}

void gluTessCallback(GLUtesselator* tess, GLenum which, _GLUfuncptr callback) {
    if (!tess) return;
    switch (which) {
    case GLU_TESS_BEGIN: set(tess->begin, callback); break;
    case GLU_TESS_BEGIN_DATA: set(tess->beginData, callback); break;
    case GLU_TESS_VERTEX: set(tess->vertex, callback); break;
    case GLU_TESS_VERTEX_DATA: set(tess->vertexData, callback); break;
    case GLU_TESS_END: set(tess->end, callback); break;
    case GLU_TESS_END_DATA: set(tess->endData, callback); break;
    case GLU_TESS_ERROR: set(tess->error, callback); break;
    case GLU_TESS_ERROR_DATA: set(tess->errorData, callback); break;
    case GLU_TESS_EDGE_FLAG: set(tess->edgeFlag, callback); break;
    case GLU_TESS_EDGE_FLAG_DATA: set(tess->edgeFlagData, callback); break;
    case GLU_TESS_COMBINE: set(tess->combine, callback); break;
    case GLU_TESS_COMBINE_DATA: set(tess->combineData, callback); break;
    default: reportError(*tess, GLU_INVALID_ENUM); break;
    }
}

void gluTessProperty(GLUtesselator* tess, GLenum which, GLdouble data) {
    if (!tess) return;
    switch (which) {
    case GLU_TESS_WINDING_RULE: {
        const GLenum rule = data >= 0.0 && data <= 1e9 ? static_cast<GLenum>(data) : 0;
        if (rule != data || rule < GLU_TESS_WINDING_ODD || rule > GLU_TESS_WINDING_ABS_GEQ_TWO) {
            reportError(*tess, GLU_INVALID_VALUE);
            return;
        }
        tess->windingRule = rule;
        return;
    }
    case GLU_TESS_BOUNDARY_ONLY: tess->boundaryOnly = data != 0.0; return;
    case GLU_TESS_TOLERANCE:
        if (!(data >= 0.0 && data <= 1.0)) {
            reportError(*tess, GLU_INVALID_VALUE);
            return;
        }
        tess->tolerance = data;
        return;
    default: reportError(*tess, GLU_INVALID_ENUM); return;
    }
}

void gluGetTessProperty(GLUtesselator* tess, GLenum which, GLdouble* data) {
    if (!tess || !data) return;
    switch (which) {
    case GLU_TESS_WINDING_RULE: *data = tess->windingRule; return;
    case GLU_TESS_BOUNDARY_ONLY: *data = tess->boundaryOnly ? GL_TRUE : GL_FALSE; return;
    case GLU_TESS_TOLERANCE: *data = tess->tolerance; return;
    default:
        *data = 0.0;
        reportError(*tess, GLU_INVALID_ENUM);
        return;
    }
}

void gluTessNormal(GLUtesselator* tess, GLdouble valueX, GLdouble valueY, GLdouble valueZ) {
    if (!tess) return;
    const bool finite = std::isfinite(valueX) && std::isfinite(valueY) && std::isfinite(valueZ);
    tess->normal[0] = finite ? valueX : 0.0;
    tess->normal[1] = finite ? valueY : 0.0;
    tess->normal[2] = finite ? valueZ : 0.0;
}

void gluBeginPolygon(GLUtesselator* tess) {
    gluTessBeginPolygon(tess, nullptr);
    gluTessBeginContour(tess);
}

// GLU 1.2 and later ignore the contour type: winding numbers decide.
void gluNextContour(GLUtesselator* tess, GLenum) {
    gluTessEndContour(tess);
    gluTessBeginContour(tess);
}

void gluEndPolygon(GLUtesselator* tess) {
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

}  // extern "C"
