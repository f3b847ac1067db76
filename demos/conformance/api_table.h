#pragma once
// The API conformance table: per GL 1.1 function, calls with valid arguments and the calls the
// spec makes errors, with the queries that show their effect. api_cases.cpp turns each row into
// one conformance case; the rows live in api_table_*.cpp, one file per group of functions.
#include <functional>
#include <string>
#include <vector>

#include "observations.h"

namespace conformance {

using ApiCall = std::function<void(Observations&)>;

// A call the spec makes an error. `compiled` false keeps it out of the display-list pass, where
// the reference crashes (glBitmap copies the data a negative size implies) or departs from the
// spec (then a row "name:in_list" of its own compiles it, an expected difference).
struct ErrorCall {
    ApiCall call;
    bool compiled = true;
    template <class F>
    ErrorCall(F f) : call(std::move(f)) {}  // NOLINT: rows list plain calls
};
template <class F>
ErrorCall notCompiled(F f) {
    ErrorCall e(std::move(f));
    e.compiled = false;
    return e;
}

struct ApiFunction {
    std::string name;   // the GL function the row is about, e.g. "glCullFace"
    std::string group;  // the case's category is "api-" + group
    ApiCall valid;      // calls with valid arguments (also inside glBegin/glEnd and compiled into a list)
    std::vector<ErrorCall> errors = {};  // each a call the spec makes an error
    ApiCall effect = {};                 // queries showing the state the calls leave
    bool allowedInsideBeginEnd = false;  // else a case calls `valid` inside glBegin/glEnd too
    ApiCall cleanup = {};                // puts back what resetState does not
    bool validCompiled = true;           // else `valid` stays out of the display-list pass (as notCompiled)
};

// Rows in brief: API_CALL(glCullFace(GL_FRONT)) is a call observing nothing itself.
#define API_CALL(...) [](::conformance::Observations&) { __VA_ARGS__; }

// An enum value no GL 1.1 parameter accepts.
inline constexpr unsigned kBadEnum = 0x9999;

// The effect `glGetFloatv` of each pname shows.
ApiCall get(std::vector<unsigned> pnames);

// True while a case runs one of a row's error calls (the coverage test counts calls then).
bool inErrorCall();

std::vector<ApiFunction>
vertexApiTable();  // glVertex, glColor, glNormal, glTexCoord, glIndex, glRasterPos, glRect, glEdgeFlag, glEval*
std::vector<ApiFunction> stateApiTable();    // enables, modes, matrices, lighting, fog, per-fragment state
std::vector<ApiFunction> textureApiTable();  // texture objects, images, parameters, environment, coordinate generation
std::vector<ApiFunction> objectApiTable();   // glBegin/glEnd, lists, arrays, pixels, selection, feedback, evaluators

}  // namespace conformance
