// GLUT's bitmap fonts: each character is one glBitmap at the current raster position, which
// moves on by the character's advance.
#include <mygl/glut.h>

#include "fonts/font_data.h"
#include "fonts/widest_line.h"

void* glutBitmap9By15;
void* glutBitmap8By13;
void* glutBitmapTimesRoman10;
void* glutBitmapTimesRoman24;
void* glutBitmapHelvetica10;
void* glutBitmapHelvetica12;
void* glutBitmapHelvetica18;

namespace {

using glut::fonts::BitmapFont;
using glut::fonts::BitmapGlyph;

// The font behind a GLUT_BITMAP_* handle, or nullptr.
const BitmapFont* bitmapFont(void* handle) {
    if (handle == &glutBitmap8By13) return &glut::fonts::kFixed8x13;
    if (handle == &glutBitmap9By15) return &glut::fonts::kFixed9x15;
    if (handle == &glutBitmapTimesRoman10) return &glut::fonts::kTimesRoman10;
    if (handle == &glutBitmapTimesRoman24) return &glut::fonts::kTimesRoman24;
    if (handle == &glutBitmapHelvetica10) return &glut::fonts::kHelvetica10;
    if (handle == &glutBitmapHelvetica12) return &glut::fonts::kHelvetica12;
    if (handle == &glutBitmapHelvetica18) return &glut::fonts::kHelvetica18;
    return nullptr;
}

const BitmapGlyph* glyph(const BitmapFont* font, int character) {
    return font && character >= 0 && character < 256 ? &font->glyphs[character] : nullptr;
}

// Draws one glyph with the rows packed byte by byte, as the data is, and puts the program's
// unpack alignment back.
void drawGlyph(const BitmapFont& font, const BitmapGlyph& g) {
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBitmap(g.width, g.height, g.xorig, g.yorig, g.advance, 0.0f, font.bits + g.bits);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
}

}  // namespace

void glutBitmapCharacter(void* font, int character) {
    const BitmapFont* f = bitmapFont(font);
    if (const BitmapGlyph* g = glyph(f, character)) drawGlyph(*f, *g);
}

// A newline goes back to where the line started, one line height down.
void glutBitmapString(void* font, const unsigned char* string) {
    const BitmapFont* f = bitmapFont(font);
    if (!f || !string) return;
    int lineWidth = 0;
    for (const unsigned char* c = string; *c; ++c) {
        if (*c == '\n') {
            glBitmap(0, 0, 0.0f, 0.0f, static_cast<GLfloat>(-lineWidth), static_cast<GLfloat>(-f->height), nullptr);
            lineWidth = 0;
        } else {
            drawGlyph(*f, f->glyphs[*c]);
            lineWidth += f->glyphs[*c].advance;
        }
    }
}

int glutBitmapWidth(void* font, int character) {
    const BitmapGlyph* g = glyph(bitmapFont(font), character);
    return g ? g->advance : 0;
}

int glutBitmapHeight(void* font) {
    const BitmapFont* f = bitmapFont(font);
    return f ? f->height : 0;
}

// The widest line.
int glutBitmapLength(void* font, const unsigned char* string) {
    const BitmapFont* f = bitmapFont(font);
    if (!f || !string) return 0;
    return glut::fonts::widestLine(string, [f](unsigned char c) { return static_cast<int>(f->glyphs[c].advance); });
}
