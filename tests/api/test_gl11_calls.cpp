// The one list of GL 1.1 functions (glcalls/gl11_calls.h) against the loader glad generated and
// against the GL 1.1 specification's list of commands not compiled into display lists; its
// count rules against what the calls read.
#include <gtest/gtest.h>

#include <glad/gl.h>
#include <glcalls/gl11_calls.h>

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>

namespace {

using glcalls::ListClass;

// The functions glad's gl.h defines (`#define glName glad_glName`), read from the header itself.
// (Split by hand: GCC 12's std::regex warns of an uninitialized member under the sanitizers.)
std::set<std::string> loaderFunctions() {
    std::ifstream header(MYGL_GLAD_HEADER);
    std::set<std::string> names;
    for (std::string line; std::getline(header, line);) {
        std::istringstream words(line);
        std::string define, name, target, rest;
        if (!(words >> define >> name >> target) || words >> rest) continue;
        const bool glName =
            name.size() > 2 && name.starts_with("gl") && std::isupper(static_cast<unsigned char>(name[2]));
        if (define == "#define" && glName && target == "glad_" + name) names.insert(name);
    }
    return names;
}

// GL 1.1, section 5.4: "Certain commands, when called while compiling a display list, are not
// compiled into the display list but are executed immediately. These are: IsList, GenLists,
// DeleteLists, FeedbackBuffer, SelectBuffer, RenderMode, ColorPointer, EdgeFlagPointer,
// IndexPointer, NormalPointer, TexCoordPointer, VertexPointer, InterleavedArrays,
// EnableClientState, DisableClientState, PushClientAttrib, PopClientAttrib, ReadPixels,
// PixelStore, GenTextures, DeleteTextures, AreTexturesResident, IsTexture, Flush, Finish, as well
// as IsEnabled and all of the Get commands." NewList and EndList control compiling itself.
bool notCompiledBySpec(const std::string& name) {
    static const std::set<std::string> kListed = {"glIsList",
                                                  "glGenLists",
                                                  "glDeleteLists",
                                                  "glFeedbackBuffer",
                                                  "glSelectBuffer",
                                                  "glRenderMode",
                                                  "glColorPointer",
                                                  "glEdgeFlagPointer",
                                                  "glIndexPointer",
                                                  "glNormalPointer",
                                                  "glTexCoordPointer",
                                                  "glVertexPointer",
                                                  "glInterleavedArrays",
                                                  "glEnableClientState",
                                                  "glDisableClientState",
                                                  "glPushClientAttrib",
                                                  "glPopClientAttrib",
                                                  "glReadPixels",
                                                  "glPixelStoref",
                                                  "glPixelStorei",
                                                  "glGenTextures",
                                                  "glDeleteTextures",
                                                  "glAreTexturesResident",
                                                  "glIsTexture",
                                                  "glFlush",
                                                  "glFinish",
                                                  "glIsEnabled",
                                                  "glNewList",
                                                  "glEndList"};
    return kListed.contains(name) || name.starts_with("glGet");
}

// Commands that answer and change nothing: the Get and Is commands, glReadPixels,
// glAreTexturesResident.
bool isQuery(const std::string& name) {
    return name.starts_with("glGet") || name.starts_with("glIs") || name == "glReadPixels" ||
           name == "glAreTexturesResident";
}

// Commands a list keeps with what they read from client memory at compile time: the pixel
// rectangles and images (unpacked then, section 3.6) and the vertex array draws (section 2.8:
// "array elements are dereferenced when compiled").
bool readsClientMemoryWhenCompiled(const std::string& name) {
    static const std::set<std::string> kDereferenced = {
        "glBitmap",        "glDrawPixels",    "glPolygonStipple", "glTexImage1D", "glTexImage2D",
        "glTexSubImage1D", "glTexSubImage2D", "glArrayElement",   "glDrawArrays", "glDrawElements"};
    return kDereferenced.contains(name);
}

}  // namespace

TEST(Gl11Calls, NamesEveryFunctionOfTheLoaderExactlyOnce) {
    const std::set<std::string> loader = loaderFunctions();
    EXPECT_EQ(loader.size(), 336u);
    std::map<std::string, int> listed;
    for (const glcalls::Function& f : glcalls::kFunctions) ++listed[f.name];
    for (const auto& [name, times] : listed) {
        EXPECT_EQ(times, 1) << name << " is listed " << times << " times";
        EXPECT_TRUE(loader.contains(name)) << name << " is not a GL 1.1 function of the loader";
    }
    for (const std::string& name : loader) EXPECT_TRUE(listed.contains(name)) << name << " is missing from the list";
}

TEST(Gl11Calls, ClassesFollowTheSpecsCommandsNotCompiledIntoLists) {
    int compiled = 0;
    for (const glcalls::Function& f : glcalls::kFunctions) {
        const std::string name = f.name;
        const bool kept = f.listClass == ListClass::compiled || f.listClass == ListClass::dereferenced;
        EXPECT_EQ(kept, !notCompiledBySpec(name)) << name;
        EXPECT_EQ(f.listClass == ListClass::query, isQuery(name)) << name;
        EXPECT_EQ(f.listClass == ListClass::dereferenced, readsClientMemoryWhenCompiled(name)) << name;
        compiled += kept;
    }
    EXPECT_EQ(compiled, 336 - 58);  // 24 executed at once (with glNewList, glEndList), 34 queries
}

namespace {

// Whether a call the list keeps (in a display list or a recording) has a count for each pointer
// argument: a rule, or a number other than 0. Only the vertex array pointers (executed at once,
// never compiled) are kept as pointers, to be read when a draw is replayed.
template <class Call, class R, class... Args>
bool countsItsPointers(R (*)(Args...)) {
    using Count = std::remove_const_t<decltype(Call::kCount)>;
    constexpr bool rule =
        std::is_invocable_v<Count, Args...> || std::is_invocable_v<Count, const glcalls::UnpackModes&, Args...>;
    constexpr bool pointers = (std::is_pointer_v<Args> || ...);
    if constexpr (!pointers || rule) {
        return true;
    } else if constexpr (std::is_integral_v<Count>) {
        const bool arrayPointer =
            std::is_same_v<std::tuple<Args...>, std::tuple<GLint, GLenum, GLsizei, const void*>> ||
            std::is_same_v<std::tuple<Args...>, std::tuple<GLenum, GLsizei, const void*>> ||
            std::is_same_v<std::tuple<Args...>, std::tuple<GLsizei, const void*>>;
        return Call::kCount != 0 || Call::kClass == ListClass::query ||
               (arrayPointer && Call::kClass == ListClass::immediate) || std::string(Call::kName) == "glSelectBuffer" ||
               std::string(Call::kName) == "glFeedbackBuffer";
    } else {
        return false;  // a rule that does not take the call's arguments
    }
}

}  // namespace

TEST(Gl11Calls, EveryKeptPointerArgumentHasACountRule) {
#define MYGL_CHECK(name, class_, count) \
    EXPECT_TRUE(countsItsPointers<glcalls::call::name>(typename glcalls::call::name::Signature{})) << #name;
    MYGL_GL11_CALLS(MYGL_CHECK)
#undef MYGL_CHECK
}

TEST(Gl11Calls, CountRulesGiveWhatTheCallsRead) {
    using namespace glcalls;
    EXPECT_EQ(lightCount<GLfloat>(GL_LIGHT0, GL_POSITION, nullptr), 4u);
    EXPECT_EQ(lightCount<GLfloat>(GL_LIGHT0, GL_SPOT_DIRECTION, nullptr), 3u);
    EXPECT_EQ(lightCount<GLint>(GL_LIGHT0, GL_SPOT_CUTOFF, nullptr), 1u);
    EXPECT_EQ(materialCount<GLfloat>(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, nullptr), 4u);
    EXPECT_EQ(materialCount<GLfloat>(GL_FRONT, GL_COLOR_INDEXES, nullptr), 3u);
    EXPECT_EQ(materialCount<GLfloat>(GL_FRONT, GL_SHININESS, nullptr), 1u);
    EXPECT_EQ(materialCount<GLfloat>(GL_FRONT, GL_POSITION, nullptr), 1u);  // an error: read nothing more
    EXPECT_EQ(fogCount<GLint>(GL_FOG_COLOR, nullptr), 4u);
    EXPECT_EQ(texGenCount<GLdouble>(GL_S, GL_EYE_PLANE, nullptr), 4u);
    EXPECT_EQ(texEnvCount<GLfloat>(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, nullptr), 4u);
    EXPECT_EQ(callListsBytes(3, GL_3_BYTES, nullptr), 9u);
    EXPECT_EQ(callListsBytes(2, GL_FLOAT, nullptr), 8u);
    EXPECT_EQ(elementBytes(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, nullptr), 12u);
    EXPECT_EQ(map1Count<GLfloat>(GL_MAP1_VERTEX_3, 0, 1, 3, 4, nullptr), 12u);
    EXPECT_EQ(map2Count<GLfloat>(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 3, nullptr), 4u + 16u + 4u);
    EXPECT_EQ(map1Count<GLfloat>(GL_MAP2_VERTEX_3, 0, 1, 3, 4, nullptr), 1u);  // a glMap2 target
    EXPECT_EQ(pixelMapCount<GLushort>(GL_PIXEL_MAP_I_TO_R, 5, nullptr), 5u);
    EXPECT_EQ(pixelMapCount<GLfloat>(GL_PIXEL_MAP_I_TO_R, -1, nullptr), 0u);
    // 3 x 2 RGB bytes, rows padded to 4: 12 bytes and a last row of 9.
    EXPECT_EQ(texImage2DBytes(UnpackModes{}, GL_TEXTURE_2D, 0, GL_RGB, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr),
              21u);
    // Row length 6, one skipped row and pixel, alignment 1 (the replay test's texture).
    EXPECT_EQ(
        texImage2DBytes(UnpackModes{1, 6, 1, 1}, GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, nullptr),
        87u);
    EXPECT_EQ(bitmapBytes(UnpackModes{1, 0, 0, 0}, 10, 3, 0, 0, 0, 0, nullptr), 6u);
    EXPECT_EQ(bitmapBytes(UnpackModes{}, 10, 3, 0, 0, 0, 0, nullptr), 4u + 4u + 2u);
    EXPECT_EQ(polygonStippleBytes(UnpackModes{}, nullptr), 128u);
    EXPECT_EQ(drawPixelsBytes(UnpackModes{}, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr), 16u);
}
