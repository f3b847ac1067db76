// GLUT's stroke fonts: each character is line strips in the current modelview, which then
// moves right by the character's advance.
#include <mygl/glut.h>

#include "fonts/font_data.h"
#include "fonts/widest_line.h"

void* glutStrokeRoman;
void* glutStrokeMonoRoman;

namespace {

using glut::fonts::StrokeFont;
using glut::fonts::StrokeGlyph;

const StrokeFont* strokeFont(void* handle) {
    if (handle == &glutStrokeRoman) return &glut::fonts::kRoman;
    if (handle == &glutStrokeMonoRoman) return &glut::fonts::kMonoRoman;
    return nullptr;
}

const StrokeGlyph* glyph(const StrokeFont* font, int character) {
    return font && character >= 0 && character < 256 ? &font->glyphs[character] : nullptr;
}

void drawGlyph(const StrokeFont& font, const StrokeGlyph& g) {
    for (int s = 0; s < g.stripCount; ++s) {
        const auto& strip = font.strips[g.firstStrip + s];
        glBegin(GL_LINE_STRIP);
        for (int p = 0; p < strip.pointCount; ++p)
            glVertex2fv(font.points + 2 * (strip.firstPoint + static_cast<unsigned>(p)));
        glEnd();
    }
    glTranslatef(g.advance, 0.0f, 0.0f);
}

}  // namespace

void glutStrokeCharacter(void* font, int character) {
    const StrokeFont* f = strokeFont(font);
    if (const StrokeGlyph* g = glyph(f, character)) drawGlyph(*f, *g);
}

// A newline goes back to where the line started, one font height down.
void glutStrokeString(void* font, const unsigned char* string) {
    const StrokeFont* f = strokeFont(font);
    if (!f || !string) return;
    float lineWidth = 0;
    for (const unsigned char* c = string; *c; ++c) {
        if (*c == '\n') {
            glTranslatef(-lineWidth, -f->height, 0.0f);
            lineWidth = 0;
        } else {
            drawGlyph(*f, f->glyphs[*c]);
            lineWidth += f->glyphs[*c].advance;
        }
    }
}

GLfloat glutStrokeWidthf(void* font, int character) {
    const StrokeGlyph* g = glyph(strokeFont(font), character);
    return g ? g->advance : 0.0f;
}

int glutStrokeWidth(void* font, int character) { return static_cast<int>(glutStrokeWidthf(font, character) + 0.5f); }

GLfloat glutStrokeHeight(void* font) {
    const StrokeFont* f = strokeFont(font);
    return f ? f->height : 0.0f;
}

// The widest line.
GLfloat glutStrokeLengthf(void* font, const unsigned char* string) {
    const StrokeFont* f = strokeFont(font);
    if (!f || !string) return 0.0f;
    return glut::fonts::widestLine(string, [f](unsigned char c) { return f->glyphs[c].advance; });
}

int glutStrokeLength(void* font, const unsigned char* string) {
    return static_cast<int>(glutStrokeLengthf(font, string) + 0.5f);
}
