#pragma once
// OSMesa's count of the samples a draw passes, by a GL_SAMPLES_PASSED occlusion query: what the
// tests check MyGL's fragment counters against. Occlusion queries are GL 1.5 and the project's
// loader is generated for 1.1, so they are fetched from OSMesa by name with their spec signatures.
#include <glad/gl.h>

#include "reference/osmesa_context.h"

namespace testing_support {

class SamplesPassedQuery {
public:
    // With an OSMesa context current.
    SamplesPassedQuery()
        : gen_(reinterpret_cast<Gen>(reference::OsmesaContext::getProcAddress("glGenQueries"))),
          begin_(reinterpret_cast<Begin>(reference::OsmesaContext::getProcAddress("glBeginQuery"))),
          end_(reinterpret_cast<End>(reference::OsmesaContext::getProcAddress("glEndQuery"))),
          result_(reinterpret_cast<Result>(reference::OsmesaContext::getProcAddress("glGetQueryObjectuiv"))) {
        if (available()) gen_(1, &query_);
    }
    bool available() const { return gen_ && begin_ && end_ && result_; }
    // The samples `draw` passes.
    template <class Draw>
    GLuint samplesPassed(Draw&& draw) {
        begin_(kSamplesPassed, query_);
        draw();
        end_(kSamplesPassed);
        GLuint samples = 0;
        result_(query_, kQueryResult, &samples);
        return samples;
    }

private:
    static constexpr GLenum kSamplesPassed = 0x8914, kQueryResult = 0x8866;
    using Gen = void(GLAD_API_PTR*)(GLsizei, GLuint*);
    using Begin = void(GLAD_API_PTR*)(GLenum, GLuint);
    using End = void(GLAD_API_PTR*)(GLenum);
    using Result = void(GLAD_API_PTR*)(GLuint, GLenum, GLuint*);
    Gen gen_;
    Begin begin_;
    End end_;
    Result result_;
    GLuint query_ = 0;
};

}  // namespace testing_support
