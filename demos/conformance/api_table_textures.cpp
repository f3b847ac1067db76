// The API table's texture functions: objects, images, parameters, environment, coordinate
// generation.
#include <glad/gl.h>

#include <algorithm>
#include <string>

#include "api_table.h"

namespace conformance {
namespace {

constexpr GLenum kBad = kBadEnum;

GLubyte texels[8 * 8 * 4];

// A 2D texture of 4x4 texels bound to the name `name`.
void texture2D(GLuint name) {
    glBindTexture(GL_TEXTURE_2D, name);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
}

void deleteTextures(Observations&) {
    GLuint names[16];
    for (GLuint i = 0; i < 16; ++i) names[i] = i + 1;
    glDeleteTextures(16, names);
    glBindTexture(GL_TEXTURE_1D, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

// The bound 2D (or 1D) texture's level 0: its size, format and texels.
ApiCall textureImage(GLenum target) {
    return [target](Observations& o) {
        for (GLenum pname : {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_BORDER,
                             GL_TEXTURE_RED_SIZE}) {
            GLint v = -12345;
            glGetTexLevelParameteriv(target, 0, pname, &v);
            o.value("level 0 parameter " + std::to_string(pname), v);
        }
        GLubyte back[8 * 8 * 4];
        std::fill(std::begin(back), std::end(back), GLubyte{0xA5});
        glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        o.bytes("glGetTexImage", back, sizeof back);
    };
}

ApiCall texParameter(GLenum target, GLenum pname) {
    return [target, pname](Observations& o) {
        o.floatsAndInts(
            "glGetTexParameter", [&](GLfloat* v) { glGetTexParameterfv(target, pname, v); },
            [&](GLint* v) { glGetTexParameteriv(target, pname, v); });
    };
}

ApiCall texEnv(GLenum pname) {
    return [pname](Observations& o) {
        o.floatsAndInts(
            "glGetTexEnv", [&](GLfloat* v) { glGetTexEnvfv(GL_TEXTURE_ENV, pname, v); },
            [&](GLint* v) { glGetTexEnviv(GL_TEXTURE_ENV, pname, v); });
    };
}

ApiCall texGen(GLenum coord, GLenum pname) {
    return [coord, pname](Observations& o) {
        GLdouble d[4] = {-1, -1, -1, -1};
        glGetTexGendv(coord, pname, d);
        o.doubles("glGetTexGendv", d, 4);
        o.floatsAndInts(
            "glGetTexGen", [&](GLfloat* v) { glGetTexGenfv(coord, pname, v); },
            [&](GLint* v) { glGetTexGeniv(coord, pname, v); });
    };
}

}  // namespace

std::vector<ApiFunction> textureApiTable() {
    for (std::size_t i = 0; i < sizeof texels; ++i) texels[i] = static_cast<GLubyte>(i * 29 + 3);
    static const GLuint kNames[2] = {7, 0}, kUnknown[1] = {999};
    static const GLclampf kPriority[1] = {0.25f};
    static const GLfloat kParamsF[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    static const GLint kParamsI[4] = {GL_NEAREST, 0, 0, 0};
    static const GLdouble kPlaneD[4] = {1.0, 0.5, -0.25, 2.0};
    static const GLint kPlaneI[4] = {1, 2, 3, 4};
    return {
        // Texture objects and images.
        {"glGenTextures",
         "texture",
         [](Observations& o) {
             GLuint names[3] = {0, 0, 0};
             glGenTextures(3, names);
             o.uints("glGenTextures", names, 3);
         },
         {[](Observations&) {
             GLuint names[1] = {0};
             glGenTextures(-1, names);
         }},
         {},
         false,
         deleteTextures},
        {"glBindTexture",
         "texture",
         API_CALL(texture2D(5)),
         {API_CALL(glBindTexture(kBad, 5)), API_CALL(glBindTexture(GL_TEXTURE_1D, 5))},
         [](Observations& o) {
             o.get({GL_TEXTURE_BINDING_1D, GL_TEXTURE_BINDING_2D});
             o.value("glIsTexture(5)", glIsTexture(5));
         },
         false,
         deleteTextures},
        {"glDeleteTextures",
         "texture",
         API_CALL(texture2D(6); const GLuint n[1] = {6}; glDeleteTextures(1, n)),
         {API_CALL(const GLuint n[1] = {6}; glDeleteTextures(-1, n))},
         [](Observations& o) {
             o.get({GL_TEXTURE_BINDING_2D});
             o.value("glIsTexture(6)", glIsTexture(6));
         },
         false,
         deleteTextures},
        {"glIsTexture",
         "texture",
         [](Observations& o) {
             texture2D(3);
             o.value("glIsTexture(0)", glIsTexture(0));
             o.value("glIsTexture(3)", glIsTexture(3));
             o.value("glIsTexture(4)", glIsTexture(4));
         },
         {},
         {},
         false,
         deleteTextures},
        {"glAreTexturesResident",
         "texture",
         [](Observations& o) {
             texture2D(7);
             GLboolean resident[2] = {0xA5, 0xA5};
             o.value("glAreTexturesResident", glAreTexturesResident(1, kNames, resident));
             o.bytes("residences", resident, 2);
         },
         {API_CALL(GLboolean r[2]; glAreTexturesResident(-1, kNames, r)),
          API_CALL(GLboolean r[2]; glAreTexturesResident(2, kNames, r)),
          API_CALL(GLboolean r[2]; glAreTexturesResident(1, kUnknown, r))},
         {},
         false,
         deleteTextures},
        {"glPrioritizeTextures",
         "texture",
         API_CALL(texture2D(7); glPrioritizeTextures(1, kNames, kPriority)),
         {notCompiled(API_CALL(glPrioritizeTextures(-1, kNames, kPriority)))},
         get({GL_TEXTURE_BINDING_2D}),
         false,
         deleteTextures},
        // Compiled into a list, Mesa's glPrioritizeTextures keeps one entry per texture: a negative
        // count leaves nothing, and no error when the list runs. An expected difference.
        {"glPrioritizeTextures:in_list",
         "texture",
         API_CALL(texture2D(7); glPrioritizeTextures(1, kNames, kPriority)),
         {API_CALL(glPrioritizeTextures(-1, kNames, kPriority))},
         get({GL_TEXTURE_BINDING_2D}),
         false,
         deleteTextures},
        // The spec rounds a priority asked as an integer, Mesa maps [0, 1] to [0, INT_MAX]: an expected difference.
        {"glGetTexParameteriv:priority",
         "texture",
         API_CALL(texture2D(7); glPrioritizeTextures(1, kNames, kPriority)),
         {},
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY),
         false,
         deleteTextures},
        {"glTexImage1D",
         "texture",
         API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
         {API_CALL(glTexImage1D(kBad, 0, GL_RGB, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, -1, GL_RGB, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, kBad, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, -8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, kBad, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGBA, kBad, texels)),
          API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 8, 0, GL_RGBA, GL_BITMAP, texels))},
         textureImage(GL_TEXTURE_1D),
         false,
         deleteTextures},
        {"glTexImage2D",
         "texture",
         API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
         {API_CALL(glTexImage2D(kBad, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, kBad, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, -4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, -1, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, kBad, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, kBad, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_BITMAP, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 20, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 40000, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glTexSubImage1D",
         "texture",
         API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
                  glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 3, GL_RGB, GL_UNSIGNED_BYTE, texels + 100)),
         {API_CALL(glTexSubImage1D(kBad, 0, 2, 3, GL_RGB, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, -1, 2, 3, GL_RGB, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 0, -1, 3, GL_RGB, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 0, 6, 3, GL_RGB, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 0, 2, -3, GL_RGB, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 3, kBad, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 0, 2, 3, GL_RGB, kBad, texels)),
          API_CALL(glTexSubImage1D(GL_TEXTURE_1D, 2, 0, 1, GL_RGB, GL_UNSIGNED_BYTE, texels))},
         textureImage(GL_TEXTURE_1D),
         false,
         deleteTextures},
        {"glTexSubImage2D",
         "texture",
         API_CALL(texture2D(2);
                  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, texels + 60)),
         {API_CALL(glTexSubImage2D(kBad, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, -1, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 1, -1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, -2, GL_RGBA, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, kBad, GL_UNSIGNED_BYTE, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, kBad, texels)),
          API_CALL(glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glCopyTexImage1D",
         "texture",
         API_CALL(glClearColor(0.2f, 0.4f, 0.6f, 0.8f); glClear(GL_COLOR_BUFFER_BIT);
                  glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 3, 4, 8, 0)),
         {API_CALL(glCopyTexImage1D(kBad, 0, GL_RGB, 0, 0, 8, 0)),
          API_CALL(glCopyTexImage1D(GL_TEXTURE_1D, -1, GL_RGB, 0, 0, 8, 0)),
          API_CALL(glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 0, 0, -8, 0)),
          API_CALL(glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 0, 0, 8, 2))},
         textureImage(GL_TEXTURE_1D),
         false,
         deleteTextures},
        {"glCopyTexImage2D",
         "texture",
         API_CALL(glClearColor(0.6f, 0.4f, 0.2f, 1.0f); glClear(GL_COLOR_BUFFER_BIT);
                  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 3, 8, 4, 0)),
         {API_CALL(glCopyTexImage2D(kBad, 0, GL_RGB, 0, 0, 8, 8, 0)),
          API_CALL(glCopyTexImage2D(GL_TEXTURE_2D, -1, GL_RGB, 0, 0, 8, 8, 0)),
          API_CALL(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 8, -8, 0)),
          API_CALL(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 8, 8, 3))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        // The spec makes a bad internal format GL_INVALID_VALUE (as for glTexImage), Mesa's
        // glCopyTexImage GL_INVALID_ENUM: cases of their own, expected differences.
        {"glCopyTexImage1D:internal_format",
         "texture",
         API_CALL(glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 0, 0, 4, 0)),
         {API_CALL(glCopyTexImage1D(GL_TEXTURE_1D, 0, kBad, 0, 0, 8, 0))},
         textureImage(GL_TEXTURE_1D),
         false,
         deleteTextures},
        {"glCopyTexImage2D:internal_format",
         "texture",
         API_CALL(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 4, 4, 0)),
         {API_CALL(glCopyTexImage2D(GL_TEXTURE_2D, 0, kBad, 0, 0, 8, 8, 0))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glCopyTexSubImage1D",
         "texture",
         API_CALL(glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
                  glClearColor(0.1f, 0.7f, 0.3f, 0.5f); glClear(GL_COLOR_BUFFER_BIT);
                  glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 2, 5, 5, 3)),
         {API_CALL(glCopyTexSubImage1D(kBad, 0, 0, 0, 0, 2)),
          API_CALL(glCopyTexSubImage1D(GL_TEXTURE_1D, -1, 0, 0, 0, 2)),
          API_CALL(glCopyTexSubImage1D(GL_TEXTURE_1D, 0, -1, 0, 0, 2)),
          API_CALL(glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 7, 0, 0, 2)),
          API_CALL(glCopyTexSubImage1D(GL_TEXTURE_1D, 3, 0, 0, 0, 1))},
         textureImage(GL_TEXTURE_1D),
         false,
         deleteTextures},
        {"glCopyTexSubImage2D",
         "texture",
         API_CALL(texture2D(4); glClearColor(0.9f, 0.1f, 0.5f, 0.25f); glClear(GL_COLOR_BUFFER_BIT);
                  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 5, 5, 3, 2)),
         {API_CALL(glCopyTexSubImage2D(kBad, 0, 0, 0, 0, 0, 2, 2)),
          API_CALL(glCopyTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 0, 0, 2, 2)),
          API_CALL(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, -1, 0, 0, 2, 2)),
          API_CALL(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 0, 2, 2)),
          API_CALL(glCopyTexSubImage2D(GL_TEXTURE_2D, 2, 0, 0, 0, 0, 1, 1))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glGetTexImage",
         "texture",
         API_CALL(texture2D(8)),
         {API_CALL(GLubyte b[64]; glGetTexImage(kBad, 0, GL_RGBA, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glGetTexImage(GL_TEXTURE_2D, 0, kBad, GL_UNSIGNED_BYTE, b)),
          API_CALL(GLubyte b[64]; glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, kBad, b))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glGetTexLevelParameterfv",
         "texture",
         [](Observations& o) {
             texture2D(9);
             GLfloat v[2] = {Observations::kUnwritten, Observations::kUnwritten};
             glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, v);
             o.floats("width", v, 2);
         },
         {API_CALL(GLfloat v[2]; glGetTexLevelParameterfv(kBad, 0, GL_TEXTURE_WIDTH, v)),
          API_CALL(GLfloat v[2]; glGetTexLevelParameterfv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, v)),
          API_CALL(GLfloat v[2]; glGetTexLevelParameterfv(GL_TEXTURE_2D, 0, kBad, v)),
          API_CALL(GLfloat v[2]; glGetTexLevelParameterfv(GL_TEXTURE_2D, 20, GL_TEXTURE_WIDTH, v))},
         {},
         false,
         deleteTextures},
        {"glGetTexLevelParameteriv",
         "texture",
         API_CALL(texture2D(9)),
         {API_CALL(GLint v[2]; glGetTexLevelParameteriv(kBad, 0, GL_TEXTURE_WIDTH, v)),
          API_CALL(GLint v[2]; glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, v)),
          API_CALL(GLint v[2]; glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, kBad, v))},
         textureImage(GL_TEXTURE_2D),
         false,
         deleteTextures},
        {"glTexParameterf",
         "texture",
         API_CALL(texture2D(10); glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP)),
         {API_CALL(glTexParameterf(kBad, GL_TEXTURE_WRAP_S, GL_CLAMP)),
          API_CALL(glTexParameterf(GL_TEXTURE_2D, kBad, GL_CLAMP)),
          API_CALL(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR))},
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S),
         false,
         deleteTextures},
        {"glTexParameteri",
         "texture",
         API_CALL(texture2D(10); glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR)),
         {API_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_CLAMP)),
          API_CALL(glTexParameteri(kBad, GL_TEXTURE_MIN_FILTER, GL_LINEAR)),
          API_CALL(glTexParameteri(GL_TEXTURE_2D, kBad, GL_LINEAR)),
          API_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST_MIPMAP_NEAREST))},
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
         false,
         deleteTextures},
        {"glTexParameterfv",
         "texture",
         API_CALL(texture2D(10); glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, kParamsF)),
         {API_CALL(glTexParameterfv(GL_TEXTURE_2D, kBad, kParamsF)),
          API_CALL(glTexParameterfv(kBad, GL_TEXTURE_BORDER_COLOR, kParamsF))},
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR),
         false,
         deleteTextures},
        {"glTexParameteriv",
         "texture",
         API_CALL(texture2D(10); glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, kParamsI)),
         {API_CALL(glTexParameteriv(kBad, GL_TEXTURE_MAG_FILTER, kParamsI)),
          API_CALL(glTexParameteriv(GL_TEXTURE_2D, kBad, kParamsI))},
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER),
         false,
         deleteTextures},
        {"glGetTexParameterfv",
         "texture",
         texParameter(GL_TEXTURE_1D, GL_TEXTURE_WRAP_T),
         {API_CALL(GLfloat f[4]; glGetTexParameterfv(kBad, GL_TEXTURE_WRAP_T, f)),
          API_CALL(GLfloat f[4]; glGetTexParameterfv(GL_TEXTURE_2D, kBad, f))}},
        {"glGetTexParameteriv",
         "texture",
         texParameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER),
         {API_CALL(GLint i[4]; glGetTexParameteriv(kBad, GL_TEXTURE_WRAP_T, i)),
          API_CALL(GLint i[4]; glGetTexParameteriv(GL_TEXTURE_2D, kBad, i))}},
        {"glTexEnvf",
         "texture",
         API_CALL(glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL)),
         {API_CALL(glTexEnvf(kBad, GL_TEXTURE_ENV_MODE, GL_DECAL)), API_CALL(glTexEnvf(GL_TEXTURE_ENV, kBad, GL_DECAL)),
          API_CALL(glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR))},
         texEnv(GL_TEXTURE_ENV_MODE),
         false,
         API_CALL(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE))},
        {"glTexEnvi",
         "texture",
         API_CALL(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND)),
         {API_CALL(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, kBad)),
          API_CALL(glTexEnvi(kBad, GL_TEXTURE_ENV_MODE, GL_BLEND)),
          API_CALL(glTexEnvi(GL_TEXTURE_ENV, kBad, GL_BLEND))},
         texEnv(GL_TEXTURE_ENV_MODE),
         false,
         API_CALL(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE))},
        {"glTexEnvfv",
         "texture",
         API_CALL(glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, kParamsF)),
         {API_CALL(glTexEnvfv(kBad, GL_TEXTURE_ENV_COLOR, kParamsF)),
          API_CALL(glTexEnvfv(GL_TEXTURE_ENV, kBad, kParamsF))},
         texEnv(GL_TEXTURE_ENV_COLOR)},
        {"glTexEnviv",
         "texture",
         API_CALL(glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, kPlaneI)),
         {API_CALL(glTexEnviv(GL_TEXTURE_ENV, kBad, kPlaneI)),
          API_CALL(glTexEnviv(kBad, GL_TEXTURE_ENV_COLOR, kPlaneI))},
         texEnv(GL_TEXTURE_ENV_COLOR)},
        {"glGetTexEnvfv",
         "texture",
         texEnv(GL_TEXTURE_ENV_MODE),
         {API_CALL(GLfloat f[4]; glGetTexEnvfv(kBad, GL_TEXTURE_ENV_MODE, f)),
          API_CALL(GLfloat f[4]; glGetTexEnvfv(GL_TEXTURE_ENV, kBad, f))}},
        {"glGetTexEnviv",
         "texture",
         texEnv(GL_TEXTURE_ENV_COLOR),
         {API_CALL(GLint i[4]; glGetTexEnviv(kBad, GL_TEXTURE_ENV_MODE, i)),
          API_CALL(GLint i[4]; glGetTexEnviv(GL_TEXTURE_ENV, kBad, i))}},
        {"glTexGeni",
         "texture",
         API_CALL(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP)),
         {API_CALL(glTexGeni(kBad, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP)), API_CALL(glTexGeni(GL_S, kBad, GL_SPHERE_MAP)),
          API_CALL(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, kBad)),
          API_CALL(glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP))},
         texGen(GL_S, GL_TEXTURE_GEN_MODE)},
        {"glTexGenf",
         "texture",
         API_CALL(glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR)),
         {API_CALL(glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, GL_LINEAR)),
          API_CALL(glTexGenf(kBad, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR)),
          API_CALL(glTexGenf(GL_T, kBad, GL_OBJECT_LINEAR))},
         texGen(GL_T, GL_TEXTURE_GEN_MODE)},
        {"glTexGend",
         "texture",
         API_CALL(glTexGend(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR)),
         {API_CALL(glTexGend(GL_Q, kBad, GL_EYE_LINEAR)), API_CALL(glTexGend(kBad, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR)),
          API_CALL(glTexGend(GL_Q, GL_TEXTURE_GEN_MODE, kBad))},
         texGen(GL_Q, GL_TEXTURE_GEN_MODE)},
        // Mesa takes a plane given to the scalar forms as (v, 0, 0, 0): its own case, an expected difference.
        {"glTexGeni:plane",
         "texture",
         API_CALL(glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR)),
         {API_CALL(glTexGeni(GL_S, GL_OBJECT_PLANE, 2)), API_CALL(glTexGenf(GL_S, GL_EYE_PLANE, 3.0f)),
          API_CALL(glTexGend(GL_S, GL_OBJECT_PLANE, 4.0))},
         [](Observations& o) {
             texGen(GL_S, GL_OBJECT_PLANE)(o);
             texGen(GL_S, GL_EYE_PLANE)(o);
         }},
        {"glTexGendv",
         "texture",
         API_CALL(glTexGendv(GL_R, GL_OBJECT_PLANE, kPlaneD)),
         {API_CALL(glTexGendv(GL_R, kBad, kPlaneD)), API_CALL(glTexGendv(kBad, GL_OBJECT_PLANE, kPlaneD))},
         texGen(GL_R, GL_OBJECT_PLANE)},
        {"glTexGenfv",
         "texture",
         API_CALL(glTexGenfv(GL_S, GL_EYE_PLANE, kParamsF)),
         {API_CALL(glTexGenfv(kBad, GL_EYE_PLANE, kParamsF)), API_CALL(glTexGenfv(GL_S, kBad, kParamsF))},
         texGen(GL_S, GL_EYE_PLANE)},
        {"glTexGeniv",
         "texture",
         API_CALL(glTexGeniv(GL_T, GL_OBJECT_PLANE, kPlaneI)),
         {API_CALL(glTexGeniv(GL_T, kBad, kPlaneI)), API_CALL(glTexGeniv(kBad, GL_OBJECT_PLANE, kPlaneI))},
         texGen(GL_T, GL_OBJECT_PLANE)},
        {"glGetTexGendv",
         "texture",
         texGen(GL_S, GL_EYE_PLANE),
         {API_CALL(GLdouble d[4]; glGetTexGendv(kBad, GL_EYE_PLANE, d)),
          API_CALL(GLdouble d[4]; glGetTexGendv(GL_S, kBad, d))}},
        {"glGetTexGenfv",
         "texture",
         texGen(GL_T, GL_TEXTURE_GEN_MODE),
         {API_CALL(GLfloat f[4]; glGetTexGenfv(GL_T, kBad, f)),
          API_CALL(GLfloat f[4]; glGetTexGenfv(kBad, GL_EYE_PLANE, f))}},
        {"glGetTexGeniv",
         "texture",
         texGen(GL_R, GL_OBJECT_PLANE),
         {API_CALL(GLint i[4]; glGetTexGeniv(kBad, GL_OBJECT_PLANE, i)),
          API_CALL(GLint i[4]; glGetTexGeniv(GL_R, kBad, i))}},
    };
}

}  // namespace conformance
