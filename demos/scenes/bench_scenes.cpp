#include "bench_scenes.h"

#include <glad/gl.h>
#include <mygl/glu.h>

#include <cmath>
#include <random>
#include <vector>

#include "scene.h"

namespace scenes {
namespace {

constexpr float kTwoPi = 6.28318530718f;

void perspectiveView(int width, int height, float distance) {
    glMatrixMode(GL_PROJECTION);
    gluPerspective(40.0, static_cast<double>(width) / height, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -distance);
}

// A torus of (rings x sides) quads as triangle strips, colored by its normal, or given the
// normal itself for lighting (`lit`).
void torus(float major, float minor, int rings, int sides, bool lit = false) {
    for (int r = 0; r < rings; ++r) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int s = 0; s <= sides; ++s) {
            for (int k = 1; k >= 0; --k) {
                const float u = static_cast<float>(r + k) * kTwoPi / static_cast<float>(rings);
                const float v = static_cast<float>(s) * kTwoPi / static_cast<float>(sides);
                const float nx = std::cos(u) * std::cos(v), ny = std::sin(u) * std::cos(v), nz = std::sin(v);
                if (lit)
                    glNormal3f(nx, ny, nz);
                else
                    glColor3f(0.5f + 0.5f * nx, 0.5f + 0.5f * ny, 0.5f + 0.5f * nz);
                glVertex3f((major + minor * std::cos(v)) * std::cos(u), (major + minor * std::cos(v)) * std::sin(u),
                           minor * nz);
            }
        }
        glEnd();
    }
}

// A gear in the z = 0..width slab: a toothed ring of quads, flat shaded.
void gear(float inner, float outer, float width, int teeth, float toothDepth) {
    const float r0 = inner, r1 = outer - toothDepth / 2.0f, r2 = outer + toothDepth / 2.0f;
    const float da = kTwoPi / static_cast<float>(teeth) / 4.0f;
    for (float z : {width * 0.5f, -width * 0.5f}) {  // the two faces
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= teeth; ++i) {
            const float a = static_cast<float>(i) * kTwoPi / static_cast<float>(teeth);
            glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
            glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
            glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
            glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
        }
        glEnd();
        glBegin(GL_QUADS);  // the teeth's faces
        for (int i = 0; i < teeth; ++i) {
            const float a = static_cast<float>(i) * kTwoPi / static_cast<float>(teeth);
            glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
            glVertex3f(r2 * std::cos(a + da), r2 * std::sin(a + da), z);
            glVertex3f(r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da), z);
            glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
        }
        glEnd();
    }
    glBegin(GL_QUAD_STRIP);  // the outward faces of the teeth
    for (int i = 0; i < teeth; ++i) {
        const float a = static_cast<float>(i) * kTwoPi / static_cast<float>(teeth);
        const float corners[4][2] = {{r1, a}, {r2, a + da}, {r2, a + 2 * da}, {r1, a + 3 * da}};
        for (const auto& [r, angle] : corners) {
            glVertex3f(r * std::cos(angle), r * std::sin(angle), width * 0.5f);
            glVertex3f(r * std::cos(angle), r * std::sin(angle), -width * 0.5f);
        }
    }
    glVertex3f(r1, 0.0f, width * 0.5f);
    glVertex3f(r1, 0.0f, -width * 0.5f);
    glEnd();
}

// bench-cubes' 1000 cubes in a 10 x 10 x 10 block, turning with the frame, each drawn by `drawOne`.
template <class DrawOne>
void drawCubeField(int width, int height, int frame, DrawOne drawOne) {
    perspectiveView(width, height, 30.0f);
    glRotatef(25.0f + static_cast<float>(frame), 1.0f, 1.0f, 0.0f);
    for (int i = 0; i < 1000; ++i) {
        glPushMatrix();
        glTranslatef(static_cast<float>(i % 10) * 2.2f - 9.9f, static_cast<float>(i / 10 % 10) * 2.2f - 9.9f,
                     static_cast<float>(i / 100) * 2.2f - 9.9f);
        glRotatef(static_cast<float>(i * 37 % 360), 0.3f, 1.0f, 0.2f);
        glScalef(0.6f, 0.6f, 0.6f);
        drawOne();
        glPopMatrix();
    }
}

}  // namespace

void drawBenchTorus(int width, int height, int frame) {
    beginFrame(width, height, true, true);
    perspectiveView(width, height, 7.0f);
    glRotatef(30.0f + static_cast<float>(frame) * 5.0f, 1.0f, 0.4f, 0.0f);
    torus(1.8f, 0.7f, 256, 128);  // 256 * 128 * 2 = 65536 triangles
}

void drawBenchLitTorus(int width, int height, int frame) {
    beginFrame(width, height, true, true);
    perspectiveView(width, height, 7.0f);
    const GLfloat white[] = {1, 1, 1, 1}, warm[] = {1.0f, 0.8f, 0.5f, 1};
    const GLfloat spotPosition[] = {0.0f, 0.0f, 2.0f, 1.0f}, spotDirection[] = {0.0f, 0.0f, -1.0f};
    const GLfloat sun[] = {-0.5f, 0.7f, 0.6f, 0.0f};
    const GLfloat diffuse[] = {0.7f, 0.35f, 0.25f, 1}, specular[] = {0.8f, 0.8f, 0.8f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, spotPosition);  // a spot from the viewer's side
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spotDirection);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0f);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 8.0f);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_POSITION, sun);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glRotatef(30.0f + static_cast<float>(frame) * 5.0f, 1.0f, 0.4f, 0.0f);
    torus(1.8f, 0.7f, 128, 64, true);  // 128 * 64 * 2 = 16384 triangles
    glDisable(GL_LIGHTING);
}

void drawBenchFill(int width, int height, int) {
    beginFrame(width, height, true, false);
    for (int i = 0; i < 32; ++i) {  // back to front: every quad passes the depth test
        const float z = 0.95f - static_cast<float>(i) * 0.06f;
        glColor3f(static_cast<float>(i % 4) / 3.0f, static_cast<float>(i % 7) / 6.0f, 0.5f);
        glBegin(GL_QUADS);
        glVertex3f(-1.0f, -1.0f, z);
        glVertex3f(1.0f, -1.0f, z);
        glColor3f(0.2f, static_cast<float>(i % 5) / 4.0f, 0.9f);
        glVertex3f(1.0f, 1.0f, z);
        glVertex3f(-1.0f, 1.0f, z);
        glEnd();
    }
}

void drawBenchCubes(int width, int height, int frame) {
    static const float colors[6][3] = {{0.9f, 0.2f, 0.2f},   {0.2f, 0.8f, 0.3f},   {0.25f, 0.35f, 0.95f},
                                       {0.95f, 0.85f, 0.2f}, {0.85f, 0.3f, 0.85f}, {0.2f, 0.85f, 0.85f}};
    beginFrame(width, height, true, true);
    drawCubeField(width, height, frame, [] { drawCube(colors); });
}

namespace {

// Texture 1 of the current context: a 64 x 64 brick-like pattern with every mipmap level,
// made once per context (a fresh context's first name), then only bound.
void bindBenchTexture() {
    if (!glIsTexture(1)) {
        GLuint name = 0;
        glGenTextures(1, &name);
        glBindTexture(GL_TEXTURE_2D, name);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        for (int level = 0, side = 64; side >= 1; ++level, side /= 2) {
            std::vector<GLubyte> texels;
            for (int y = 0; y < side; ++y) {
                for (int x = 0; x < side; ++x) {
                    const int s = x * 64 / side, t = y * 64 / side;
                    const bool mortar = t % 16 < 2 || (s + (t / 16 % 2) * 16) % 32 < 2;
                    texels.insert(texels.end(), {GLubyte(mortar ? 200 : 150 + (s * 7 + t * 3) % 60),
                                                 GLubyte(mortar ? 200 : 70), GLubyte(mortar ? 190 : 50 + level * 20)});
                }
            }
            glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
    glBindTexture(GL_TEXTURE_2D, 1);
}

// A unit cube with texture coordinates over each face and a colour per face.
void drawTexturedCube(const float (*faceColors)[3]) {
    static const float corners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6}, {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    static const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; ++f) {
        glColor3fv(faceColors[f]);
        for (int k = 0; k < 4; ++k) {
            glTexCoord2fv(st[k]);
            glVertex3fv(corners[faces[f][k]]);
        }
    }
    glEnd();
}

}  // namespace

void drawBenchTexturedCubes(int width, int height, int frame) {
    static const float colors[6][3] = {{1.0f, 0.8f, 0.8f}, {0.8f, 1.0f, 0.8f}, {0.8f, 0.85f, 1.0f},
                                       {1.0f, 1.0f, 0.8f}, {1.0f, 0.8f, 1.0f}, {0.8f, 1.0f, 1.0f}};
    beginFrame(width, height, true, true);
    bindBenchTexture();
    glEnable(GL_TEXTURE_2D);
    drawCubeField(width, height, frame, [] { drawTexturedCube(colors); });
    glDisable(GL_TEXTURE_2D);
}

// A 256 x 256 RGBA image (rings over a gradient) drawn with glDrawPixels each frame, zoomed
// to cover the window and a little more every frame (the zoom cycles over 4 frames).
void drawBenchDrawPixels(int width, int height, int frame) {
    constexpr int kSize = 256;
    static const std::vector<GLubyte> image = [] {
        std::vector<GLubyte> pixels(kSize * kSize * 4);
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                GLubyte* p = &pixels[static_cast<std::size_t>((y * kSize + x) * 4)];
                const int ring = ((x - 128) * (x - 128) + (y - 128) * (y - 128)) / 256;
                p[0] = static_cast<GLubyte>(x);
                p[1] = static_cast<GLubyte>(y);
                p[2] = static_cast<GLubyte>(ring % 2 ? 255 : 64);
                p[3] = 255;
            }
        }
        return pixels;
    }();
    beginFrame(width, height, false, false);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width, 0, height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const float grow = 1.0f + 0.05f * static_cast<float>(frame % 4);
    glPixelZoom(static_cast<float>(width) / kSize * grow, static_cast<float>(height) / kSize * grow);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glRasterPos2i(0, 0);
    glDrawPixels(kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    glPixelZoom(1.0f, 1.0f);
}

void drawBenchTiny(int width, int height, int) {
    beginFrame(width, height, true, false);
    std::mt19937 random(1);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), c(0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 100000; ++i) {
        const float x = u(random), y = u(random), z = u(random) * 0.9f;
        for (int k = 0; k < 3; ++k) {
            glColor3f(c(random), c(random), c(random));
            glVertex3f(x + u(random) * 0.006f, y + u(random) * 0.008f, z);
        }
    }
    glEnd();
}

namespace {

// The gears of glxgears' layout, drawn at once or from display lists compiled on the first frame
// of a context.
void gears(int width, int height, int frame, bool fromLists) {
    beginFrame(width, height, true, true);
    glShadeModel(GL_FLAT);
    perspectiveView(width, height, 30.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    const float angle = static_cast<float>(frame) * 2.0f;
    const struct {
        float x, y, rotation, color[3], inner, outer, width;
        int teeth;
    } gears[3] = {{-3.0f, -2.0f, angle, {0.8f, 0.1f, 0.0f}, 1.0f, 4.0f, 1.0f, 20},
                  {3.1f, -2.0f, -2.0f * angle - 9.0f, {0.0f, 0.8f, 0.2f}, 0.5f, 2.0f, 2.0f, 10},
                  {-3.1f, 4.2f, -2.0f * angle - 25.0f, {0.2f, 0.2f, 1.0f}, 1.3f, 2.0f, 0.5f, 10}};
    constexpr GLuint kFirstList = 1;
    const auto draw = [](const auto& g) {
        glColor3fv(g.color);
        gear(g.inner, g.outer, g.width, g.teeth, 0.7f);
    };
    if (fromLists && !glIsList(kFirstList)) {
        for (GLuint i = 0; i < 3; ++i) {
            glNewList(kFirstList + i, GL_COMPILE);
            draw(gears[i]);
            glEndList();
        }
    }
    for (GLuint i = 0; i < 3; ++i) {
        glPushMatrix();
        glTranslatef(gears[i].x, gears[i].y, 0.0f);
        glRotatef(gears[i].rotation, 0.0f, 0.0f, 1.0f);
        if (fromLists)
            glCallList(kFirstList + i);
        else
            draw(gears[i]);
        glPopMatrix();
    }
}

// A wavy terrain of 224 x 224 quads (100352 triangles), a colour per vertex by height and
// texture coordinates that repeat a ground texture 12 times across it.
struct Terrain {
    static constexpr int kQuads = 224;
    std::vector<GLfloat> positions, colors, texCoords;
    std::vector<GLuint> indices;
    Terrain() {
        constexpr int n = kQuads + 1;
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const float x = static_cast<float>(i) / kQuads * 2.0f - 1.0f,
                            y = static_cast<float>(j) / kQuads * 2.0f - 1.0f;
                const float h = 0.12f * std::sin(7.0f * x) * std::cos(5.0f * y) + 0.05f * std::sin(23.0f * x * y);
                positions.insert(positions.end(), {x, y, h});
                colors.insert(colors.end(), {0.3f + 2.0f * h, 0.6f - h, 0.4f + 3.0f * h});
                texCoords.insert(texCoords.end(),
                                 {static_cast<float>(i) * 12.0f / kQuads, static_cast<float>(j) * 12.0f / kQuads});
            }
        }
        for (int j = 0; j < kQuads; ++j) {
            for (int i = 0; i < kQuads; ++i) {
                const GLuint v = static_cast<GLuint>(j * n + i);
                indices.insert(indices.end(), {v, v + 1, v + n + 1, v, v + n + 1, v + n});
            }
        }
    }
};

}  // namespace

void drawBenchGears(int width, int height, int frame) { gears(width, height, frame, false); }

void drawBenchGearsLists(int width, int height, int frame) { gears(width, height, frame, true); }

namespace {

// The terrain mesh seen from above at an angle, turning with the frame, after `setup`; with
// its texture coordinates when `textured`.
void terrainScene(int width, int height, int frame, void (*setup)(), bool textured = false) {
    static const Terrain terrain;
    beginFrame(width, height, true, true);
    setup();
    perspectiveView(width, height, 2.6f);
    glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(static_cast<float>(frame) * 3.0f, 0.0f, 0.0f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, terrain.positions.data());
    glColorPointer(3, GL_FLOAT, 0, terrain.colors.data());
    if (textured) {
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, terrain.texCoords.data());
    }
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(terrain.indices.size()), GL_UNSIGNED_INT, terrain.indices.data());
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

}  // namespace

void drawBenchMesh(int width, int height, int frame) {
    terrainScene(width, height, frame, [] {});
}

namespace {

// LINEAR fog into a haze from 1.8 to 3.6 units from the eye.
void hazeFog() {
    const GLfloat haze[] = {0.7f, 0.75f, 0.8f, 1.0f};
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 1.8f);
    glFogf(GL_FOG_END, 3.6f);
    glFogfv(GL_FOG_COLOR, haze);
}

// A 64 x 64 ground texture (grass with pebbles, from a hash of the texel) with mipmaps from
// gluBuild2DMipmaps, LINEAR_MIPMAP_LINEAR, repeating, MODULATE: made once per context under a
// name of its own, then only bound.
void bindGroundTexture() {
    constexpr GLuint kGround = 2;  // apart from bench-textured-cubes' texture 1
    const bool made = glIsTexture(kGround);
    glBindTexture(GL_TEXTURE_2D, kGround);
    if (!made) {
        constexpr int kSide = 64;
        std::vector<GLubyte> texels;
        for (int y = 0; y < kSide; ++y) {
            for (int x = 0; x < kSide; ++x) {
                const unsigned hash = (static_cast<unsigned>(x) * 73856093u) ^ (static_cast<unsigned>(y) * 19349663u);
                const int noise = static_cast<int>(hash >> 7 & 63);
                const bool pebble = (hash >> 13 & 31) == 0;
                texels.insert(texels.end(), {GLubyte(pebble ? 170 : 70 + noise), GLubyte(pebble ? 165 : 130 + noise),
                                             GLubyte(pebble ? 150 : 50 + noise / 2)});
            }
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, kSide, kSide, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
}

}  // namespace

void drawBenchFogTerrain(int width, int height, int frame) { terrainScene(width, height, frame, hazeFog); }

void drawBenchFogTexturedTerrain(int width, int height, int frame) {
    terrainScene(
        width, height, frame,
        [] {
            hazeFog();
            bindGroundTexture();
            glEnable(GL_TEXTURE_2D);
        },
        true);
    glDisable(GL_TEXTURE_2D);
}

// Particles: an opaque floor, then 1600 smooth quads (as triangle pairs) and 400 points of varying alpha blended with
// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, depth-tested without depth writes, as a fountain of sparks.
void drawBenchParticles(int width, int height, int frame) {
    beginFrame(width, height, true, false);  // particles face the viewer: no culling
    perspectiveView(width, height, 9.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glColor3f(0.25f, 0.3f, 0.35f);
    glBegin(GL_QUADS);
    glVertex3f(-6.0f, -2.0f, 6.0f), glVertex3f(6.0f, -2.0f, 6.0f), glVertex3f(6.0f, -2.0f, -6.0f),
        glVertex3f(-6.0f, -2.0f, -6.0f);
    glEnd();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float t = static_cast<float>(frame) * 0.05f;
    const auto place = [&](float& x, float& y, float& z) {
        const float a = unit(random) * kTwoPi, r = unit(random) * 3.0f, h = std::fmod(unit(random) * 4.0f + t, 4.0f);
        x = r * std::cos(a), y = h - 2.0f + 0.5f * std::sin(r + t), z = r * std::sin(a);
    };
    // Each quad as two triangles, as the scene was first measured (a GL_QUADS block this long
    // is reproduced too, segment by segment: DrawModuleCulling.LongQuadDrawsChooseThePathPerSegment).
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 1600; ++i) {
        float x, y, z;
        place(x, y, z);
        const float s = 0.08f + 0.12f * unit(random), alpha = 0.2f + 0.6f * unit(random);
        const float corners[4][6] = {{x - s, y - s, 1.0f, 0.6f + 0.4f * unit(random), 0.2f, alpha},
                                     {x + s, y - s, 1.0f, 0.5f, 0.1f, alpha * 0.5f},
                                     {x + s, y + s, 1.0f, 0.9f, 0.4f, alpha},
                                     {x - s, y + s, 0.9f, 0.4f, 0.1f, alpha * 0.7f}};
        for (int corner : {0, 1, 2, 0, 2, 3}) {
            const float* c = corners[corner];
            glColor4f(c[2], c[3], c[4], c[5]), glVertex3f(c[0], c[1], z);
        }
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 400; ++i) {
        float x, y, z;
        place(x, y, z);
        glColor4f(1.0f, 1.0f, 0.7f, 0.3f + 0.5f * unit(random)), glVertex3f(x, y, z);
    }
    glEnd();
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

}  // namespace scenes
