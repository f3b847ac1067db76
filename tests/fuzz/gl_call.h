#pragma once
// The fuzzer's call-stream model: a GL call with concrete arguments that can run through the
// loaded GL table (<glad/gl.h>, so on MyGL or OSMesa alike) and print itself as a C statement.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fuzz {

// What a call gives back; the runner compares these between the backends.
enum class AnswerKind : std::uint8_t { Error, Get, Color, Depth };

struct Answer {
    AnswerKind kind;
    std::uint32_t call;  // index of the call in its stream (kFinalFrame for the final read)
    std::vector<std::uint8_t> bytes;
    bool operator==(const Answer&) const = default;
};
using Answers = std::vector<Answer>;

constexpr std::uint32_t kFinalFrame = 0xFFFFFFFFu;

// One call. `args` holds the scalar arguments and the elements behind each const-pointer
// argument, in order, as doubles: exact for every value of every GL type passed.
struct Call {
    std::uint16_t function = 0;  // index into the function table
    std::vector<double> args;
};

// A stream runs on a fresh context of this size.
struct Stream {
    int width = 16;
    int height = 16;
    std::vector<Call> calls;
};

// The table index of the GL function `name` ("glVertex3f"); throws std::invalid_argument if the
// fuzzer does not know it.
std::uint16_t functionId(std::string_view name);
std::string_view functionName(const Call& call);
std::size_t functionCount();  // the table's size: ids are 0 .. functionCount() - 1
// How many doubles `args` must hold for the function.
std::size_t argumentCount(std::uint16_t function);
Call makeCall(std::string_view name, std::vector<double> args = {});

// Runs the call through the loaded GL table; queries append what they return to `answers`.
// `width` and `height` are the framebuffer's, used to size glReadPixels' destination exactly.
void runCall(const Call& call, std::uint32_t index, int width, int height, Answers& answers);

// The call as a C statement ("glVertex3f(1.0f, 2.0f, 0.5f);"), compilable against <GL/gl.h>.
std::string toC(const Call& call);

// Bytes glReadPixels writes at most into its destination for this rectangle on a framebuffer of
// `width` x `height` (rows aligned to 8 bytes, the largest GL_PACK_ALIGNMENT); at least 4.
std::size_t readPixelsBytes(std::int64_t x, std::int64_t y, std::int64_t w, std::int64_t h, int bytesPerPixel,
                            int width, int height);

}  // namespace fuzz
