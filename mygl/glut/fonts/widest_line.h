#pragma once
// The width of a string's widest line (lines end at '\n'), each character `advance(c)` wide:
// glutBitmapLength and glutStrokeLength.
#include <algorithm>

namespace glut::fonts {

template <class Advance>
auto widestLine(const unsigned char* text, Advance advance) -> decltype(advance(text[0])) {
    decltype(advance(text[0])) widest{}, line{};
    for (const unsigned char* c = text; *c; ++c) {
        line = *c == '\n' ? decltype(line){} : line + advance(*c);
        widest = std::max(widest, line);
    }
    return widest;
}

}  // namespace glut::fonts
