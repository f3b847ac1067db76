#pragma once
// What an API case saw, in order: the glGetError value after each call and the answers of the
// queries that show a call's effect, each as one line of text, so that MyGL's sequence and
// OSMesa's compare exactly and a difference prints readably.
#include <glad/gl.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace conformance {

class Observations {
public:
    // Reads glGetError and records it after `label`.
    void error(const std::string& label);
    // Reads errors until GL_NO_ERROR (a bounded number), recording nothing: a clean start.
    void drainErrors();
    // Query answers; arrays were filled with kUnwritten first, so how many values a query wrote
    // is compared too (trailing unwritten values are left out of the line).
    void floats(const std::string& what, const GLfloat* values, std::size_t count);
    void doubles(const std::string& what, const GLdouble* values, std::size_t count);
    void ints(const std::string& what, const GLint* values, std::size_t count);
    void uints(const std::string& what, const GLuint* values, std::size_t count);
    void bytes(const std::string& what, const GLubyte* values, std::size_t count);
    void value(const std::string& what, long long v);

    // A query's float and integer forms (`name` + "fv", "iv"), each into 4 unwritten values.
    void floatsAndInts(const std::string& name, const std::function<void(GLfloat*)>& fv,
                       const std::function<void(GLint*)>& iv);

    // glGetFloatv of each pname into a fresh array.
    void get(std::initializer_list<GLenum> pnames);

    const std::vector<std::string>& lines() const { return lines_; }

    static constexpr GLfloat kUnwritten = -12345.0f;

private:
    std::vector<std::string> lines_;
};

// The first line where two sequences differ, as "#i: ours | theirs"; empty when equal.
std::string firstDifference(const std::vector<std::string>& ours, const std::vector<std::string>& theirs);

}  // namespace conformance
