#include "tess_recorder.h"

namespace testing_support {
namespace {

TessRecorder& recorder(void* self) { return *static_cast<TessRecorder*>(self); }

}  // namespace

TessRecorder::TessRecorder(GLUtesselator* tess) {
    gluTessCallback(tess, GLU_TESS_BEGIN_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::begin));
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::vertex));
    gluTessCallback(tess, GLU_TESS_END_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::end));
    gluTessCallback(tess, GLU_TESS_ERROR_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::error));
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::edgeFlag));
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, reinterpret_cast<_GLUfuncptr>(&TessRecorder::combine));
}

void TessRecorder::clear() {
    primitives.clear();
    errors.clear();
    combined.clear();
    nestedBegin = insideBeginEnd = false;
    flag_ = true;
}

void TessRecorder::begin(GLenum mode, void* self) {
    TessRecorder& r = recorder(self);
    r.nestedBegin = r.nestedBegin || r.insideBeginEnd;
    r.insideBeginEnd = true;
    r.primitives.push_back({mode, {}, {}});
}

void TessRecorder::vertex(void* data, void* self) {
    TessRecorder& r = recorder(self);
    if (r.primitives.empty()) return;
    r.primitives.back().vertices.push_back(static_cast<const Point3*>(data));
    r.primitives.back().edgeFlags.push_back(r.flag_);
}

void TessRecorder::end(void* self) { recorder(self).insideBeginEnd = false; }

void TessRecorder::error(GLenum error, void* self) { recorder(self).errors.push_back(error); }

void TessRecorder::edgeFlag(GLboolean flag, void* self) { recorder(self).flag_ = flag != GL_FALSE; }

void TessRecorder::combine(GLdouble coords[3], void* data[4], GLfloat weights[4], void** out, void* self) {
    TessRecorder& r = recorder(self);
    (void)data;
    (void)weights;
    const Point3 p{coords[0], coords[1], coords[2]};
    r.combined.push_back(p);
    *out = r.keep(p);
}

}  // namespace testing_support
