#include "cases.h"

#include <glad/gl.h>
#include <scene.h>

#include <array>
#include <cmath>
#include <random>

namespace conformance {
namespace {

using scenes::resetState;

// Where a mode's shape sits: inside the window, across its edge, or across the near plane.
enum class Placement { Inside, CrossingViewport, CrossingNear };

struct ModeCase {
    GLenum mode;
    bool flat;
    int cull;  // 0 off, then GL_BACK, GL_FRONT, GL_FRONT_AND_BACK
    bool frontCCW;
    bool depth;
    GLenum polygonMode;
    Placement placement;
};

const char* modeName(GLenum mode) {
    static const char* names[] = {"points",   "lines",  "lineloop", "linestrip", "triangles",
                                  "tristrip", "trifan", "quads",    "quadstrip", "polygon"};
    return names[mode];
}

void color(int i) {
    const float t = static_cast<float>(i) * 0.61f;
    glColor3f(0.5f + 0.45f * std::sin(t), 0.5f + 0.45f * std::sin(t + 2.0f), 0.5f + 0.45f * std::sin(t + 4.0f));
}

// Twelve vertices of a ring (star-shaped, so fans and polygons are concave in places), folded
// so that strips and quads get both windings.
void emitModeShape(const ModeCase& c) {
    for (int i = 0; i < 12; ++i) {
        color(i);
        const float angle = static_cast<float>(i) * 0.5236f + 0.1f;
        const float radius = (i % 3 == 1) ? 0.45f : 0.85f;
        float x = radius * std::cos(angle), y = radius * std::sin(angle);
        if (c.mode == GL_TRIANGLE_STRIP || c.mode == GL_QUAD_STRIP) {
            x = -0.9f + 0.16f * static_cast<float>(i);
            y = (i % 2 ? 0.7f : -0.6f) + (i > 6 ? 0.3f : 0.0f) * static_cast<float>(i % 2 ? -1 : 1);
        }
        // Depth varies over the shape so the depth test has something to decide.
        const float z = 0.4f * std::sin(static_cast<float>(i) * 1.3f);
        glVertex3f(x, y, z);
    }
}

void drawModeCase(const ModeCase& c, int width, int height) {
    resetState(width, height);
    glShadeModel(c.flat ? GL_FLAT : GL_SMOOTH);
    if (c.cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(static_cast<GLenum>(c.cull));
    }
    glFrontFace(c.frontCCW ? GL_CCW : GL_CW);
    if (c.depth) glEnable(GL_DEPTH_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, c.polygonMode);
    glMatrixMode(GL_PROJECTION);
    if (c.placement == Placement::CrossingNear) {
        glFrustum(-0.6, 0.6, -0.45, 0.45, 1.0, 10.0);
        glMatrixMode(GL_MODELVIEW);
        glTranslatef(0.0f, 0.0f, -1.6f);
        glRotatef(70.0f, 1.0f, 0.0f, 0.0f);  // tilted so that part of the shape is nearer than 1
        glScalef(1.3f, 1.3f, 1.3f);
    } else {
        glMatrixMode(GL_MODELVIEW);
        if (c.placement == Placement::CrossingViewport) {
            glTranslatef(0.55f, -0.4f, 0.0f);
            glScalef(1.3f, 1.3f, 1.0f);
        }
    }
    // Two blocks of the same mode: mergeable modes join into one draw, as in the reference.
    glBegin(c.mode);
    emitModeShape(c);
    glEnd();
    glTranslatef(0.05f, 0.03f, -0.1f);
    glBegin(c.mode);
    emitModeShape(c);
    glEnd();
}

void addModeCases(std::vector<Case>& out) {
    const std::array<std::pair<Placement, const char*>, 3> placements{
        {{Placement::Inside, "inside"}, {Placement::CrossingViewport, "viewport"}, {Placement::CrossingNear, "near"}}};
    const std::array<std::pair<GLenum, const char*>, 3> polygonModes{
        {{GL_FILL, "fill"}, {GL_LINE, "line"}, {GL_POINT, "point"}}};
    const std::array<std::pair<int, const char*>, 4> culls{
        {{0, "nocull"}, {GL_BACK, "cullback"}, {GL_FRONT, "cullfront"}, {GL_FRONT_AND_BACK, "cullboth"}}};
    for (GLenum mode = GL_POINTS; mode <= GL_POLYGON; ++mode)
        for (bool flat : {true, false})
            for (const auto& [cull, cullName] : culls)
                for (bool ccw : {true, false})
                    for (bool depth : {false, true})
                        for (const auto& [polygonMode, polygonName] : polygonModes)
                            for (const auto& [placement, placementName] : placements) {
                                const bool triangles = mode >= GL_TRIANGLES;
                                // Culling, winding and polygon mode only matter to triangles.
                                if (!triangles && (cull != 0 || !ccw || polygonMode != GL_FILL)) continue;
                                const ModeCase c{mode, flat, cull, ccw, depth, polygonMode, placement};
                                std::string name = std::string(modeName(mode)) + "_" + (flat ? "flat" : "smooth") +
                                                   "_" + cullName + "_" + (ccw ? "ccw" : "cw") + "_" +
                                                   (depth ? "depth" : "nodepth") + "_" + polygonName + "_" +
                                                   placementName;
                                out.push_back({"modes", name, flat, [c](int w, int h) { drawModeCase(c, w, h); }});
                            }
}

// One triangle per case from a fixed seed, in window pixels (sub-pixel positions), smooth.
void addRandomTriangles(std::vector<Case>& out) {
    std::mt19937 random(2024);
    std::uniform_real_distribution<float> x(-8.0f, kWidth + 8.0f), y(-8.0f, kHeight + 8.0f), c(0.0f, 1.0f),
        z(-0.9f, 0.9f);
    for (int i = 0; i < 400; ++i) {
        std::array<float, 15> v;
        for (int k = 0; k < 3; ++k)
            v[static_cast<std::size_t>(k * 5)] = x(random), v[static_cast<std::size_t>(k * 5 + 1)] = y(random),
                                           v[static_cast<std::size_t>(k * 5 + 2)] = c(random),
                                           v[static_cast<std::size_t>(k * 5 + 3)] = c(random),
                                           v[static_cast<std::size_t>(k * 5 + 4)] = z(random);
        const bool flat = i % 4 == 0;
        out.push_back({"random", "random_" + std::to_string(i), flat, [v, flat](int w, int h) {
                           resetState(w, h);
                           glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
                           glMatrixMode(GL_PROJECTION);
                           glOrtho(0, w, 0, h, -1, 1);
                           glMatrixMode(GL_MODELVIEW);
                           glBegin(GL_TRIANGLES);
                           for (std::size_t k = 0; k < 15; k += 5) {
                               glColor3f(v[k + 2], v[k + 3], 0.5f);
                               glVertex3f(v[k], v[k + 1], v[k + 4]);
                           }
                           glEnd();
                       }});
    }
}

// Long thin triangles, triangles smaller than a pixel, and triangles far larger than the window.
void addSpecialTriangles(std::vector<Case>& out) {
    std::mt19937 random(77);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 60; ++i) {
        const float x0 = u(random) * kWidth, y0 = u(random) * kHeight, angle = u(random) * 6.2832f;
        const float length = 20.0f + u(random) * 60.0f, width = 0.01f + u(random) * 0.6f;
        const float dx = std::cos(angle) * length, dy = std::sin(angle) * length;
        const float nx = -std::sin(angle) * width, ny = std::cos(angle) * width;
        out.push_back({"slivers", "sliver_" + std::to_string(i), true, [=](int w, int h) {
                           resetState(w, h);
                           glShadeModel(GL_FLAT);
                           glMatrixMode(GL_PROJECTION);
                           glOrtho(0, w, 0, h, -1, 1);
                           glColor3f(1.0f, 0.6f, 0.2f);
                           glBegin(GL_TRIANGLES);
                           glVertex2f(x0, y0);
                           glVertex2f(x0 + dx, y0 + dy);
                           glVertex2f(x0 + dx * 0.5f + nx, y0 + dy * 0.5f + ny);
                           glEnd();
                       }});
    }
    for (int i = 0; i < 60; ++i) {
        const float x0 = u(random) * kWidth, y0 = u(random) * kHeight, s = 0.05f + u(random) * 1.2f;
        out.push_back({"tiny", "tiny_" + std::to_string(i), true, [=](int w, int h) {
                           resetState(w, h);
                           glShadeModel(GL_FLAT);
                           glMatrixMode(GL_PROJECTION);
                           glOrtho(0, w, 0, h, -1, 1);
                           glColor3f(0.3f, 1.0f, 0.4f);
                           glBegin(GL_TRIANGLES);
                           for (int k = 0; k < 4; ++k) {  // four tiny triangles around the point
                               const float ox = static_cast<float>(k % 2) * 3.3f, oy = static_cast<float>(k / 2) * 2.7f;
                               glVertex2f(x0 + ox, y0 + oy);
                               glVertex2f(x0 + ox + s, y0 + oy + s * 0.3f);
                               glVertex2f(x0 + ox + s * 0.2f, y0 + oy + s);
                           }
                           glEnd();
                       }});
    }
    for (int i = 0; i < 30; ++i) {
        const float scale = std::pow(10.0f, 1.0f + static_cast<float>(i % 6)), a = u(random) * 6.2832f;
        out.push_back({"huge", "huge_" + std::to_string(i), false, [=](int w, int h) {
                           resetState(w, h);
                           glBegin(GL_TRIANGLES);
                           for (int k = 0; k < 3; ++k) {
                               color(k + i);
                               const float angle = a + static_cast<float>(k) * 2.0944f;
                               glVertex3f(scale * std::cos(angle), scale * std::sin(angle),
                                          0.2f * static_cast<float>(k) - 0.2f);
                           }
                           glEnd();
                       }});
    }
}

// Meshes of jittered vertices whose triangles share edges, drawn over each other's colors.
void addSharedEdgeMeshes(std::vector<Case>& out) {
    for (int seed = 0; seed < 20; ++seed) {
        out.push_back({"shared-edges", "mesh_" + std::to_string(seed), seed % 2 == 0, [seed](int w, int h) {
                           std::mt19937 random(static_cast<unsigned>(seed));
                           std::uniform_real_distribution<float> jitter(-1.7f, 1.7f);
                           resetState(w, h);
                           glShadeModel(seed % 2 == 0 ? GL_FLAT : GL_SMOOTH);
                           glMatrixMode(GL_PROJECTION);
                           glOrtho(0, w, 0, h, -1, 1);
                           constexpr int kGrid = 6;
                           float px[kGrid + 1][kGrid + 1], py[kGrid + 1][kGrid + 1];
                           for (int j = 0; j <= kGrid; ++j)
                               for (int i = 0; i <= kGrid; ++i) {
                                   px[j][i] = 2.0f + static_cast<float>(i) * (static_cast<float>(w) - 4.0f) / kGrid +
                                              jitter(random);
                                   py[j][i] = 2.0f + static_cast<float>(j) * (static_cast<float>(h) - 4.0f) / kGrid +
                                              jitter(random);
                               }
                           glBegin(GL_TRIANGLES);
                           for (int j = 0; j < kGrid; ++j)
                               for (int i = 0; i < kGrid; ++i) {
                                   color(i * 7 + j);
                                   glVertex2f(px[j][i], py[j][i]);
                                   glVertex2f(px[j][i + 1], py[j][i + 1]);
                                   glVertex2f(px[j + 1][i + 1], py[j + 1][i + 1]);
                                   color(i * 7 + j + 3);
                                   glVertex2f(px[j][i], py[j][i]);
                                   glVertex2f(px[j + 1][i + 1], py[j + 1][i + 1]);
                                   glVertex2f(px[j + 1][i], py[j + 1][i]);
                               }
                           glEnd();
                       }});
    }
}

// Consecutive glBegin/glEnd blocks with no state change between them are one draw in the
// reference: when one block crosses the window edge, the whole draw is clipped, which changes
// how the quads of the other block are split.
void addMergedBlocks(std::vector<Case>& out) {
    for (GLenum mode : {GL_QUADS, GL_TRIANGLES, GL_POLYGON, GL_QUAD_STRIP})
        for (bool secondCrosses : {false, true}) {
            const std::string name =
                std::string("merged_") + modeName(mode) + (secondCrosses ? "_crossing" : "_inside");
            out.push_back({"merged-blocks", name, false, [mode, secondCrosses](int w, int h) {
                               resetState(w, h);
                               const float shift = secondCrosses ? 1.5f : 0.3f;
                               // Ring order (corner by corner) for quads and polygons, zigzag for strips.
                               const bool ring = mode == GL_QUADS || mode == GL_POLYGON;
                               static const float ringX[8] = {0, 0.3f, 0.35f, 0.02f, 0.4f, 0.7f, 0.72f, 0.38f};
                               static const float ringY[8] = {-0.5f, -0.45f, 0.55f, 0.4f, -0.6f, -0.5f, 0.45f, 0.5f};
                               for (int block = 0; block < 2; ++block) {
                                   glBegin(mode);
                                   for (int i = 0; i < 8; ++i) {
                                       color(i + 3 * block);
                                       const float x = (ring ? ringX[i] : 0.2f * static_cast<float>(i / 2)) - 0.8f;
                                       const float y =
                                           ring ? ringY[i]
                                                : (i % 2 ? 0.5f : -0.55f) + 0.13f * static_cast<float>(i % 3);
                                       glVertex2f(x + (block ? shift : 0.0f), y);
                                   }
                                   glEnd();
                               }
                           }});
        }
}

// What ends a merged draw in the reference besides a state change: a block of another mode,
// even an empty one, and a block whose incomplete tail is dropped (its vertices stay in the
// reference's buffer, so the next block is not contiguous). Quad A is inside; whether it shares
// a draw with a quad that crosses the window edge decides its diagonal.
void addMergeBreakers(std::vector<Case>& out) {
    struct Between {
        const char* name;
        GLenum mode;
        int vertices;        // of the middle block; a whole quad first if 4 or more
        bool middleCrosses;  // the middle block's quad crosses the edge (else the last block's does)
    };
    static const Between kBetween[] = {{"empty_quads", GL_QUADS, 2, false},
                                       {"empty_triangles", GL_TRIANGLES, 2, false},
                                       {"quad_and_leftover", GL_QUADS, 6, false},
                                       {"crossing_quad_and_leftover", GL_QUADS, 5, true},
                                       {"crossing_quad", GL_QUADS, 4, true}};
    auto quad = [](int firstColor, float x0, float y0, float x1, float y1) {
        const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
        for (int i = 0; i < 4; ++i) {
            color(firstColor + i);
            glVertex2f(xs[i], ys[i]);
        }
    };
    for (const Between& between : kBetween) {
        out.push_back(
            {"merged-blocks", std::string("merge_break_") + between.name, false, [between, quad](int w, int h) {
                 resetState(w, h);
                 glBegin(GL_QUADS);
                 quad(0, -0.95f, -0.9f, -0.4f, 0.7f);
                 glEnd();
                 glBegin(between.mode);
                 if (between.vertices >= 4) quad(4, -0.3f, -0.6f, 0.3f, between.middleCrosses ? 1.4f : 0.6f);
                 for (int i = between.vertices >= 4 ? 4 : 0; i < between.vertices; ++i)
                     glVertex2f(0.05f * static_cast<float>(i), 0.0f);
                 glEnd();
                 glBegin(GL_QUADS);
                 quad(8, 0.4f, -0.5f, between.middleCrosses ? 0.95f : 1.3f, 0.5f);
                 glEnd();
             }});
    }
}

// Smooth points, lines and polygons and the two stipples (issue 16), each on a small drawing
// with blending off, as course programs turn them on.
void addSmoothAndStippleCases(std::vector<Case>& out) {
    struct Feature {
        const char* name;
        GLenum capability;
        GLenum mode;
    };
    static const Feature kFeatures[] = {{"point_smooth", GL_POINT_SMOOTH, GL_POINTS},
                                        {"line_smooth", GL_LINE_SMOOTH, GL_LINE_STRIP},
                                        {"polygon_smooth", GL_POLYGON_SMOOTH, GL_TRIANGLES},
                                        {"line_stipple", GL_LINE_STIPPLE, GL_LINE_STRIP},
                                        {"polygon_stipple", GL_POLYGON_STIPPLE, GL_TRIANGLES}};
    for (const Feature& f : kFeatures) {
        out.push_back({"smooth-stipple", f.name, true, [f](int width, int height) {
                           scenes::resetState(width, height);  // a cleared frame: no earlier case shows through
                           GLubyte pattern[128];
                           for (int i = 0; i < 128; ++i) pattern[i] = (i / 4) % 2 ? 0xAA : 0x55;
                           glPolygonStipple(pattern);
                           glLineStipple(2, 0x0F0F);
                           glPointSize(4.0f);
                           glEnable(f.capability);
                           glColor3f(1.0f, 0.5f, 0.25f);
                           glBegin(f.mode);
                           glVertex2f(-0.8f, -0.7f);
                           glVertex2f(0.7f, -0.5f);
                           glVertex2f(0.1f, 0.8f);
                           glEnd();
                           glDisable(f.capability);
                       }});
    }
}

// Smooth points and lines as programs draw them, blended over a triangle (issue 16): wide and
// thin, at sub-pixel positions, a strip's colours smooth.
void addBlendedSmoothCases(std::vector<Case>& out) {
    for (const float size : {1.0f, 3.5f, 7.0f}) {
        out.push_back({"smooth-stipple", "smooth_blended_size_" + std::to_string(static_cast<int>(size * 10)), true,
                       [size](int width, int height) {
                           scenes::resetState(width, height);
                           glBegin(GL_TRIANGLES);
                           glColor3f(0.2f, 0.3f, 0.6f);
                           glVertex2f(-0.9f, -0.9f), glVertex2f(0.9f, -0.6f), glVertex2f(-0.2f, 0.9f);
                           glEnd();
                           glEnable(GL_BLEND);
                           glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                           glEnable(GL_POINT_SMOOTH);
                           glEnable(GL_LINE_SMOOTH);
                           glPointSize(size);
                           glLineWidth(size);
                           glBegin(GL_LINE_STRIP);
                           glColor4f(1.0f, 0.9f, 0.2f, 1.0f), glVertex2f(-0.83f, -0.41f);
                           glColor4f(0.1f, 1.0f, 0.5f, 0.6f), glVertex2f(0.77f, 0.13f);
                           glColor4f(1.0f, 0.2f, 0.9f, 0.9f), glVertex2f(-0.31f, 0.86f);
                           glEnd();
                           glBegin(GL_POINTS);
                           glColor4f(1.0f, 1.0f, 1.0f, 0.8f);
                           for (float i = 0.0f; i < 7.0f; i += 1.0f) glVertex2f(-0.7f + 0.23f * i, -0.75f + 0.071f * i);
                           glEnd();
                           glDisable(GL_POINT_SMOOTH);
                           glDisable(GL_LINE_SMOOTH);
                           glDisable(GL_BLEND);
                       }});
    }
}

// Two overlapping smooth triangles of varying colour and alpha, at varying depths.
void fragmentOpsLayer(float shift) {
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.2f, 0.1f, 0.1f), glVertex3f(-0.9f + shift, -0.8f, -0.5f);
    glColor4f(0.2f, 1.0f, 0.4f, 0.9f), glVertex3f(0.8f, -0.6f + shift, 0.5f);
    glColor4f(0.3f, 0.3f, 1.0f, 0.5f), glVertex3f(-0.2f, 0.9f, 0.0f);
    glColor4f(0.9f, 0.8f, 0.1f, 0.7f), glVertex3f(0.9f, 0.9f, 0.7f);
    glColor4f(0.1f, 0.6f, 0.6f, 0.3f), glVertex3f(-0.7f + shift, 0.1f, -0.7f);
    glColor4f(0.8f, 0.1f, 0.8f, 0.6f), glVertex3f(0.3f, -0.9f, 0.2f);
    glEnd();
}

// The per-fragment operations (issue 16): each alpha function, each blend factor on each side,
// each logic op, stencil functions and operations, scissor boxes and colour masks, drawn as a
// second layer over a first.
void addFragmentOpsCases(std::vector<Case>& out) {
    const auto add = [&out](const std::string& name, std::function<void()> setUp) {
        out.push_back({"fragment-ops", name, false, [setUp](int width, int height) {
                           scenes::resetState(width, height);
                           glClearStencil(0);
                           glClear(GL_STENCIL_BUFFER_BIT);
                           glPushAttrib(GL_ALL_ATTRIB_BITS);  // the contexts serve the next cases too
                           glEnable(GL_DEPTH_TEST);
                           glDepthFunc(GL_LEQUAL);
                           glEnable(GL_STENCIL_TEST);
                           glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
                           fragmentOpsLayer(0.3f);
                           glDisable(GL_STENCIL_TEST);
                           glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
                           setUp();
                           fragmentOpsLayer(0.0f);
                           glPopAttrib();
                       }});
    };
    static const GLenum kFuncs[] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const GLenum kFactors[] = {GL_ZERO,
                                      GL_ONE,
                                      GL_SRC_COLOR,
                                      GL_ONE_MINUS_SRC_COLOR,
                                      GL_DST_COLOR,
                                      GL_ONE_MINUS_DST_COLOR,
                                      GL_SRC_ALPHA,
                                      GL_ONE_MINUS_SRC_ALPHA,
                                      GL_DST_ALPHA,
                                      GL_ONE_MINUS_DST_ALPHA,
                                      GL_SRC_ALPHA_SATURATE};
    for (GLenum func : kFuncs) {
        add("alpha_" + std::to_string(func), [func] { glEnable(GL_ALPHA_TEST), glAlphaFunc(func, 0.45f); });
        add("stencil_" + std::to_string(func), [func] {
            glEnable(GL_STENCIL_TEST), glStencilFunc(func, 1, 0xFF), glStencilOp(GL_INVERT, GL_DECR, GL_REPLACE);
        });
    }
    for (GLenum factor : kFactors) {
        add("blend_src_" + std::to_string(factor),
            [factor] { glEnable(GL_BLEND), glBlendFunc(factor, GL_ONE_MINUS_SRC_ALPHA); });
        add("blend_dst_" + std::to_string(factor), [factor] { glEnable(GL_BLEND), glBlendFunc(GL_SRC_ALPHA, factor); });
    }
    for (GLenum op = GL_CLEAR; op <= GL_SET; ++op) {
        add("logic_op_" + std::to_string(op), [op] { glEnable(GL_COLOR_LOGIC_OP), glLogicOp(op); });
    }
    for (int mask = 1; mask < 15; mask += 3) {
        add("color_mask_" + std::to_string(mask), [mask] { glColorMask(mask & 1, mask & 2, mask & 4, mask & 8); });
    }
    const int boxes[][4] = {{10, 5, 30, 20}, {-20, -20, 40, 40}, {50, 30, 1000, 1000}, {0, 0, 0, 0}};
    for (const auto& b : boxes) {
        add("scissor_" + std::to_string(b[0]) + "_" + std::to_string(b[1]), [b] {
            glEnable(GL_SCISSOR_TEST), glScissor(b[0], b[1], b[2], b[3]);
            glClearColor(0.5f, 0.1f, 0.3f, 1.0f), glClear(GL_COLOR_BUFFER_BIT);
        });
    }
}

// Textures: a quad in perspective and a small triangle, textured with an 8 x 8 image (and its
// mipmaps) across filters, wraps and environment modes, smooth colours per vertex.
void addTextureCases(std::vector<Case>& out) {
    struct Filter {
        const char* name;
        GLenum min, mag;
    };
    static const Filter kFilters[] = {{"nearest", GL_NEAREST, GL_NEAREST},
                                      {"linear", GL_LINEAR, GL_LINEAR},
                                      {"nearest_mag_linear", GL_NEAREST, GL_LINEAR},
                                      {"mipmap_nearest", GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR},
                                      {"mipmap_linear", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR}};
    struct Wrap {
        const char* name;
        GLenum wrap;
    };
    static const Wrap kWraps[] = {{"repeat", GL_REPEAT}, {"edge", 0x812F}, {"clamp", GL_CLAMP}};
    struct Env {
        const char* name;
        GLenum env;
    };
    static const Env kEnvs[] = {
        {"modulate", GL_MODULATE}, {"replace", GL_REPLACE}, {"decal", GL_DECAL}, {"blend", GL_BLEND}, {"add", GL_ADD}};
    auto draw = [](GLenum min, GLenum mag, GLenum wrap, GLenum env, bool constantColor, bool clipped) {
        glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        for (int level = 0, side = 8; side >= 1; ++level, side /= 2) {
            std::vector<GLubyte> texels;
            for (int y = 0; y < side; ++y) {
                for (int x = 0; x < side; ++x) {
                    const bool check = (x + y) % 2 == 0;
                    texels.insert(texels.end(), {GLubyte(check ? 230 : 30 * x), GLubyte(255 * y / 8),
                                                 GLubyte(40 * level), GLubyte(check ? 255 : 90 + 20 * y)});
                }
            }
            glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, side, side, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(env));
        const GLfloat envColor[] = {0.3f, 0.6f, 0.9f, 0.5f};
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColor);
        glEnable(GL_TEXTURE_2D);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 40.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glColor3f(0.9f, 0.8f, 0.7f);
        glBegin(GL_QUADS);
        // Inside the view volume, or crossing it (clipped by the near edges).
        const float x = clipped ? 2.0f : 1.0f, y = clipped ? -1.0f : -0.8f;
        const float corners[4][5] = {{-x, y, -1.5f, -0.4f, -0.3f},
                                     {x, y, -1.5f, 1.6f, -0.3f},
                                     {x, y, -30.0f, 1.6f, 6.0f},
                                     {-x, y, -30.0f, -0.4f, 6.0f}};
        for (int i = 0; i < 4; ++i) {
            if (!constantColor) glColor3f(0.5f + 0.15f * float(i), 1.0f - 0.2f * float(i), 0.6f);
            glTexCoord2f(corners[i][3], corners[i][4]);
            glVertex3f(corners[i][0], corners[i][1], corners[i][2]);
        }
        glEnd();
        glBegin(GL_TRIANGLES);
        glColor3f(1.0f, 0.7f, 0.4f);
        glTexCoord2f(0.1f, 0.2f);
        glVertex3f(-0.4f, 0.1f, -2.0f);
        glColor3f(0.3f, 1.0f, 0.8f);
        glTexCoord2f(1.3f, 0.1f);
        glVertex3f(0.5f, 0.0f, -2.2f);
        glColor3f(0.8f, 0.5f, 1.0f);
        glTexCoord2f(0.6f, 1.2f);
        glVertex3f(0.1f, 0.6f, -2.4f);
        glEnd();
        glDisable(GL_TEXTURE_2D);
    };
    for (const Filter& f : kFilters) {
        for (const Wrap& w : kWraps) {
            for (const Env& e : kEnvs) {
                const std::string name = std::string("texture_") + f.name + "_" + w.name + "_" + e.name;
                out.push_back(
                    {"textures", name, false, [=](int, int) { draw(f.min, f.mag, w.wrap, e.env, false, false); }});
            }
        }
    }
    out.push_back({"textures", "texture_linear_clamp_border_color", false, [=](int, int) {
                       const GLfloat border[] = {0.9f, 0.4f, 0.1f, 0.7f}, none[] = {0.0f, 0.0f, 0.0f, 0.0f};
                       glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
                       draw(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP, GL_DECAL, false, false);
                       glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, none);  // for the next cases
                   }});
    // A constant colour under texturing is exact (the reference takes it as a uniform).
    out.push_back({"textures", "texture_constant_color", true,
                   [=](int, int) { draw(GL_LINEAR, GL_LINEAR, GL_REPEAT, GL_MODULATE, true, false); }});
    out.push_back({"textures", "texture_clipped_quad", false,
                   [=](int, int) { draw(GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_MODULATE, false, true); }});
}

// Pixel rectangles: glDrawPixels and glCopyPixels at several zooms over a depth-tested
// triangle, in window coordinates; float images beyond [0, 1] under fog (which the reference
// may fog unclamped: an expected difference).
void addPixelRectangleCases(std::vector<Case>& out) {
    struct Zoom {
        const char* name;
        float x, y;
        GLenum format, type;
        GLenum copy;  // glCopyPixels' type, or 0 to draw
        bool fog;
    };
    static const Zoom kZooms[] = {
        {"drawpixels_zoom_1", 1.0f, 1.0f, GL_RGBA, GL_UNSIGNED_BYTE, 0, false},
        {"drawpixels_zoom_half", 0.5f, 0.5f, GL_RGBA, GL_UNSIGNED_BYTE, 0, false},
        {"drawpixels_zoom_mirrored", -1.5f, 2.25f, GL_RGBA, GL_UNSIGNED_SHORT, 0, false},
        {"drawpixels_rgba_float_fog", 1.25f, 1.0f, GL_RGBA, GL_FLOAT, 0, true},
        {"copypixels_overlapping", 1.0f, 1.0f, GL_RGBA, GL_UNSIGNED_BYTE, GL_COLOR, false},
        {"copypixels_zoomed", 0.75f, -1.5f, GL_RGBA, GL_UNSIGNED_BYTE, GL_COLOR, false},
        {"drawpixels_float_fog_no_depth_test", 1.25f, 1.0f, GL_RGB, GL_FLOAT, 0, true},
        {"drawpixels_depth_float", 1.0f, 1.0f, GL_DEPTH_COMPONENT, GL_FLOAT, 0, false},
        {"drawpixels_depth_ushort_zoomed", 1.5f, -2.0f, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 0, true},
        {"drawpixels_stencil_index", 1.0f, 1.0f, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 0, false},
        {"drawpixels_color_index_zoomed", 2.0f, 1.5f, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, 0, false},
        {"copypixels_depth_overlapping", 1.0f, 1.0f, GL_RGBA, GL_UNSIGNED_BYTE, GL_DEPTH, false},
        {"copypixels_depth_zoomed", 2.0f, 1.5f, GL_RGBA, GL_UNSIGNED_BYTE, GL_DEPTH, false},
        {"copypixels_stencil_zoomed", -1.0f, 2.0f, GL_RGBA, GL_UNSIGNED_BYTE, GL_STENCIL, false}};
    for (const Zoom& z : kZooms) {
        out.push_back({"pixel-rectangles", z.name, false, [z](int w, int h) {
                           resetState(w, h);
                           glMatrixMode(GL_PROJECTION);
                           glLoadIdentity();
                           glOrtho(0, w, 0, h, -1, 1);
                           glMatrixMode(GL_MODELVIEW);
                           if (!z.fog || z.format == GL_RGBA) glEnable(GL_DEPTH_TEST);
                           glBegin(GL_TRIANGLES);
                           glColor3f(0.2f, 0.7f, 0.3f);
                           glVertex3f(2, 2, 0.8f);
                           glColor3f(0.9f, 0.2f, 0.5f);
                           glVertex3f(60, 10, -0.8f);
                           glColor3f(0.1f, 0.3f, 0.9f);
                           glVertex3f(20, 46, 0.0f);
                           glEnd();
                           constexpr int kImage = 20;
                           float pixels[kImage * kImage * 4];
                           GLushort shorts[kImage * kImage * 4];
                           GLubyte bytes[kImage * kImage * 4];
                           for (int i = 0; i < kImage * kImage * 4; ++i) {
                               pixels[i] = static_cast<float>((i * 29) % 97) / 69.0f - 0.2f;
                               shorts[i] = static_cast<GLushort>((i * 4099) % 65536);
                               bytes[i] = static_cast<GLubyte>((i * 37) % 256);
                           }
                           if (z.fog) {
                               glEnable(GL_FOG);
                               glFogi(GL_FOG_MODE, GL_LINEAR);
                               glFogf(GL_FOG_START, -1.0f);
                               glFogf(GL_FOG_END, 2.0f);
                           }
                           glPixelZoom(z.x, z.y);
                           glRasterPos3f(z.x < 0 ? 40.0f : 10.0f, 6.0f, 0.1f);
                           // Index images through maps of a few entries (reset after: maps are no attribute).
                           const GLfloat ramp[4] = {0.1f, 0.9f, 0.4f, 0.7f}, none = 0.0f;
                           if (z.format == GL_COLOR_INDEX) {
                               for (GLenum map = GL_PIXEL_MAP_I_TO_R; map <= GL_PIXEL_MAP_I_TO_A; ++map)
                                   glPixelMapfv(map, 4, ramp);
                           }
                           if (z.copy) {
                               glCopyPixels(4, 3, 30, 24, z.copy);
                           } else {
                               const void* data = z.type == GL_FLOAT            ? static_cast<const void*>(pixels)
                                                  : z.type == GL_UNSIGNED_SHORT ? static_cast<const void*>(shorts)
                                                                                : static_cast<const void*>(bytes);
                               glDrawPixels(kImage, kImage, z.format, z.type, data);
                           }
                           glPixelZoom(1.0f, 1.0f);
                           glDisable(GL_FOG);
                           for (GLenum map = GL_PIXEL_MAP_I_TO_R; map <= GL_PIXEL_MAP_I_TO_A; ++map)
                               glPixelMapfv(map, 1, &none);
                       }});
    }
}

}  // namespace

std::vector<Case> allCases() {
    std::vector<Case> cases;
    addModeCases(cases);
    addRandomTriangles(cases);
    addSpecialTriangles(cases);
    addSharedEdgeMeshes(cases);
    addMergedBlocks(cases);
    addMergeBreakers(cases);
    addSmoothAndStippleCases(cases);
    addBlendedSmoothCases(cases);
    addFragmentOpsCases(cases);
    addTextureCases(cases);
    addPixelRectangleCases(cases);
    // Last: the API cases leave state the drawing cases do not reset.
    std::vector<Case> api = apiCases();
    cases.insert(cases.end(), std::make_move_iterator(api.begin()), std::make_move_iterator(api.end()));
    return cases;
}

}  // namespace conformance
