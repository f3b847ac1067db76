#pragma once
// GLUT's fonts as data, generated at build time by make_font_data.py from Debian's font
// packages (see there for the sources and their licences).
#include <cstdint>

namespace glut::fonts {

// One glyph of a bitmap font, drawn by glBitmap: `height` rows of ceil(width / 8) bytes, bottom
// row first, most significant bit leftmost, starting at `bits`.
struct BitmapGlyph {
    std::uint8_t width, height;
    std::int8_t xorig, yorig;  // where the raster position sits in the glyph
    std::uint8_t advance;      // how far the raster position moves
    std::uint32_t bits;        // offset into the font's bits
};

struct BitmapFont {
    const char* name;
    int height;                 // line height in pixels
    const BitmapGlyph* glyphs;  // 256, Latin-1; a glyph of width 0 draws nothing
    const std::uint8_t* bits;
};

// A stroke font: each glyph is line strips in font units (capital letters 100 high above the
// baseline at y = 0), then the pen moves right by `advance`.
struct StrokeGlyph {
    float advance;
    std::uint16_t firstStrip, stripCount;
};
struct StrokeStrip {
    std::uint32_t firstPoint;
    std::uint16_t pointCount;
};
struct StrokeFont {
    const char* name;
    float height;               // from the lowest descender to the highest ascender
    const StrokeGlyph* glyphs;  // 256; only 32..126 have strokes
    const StrokeStrip* strips;
    const float* points;  // x, y pairs
};

extern const BitmapFont kFixed8x13, kFixed9x15, kTimesRoman10, kTimesRoman24, kHelvetica10, kHelvetica12, kHelvetica18;
extern const StrokeFont kRoman, kMonoRoman;

}  // namespace glut::fonts
