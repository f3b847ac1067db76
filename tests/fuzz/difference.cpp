#include "difference.h"

#include <glad/gl.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gl_enum_names.h"

namespace fuzz {
namespace {

constexpr std::size_t classIndex(FailureClass failure) { return static_cast<std::size_t>(failure) - 1; }

template <class T>
std::string values(const std::vector<std::uint8_t>& bytes, const char* format) {
    std::string text = "{";
    for (std::size_t at = 0; at + sizeof(T) <= bytes.size(); at += sizeof(T)) {
        if (std::all_of(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                        bytes.begin() + static_cast<std::ptrdiff_t>(at + sizeof(T)),
                        [](std::uint8_t b) { return b == 0xA5; }))
            break;  // the rest of the query buffer was not written
        T v;
        std::memcpy(&v, &bytes[at], sizeof v);
        char one[48];
        std::snprintf(one, sizeof one, format, v);
        text += text.size() > 1 ? " " : "";
        text += one;
    }
    return text + "}";
}

// A query's answer in words.
std::string inWords(const Stream& stream, const Answer& a) {
    const std::string_view name = functionName(stream.calls.at(a.call));
    if (a.kind == AnswerKind::Error) {
        GLenum e;
        std::memcpy(&e, a.bytes.data(), sizeof e);
        const std::string n = e == GL_NO_ERROR ? "GL_NO_ERROR" : enumName(e);
        return n.empty() ? std::to_string(e) : n;
    }
    if (name == "glGetString") return a.bytes[0] ? "a string" : "NULL";
    if (name == "glGetIntegerv") return values<GLint>(a.bytes, "%d");
    if (name == "glGetFloatv") return values<GLfloat>(a.bytes, "%.9g");
    if (name == "glGetDoublev") return values<GLdouble>(a.bytes, "%.17g");
    return values<GLubyte>(a.bytes, "%u");  // glGetBooleanv, glIsEnabled
}

// Pixels (or bytes) that differ between two read-backs, and the largest difference.
std::string pixelDifference(const Answer& a, const Answer& b) {
    const std::size_t n = std::min(a.bytes.size(), b.bytes.size());
    std::size_t differing = 0;
    long long largest = 0;
    const bool depth = a.kind == AnswerKind::Depth;
    for (std::size_t at = 0; at + 4 <= n; at += 4) {
        bool differs = false;
        if (depth) {
            std::uint32_t x, y;
            std::memcpy(&x, &a.bytes[at], 4);
            std::memcpy(&y, &b.bytes[at], 4);
            differs = x != y;
            largest = std::max(largest, std::llabs(static_cast<long long>(x >> 8) - static_cast<long long>(y >> 8)));
        } else {
            for (std::size_t c = at; c < at + 4; ++c) {
                differs |= a.bytes[c] != b.bytes[c];
                largest = std::max<long long>(largest, std::abs(a.bytes[c] - b.bytes[c]));
            }
        }
        differing += differs;
    }
    char text[160];
    std::snprintf(text, sizeof text, "%zu of %zu pixels differ, max %lld%s", differing, n / 4, largest,
                  depth ? " (24-bit depth units)" : " in a channel");
    return text;
}

}  // namespace

const char* className(FailureClass failure) {
    switch (failure) {
    case FailureClass::None: return "identical";
    case FailureClass::Crash: return "crash";
    case FailureClass::Hang: return "hang";
    case FailureClass::ErrorSequence: return "error sequence";
    case FailureClass::GetAnswers: return "get answers";
    case FailureClass::Color: return "colour";
    case FailureClass::Depth: return "depth";
    }
    return "?";
}

bool Difference::sameFailure(const Difference& other) const {
    if (failure != other.failure) return false;
    if (failure == FailureClass::Crash || failure == FailureClass::Hang)
        return mygl == other.mygl && osmesa == other.osmesa;
    return true;
}

Difference compareOutcomes(const Stream& stream, const BothOutcomes& outcomes) {
    Difference d;
    const Outcome& m = outcomes.mygl;
    const Outcome& o = outcomes.osmesa;
    for (const auto& [status, failure] : {std::pair{Outcome::Status::Crashed, FailureClass::Crash},
                                          std::pair{Outcome::Status::Hung, FailureClass::Hang}}) {
        if (m.status != status && o.status != status) continue;
        d.failure = failure;
        d.mygl = m.describe();
        d.osmesa = o.describe();
        d.detail = "mygl " + d.mygl + ", osmesa " + d.osmesa;
        d.classes[classIndex(failure)] = true;
        return d;
    }
    const std::size_t n = std::min(m.answers.size(), o.answers.size());
    for (std::size_t i = 0; i < n; ++i) {
        const Answer& a = m.answers[i];
        const Answer& b = o.answers[i];
        if (a == b) continue;
        const FailureClass failure = a.kind == AnswerKind::Error   ? FailureClass::ErrorSequence
                                     : a.kind == AnswerKind::Get   ? FailureClass::GetAnswers
                                     : a.kind == AnswerKind::Color ? FailureClass::Color
                                                                   : FailureClass::Depth;
        d.classes[classIndex(failure)] = true;
        if (d.failure != FailureClass::None && d.failure <= failure) continue;
        d.failure = failure;
        d.call = a.call;
        const std::string where = a.call == kFinalFrame ? "final frame"
                                                        : "call " + std::to_string(a.call) + " " +
                                                              std::string(functionName(stream.calls[a.call]));
        if (failure == FailureClass::Color || failure == FailureClass::Depth) {
            d.mygl = d.osmesa = "";
            d.detail = where + ": " + pixelDifference(a, b);
        } else {
            d.mygl = inWords(stream, a);
            d.osmesa = inWords(stream, b);
            d.detail = where + ": mygl " + d.mygl + ", osmesa " + d.osmesa;
        }
    }
    return d;
}

}  // namespace fuzz
