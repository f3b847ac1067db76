// Turns the API table (api_table_*.cpp) into conformance cases: per row, the valid calls, each
// error call, for a function the spec forbids between glBegin and glEnd the valid calls there,
// and each call compiled into a display list and run; each followed by glGetError and the row's
// queries.
#include <glad/gl.h>
#include <scene.h>

#include "api_table.h"
#include "cases.h"

namespace conformance {
namespace {

bool errorCall = false;
constexpr GLuint kList = 500;  // a list name no row uses

// Runs `call` as one of a row's error calls.
void asErrorCall(const ApiCall& call, Observations& o) {
    errorCall = true;
    call(o);
    errorCall = false;
}

void runRow(const ApiFunction& f, Observations& o) {
    o.drainErrors();
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glPointSize(2.0f);
    f.valid(o);
    o.error("valid");
    if (f.effect) f.effect(o);
    for (std::size_t i = 0; i < f.errors.size(); ++i) {
        asErrorCall(f.errors[i].call, o);
        o.error("error call " + std::to_string(i + 1));
        if (f.effect) f.effect(o);
    }
    if (!f.allowedInsideBeginEnd) {
        glBegin(GL_POINTS);
        asErrorCall(f.valid, o);
        glEnd();
        o.error("inside glBegin/glEnd");
        if (f.effect) f.effect(o);
    }
    // Each call compiled into a list of its own, then the list executed: errors of compiled
    // commands are the list's at its execution, those of commands executed at once come at once.
    for (std::size_t i = 0; i <= f.errors.size(); ++i) {
        if (i == 0 ? !f.validCompiled : !f.errors[i - 1].compiled) continue;
        const ApiCall& call = i == 0 ? f.valid : f.errors[i - 1].call;
        glNewList(kList, GL_COMPILE);
        if (i > 0)
            asErrorCall(call, o);
        else
            call(o);
        glEndList();
        o.error("compiled");
        glCallList(kList);
        o.error("executed");
        if (f.effect) f.effect(o);
    }
    glDeleteLists(kList, 1);
    if (f.cleanup) f.cleanup(o);
    glPointSize(1.0f);
    o.drainErrors();
}

}  // namespace

bool inErrorCall() { return errorCall; }

std::vector<Case> apiCases() {
    std::vector<ApiFunction> rows = vertexApiTable();
    for (auto* table : {stateApiTable, textureApiTable, objectApiTable}) {
        std::vector<ApiFunction> more = table();
        rows.insert(rows.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    std::vector<Case> cases;
    for (ApiFunction& row : rows) {
        std::string name = "api_" + row.name;
        if (const auto colon = name.find(':'); colon != std::string::npos) name[colon] = '_';
        cases.push_back({"api-" + row.group, name, true, scenes::resetState,
                         [f = std::move(row)](Observations& o) { runRow(f, o); }});
    }
    return cases;
}

}  // namespace conformance
