// The fragment paths of every vector width this CPU runs (scalar, AVX2, AVX-512), each fast path
// and each routine for any key, against the general path (the scalar routine for any key): same
// colors, depths and counts, bit for bit, on random spans with random planes and buffers. Then
// the fast exact method (spans, narrow blocks) of every width against per-pixel coverage, on
// random triangles in every fragment state, whole or cut to a rectangle as tiles are.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cpu_features.h"
#include "fragment_paths.h"
#include "glrenderer/color_convert.h"
#include "raster_span.h"
#include "window_vertex.h"

using namespace glrenderer;

namespace {

constexpr int kWidth = 97, kHeight = 61;  // odd sizes exercise the partial blocks

std::vector<const FragmentPaths*> pathsOfThisCpu() {
    std::vector<const FragmentPaths*> paths{&scalarFragmentPaths()};
    if (cpuHasAvx2Fma()) paths.push_back(&avx2FragmentPaths());
    if (cpuHasAvx512()) paths.insert(paths.end(), {&avx2EvexFragmentPaths(), &avx512FragmentPaths()});
    return paths;
}

std::string describe(const FragmentKey& key) {
    const char* const shadings[] = {"flat", "linear", "perspective"};
    std::string text = shadings[static_cast<int>(key.shading)];
    if (key.depthTest) {
        text += " depth func " + std::to_string(static_cast<int>(key.depthFunc)) + (key.depthWrite ? " write" : "");
    }
    if (key.fog != FogMode::Off) text += " fog " + std::to_string(static_cast<int>(key.fog));
    if (key.textureEnv != TextureEnv::Off) {
        text += " texture env " + std::to_string(static_cast<int>(key.textureEnv)) + " base " +
                std::to_string(static_cast<int>(key.textureBase)) + " filters " +
                std::to_string(static_cast<int>(key.minFilter)) + std::to_string(static_cast<int>(key.magFilter)) +
                std::to_string(static_cast<int>(key.mipFilter)) + " wraps " +
                std::to_string(static_cast<int>(key.wrapS)) + std::to_string(static_cast<int>(key.wrapT));
    }
    if (key.depthOffset) text += " offset";
    if (key.alphaFunc != CompareFunc::Always) text += " alpha " + std::to_string(static_cast<int>(key.alphaFunc));
    if (key.stencilTest) {
        text += " stencil " + std::to_string(static_cast<int>(key.stencilFunc)) + " ops " +
                std::to_string(static_cast<int>(key.stencilFail)) +
                std::to_string(static_cast<int>(key.stencilDepthFail)) +
                std::to_string(static_cast<int>(key.stencilDepthPass));
    }
    if (key.blendSrc != BlendFactor::One || key.blendDst != BlendFactor::Zero) {
        text += " blend " + std::to_string(static_cast<int>(key.blendSrc)) + " " +
                std::to_string(static_cast<int>(key.blendDst));
    }
    if (key.logicOp != LogicOp::Copy) text += " logic op " + std::to_string(static_cast<int>(key.logicOp));
    if (key.colorMask) text += " colour mask";
    if (key.colorSum) text += " colour sum";
    if (key.alphaOne) text += " alpha one";
    return text;
}

// A routine to check, with the key it serves (any key for the routines for any key).
struct NamedRoutine {
    std::string name;
    const FragmentRoutine* routine;
    bool anyKey;
    FragmentKey key;
};

std::vector<NamedRoutine> routinesOfThisCpu() {
    std::vector<NamedRoutine> routines;
    for (const FragmentPaths* paths : pathsOfThisCpu()) {
        for (const FragmentPaths::FastPath& fast : paths->fastPaths()) {
            routines.push_back({std::string(paths->name()) + " " + describe(fast.key), &fast.routine, false, fast.key});
        }
        routines.push_back({std::string(paths->name()) + " any key", &paths->anyKey(), true, {}});
    }
    return routines;
}

// Per-fragment operations (issue 16), each on in about a third of the draws.
FragmentOps randomFragmentOps(std::mt19937& random) {
    std::uniform_int_distribution<int> func(0, 7), op(0, 5), factor(0, 10), logic(0, 15), third(0, 2), byte(0, 255);
    FragmentOps ops;
    ops.alphaTest = third(random) == 0;
    ops.alphaFunc = static_cast<CompareFunc>(func(random));
    ops.alphaRef = static_cast<std::uint8_t>(byte(random));
    StencilState& s = ops.stencil;
    s.enabled = third(random) == 0;
    s.func = static_cast<CompareFunc>(func(random));
    s.ref = static_cast<std::uint8_t>(byte(random)), s.valueMask = static_cast<std::uint8_t>(byte(random));
    s.writeMask = third(random) == 0 ? 0xFF : static_cast<std::uint8_t>(byte(random));
    s.fail = static_cast<StencilOp>(op(random)), s.depthFail = static_cast<StencilOp>(op(random));
    s.depthPass = static_cast<StencilOp>(op(random));
    ops.blend = third(random) == 0;
    ops.blendSrc = static_cast<BlendFactor>(factor(random)), ops.blendDst = static_cast<BlendFactor>(factor(random));
    ops.logicOpEnabled = third(random) == 0 && third(random) == 0;
    ops.logicOp = static_cast<LogicOp>(logic(random));
    if (third(random) == 0) ops.colorMask = static_cast<std::uint32_t>(byte(random)) * 0x01010101u & 0xFF00FF00u;
    return ops;
}

FragmentKey randomKey(std::mt19937& random) {
    std::uniform_int_distribution<int> shading(0, 2), depthFunc(0, 7), coin(0, 1), fog(0, 3);
    FragmentKey key = makeFragmentKey(static_cast<Shading>(shading(random)), coin(random),
                                      static_cast<CompareFunc>(depthFunc(random)), coin(random));
    key.fog = static_cast<FogMode>(fog(random));
    key.depthOffset = key.depthTest && coin(random);
    key = withFragmentOps(key, randomFragmentOps(random));
    key.colorSum = coin(random) && coin(random);
    if (coin(random)) {
        std::uniform_int_distribution<int> env(1, 5), base(0, 5), mip(0, 2);
        key = withTexture(key, static_cast<TextureEnv>(env(random)), coin(random),
                          static_cast<TextureBase>(base(random)), static_cast<TextureFilter>(coin(random)),
                          static_cast<TextureFilter>(coin(random)), static_cast<MipmapFilter>(mip(random)),
                          static_cast<TextureWrap>(coin(random)), static_cast<TextureWrap>(coin(random)));
    }
    return coin(random) ? withAlphaOne(key) : key;
}

// A texture of width x height texels and its mipmaps, random texels.
Texture randomTexture(std::mt19937& random, int width, int height) {
    std::uniform_int_distribution<std::uint32_t> word;
    Texture t;
    t.powerOfTwoWidth = std::has_single_bit(static_cast<unsigned>(width));
    t.powerOfTwoHeight = std::has_single_bit(static_cast<unsigned>(height));
    for (; t.levelCount == 0 || width > 1 || height > 1;
         width = std::max(width / 2, 1), height = std::max(height / 2, 1)) {
        const auto level = static_cast<std::size_t>(t.levelCount++);
        t.width[level] = static_cast<std::uint32_t>(width);
        t.height[level] = static_cast<std::uint32_t>(height);
        t.offset[level] = static_cast<std::uint32_t>(t.texels.size());
        for (int i = 0; i < width * height; ++i) t.texels.push_back(word(random));
        if (width == 1 && height == 1) break;
    }
    return t;
}
// 8 x 4 texels (or 6 x 4, not a power of two).
Texture randomTexture(std::mt19937& random, bool powerOfTwo) { return randomTexture(random, powerOfTwo ? 8 : 6, 4); }

// A plane whose values over the framebuffer lie around [low, high], now and then a special one.
AttributePlane randomPlane(std::mt19937& random, float low, float high) {
    std::uniform_real_distribution<float> value(low, high), unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> special(0, 40);
    const float start = value(random), across = value(random) - start, down = value(random) - start;
    AttributePlane plane{start, across * unit(random) / kWidth, down * unit(random) / kHeight};
    switch (special(random)) {
    case 0: return {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f};
    case 1: return {1.0f, 0.0f, 0.0f};
    case 2: return {start, std::numeric_limits<float>::infinity(), 0.0f};
    case 3: return {-0.0f, 0.0f, 0.0f};
    default: return plane;
    }
}

// Fog constants of a random mode, range, density and colour.
FogState randomFog(std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), distance(-5.0f, 40.0f);
    std::uniform_int_distribution<int> mode(1, 3);
    return makeFogState(static_cast<FogMode>(mode(random)), FogDistance::OwnDotProduct, unit(random), distance(random),
                        distance(random), {unit(random), unit(random), unit(random), 1.0f});
}

struct Target {
    Framebuffer framebuffer{kWidth, kHeight};
    FragmentCounts counts;

    Target(const std::vector<std::uint32_t>& color, const std::vector<std::uint32_t>& depth) {
        std::copy(color.begin(), color.end(), framebuffer.color().begin());
        std::copy(depth.begin(), depth.end(), framebuffer.depth().begin());
        // Stencil values from the depths' low bytes: varied, and the same in every target.
        std::transform(depth.begin(), depth.end(), framebuffer.stencil().begin(),
                       [](std::uint32_t d) { return d & 0xFF; });
    }
};

testing::AssertionResult same(const Target& expected, const Target& actual) {
    if (!std::equal(expected.framebuffer.color().begin(), expected.framebuffer.color().end(),
                    actual.framebuffer.color().begin())) {
        return testing::AssertionFailure() << "colors differ";
    }
    if (!std::equal(expected.framebuffer.depth().begin(), expected.framebuffer.depth().end(),
                    actual.framebuffer.depth().begin())) {
        return testing::AssertionFailure() << "depths differ";
    }
    if (!std::equal(expected.framebuffer.stencil().begin(), expected.framebuffer.stencil().end(),
                    actual.framebuffer.stencil().begin())) {
        return testing::AssertionFailure() << "stencil values differ";
    }
    if (expected.counts.fragments != actual.counts.fragments || expected.counts.passed != actual.counts.passed) {
        return testing::AssertionFailure() << "counts differ";
    }
    return testing::AssertionSuccess();
}

// `triangle`'s part in `rect` drawn by spans with its own routine and with the path's any-key
// routine, each onto `color` and `depth`, against `expected` (the per-pixel reference).
void expectSpansMatch(const Target& expected, const RasterTriangle& triangle, const PixelRect& rect,
                      const FragmentPaths& paths, const std::vector<std::uint32_t>& color,
                      const std::vector<std::uint32_t>& depth, int i) {
    for (const FragmentRoutine* routine : {triangle.fragment.routine, &paths.anyKey()}) {
        Target actual(color, depth);
        rasterizeTriangleSpans(triangle, rect, actual.framebuffer, actual.counts, *routine);
        EXPECT_TRUE(same(expected, actual)) << paths.name() << " key " << describe(triangle.fragment.key())
                                            << (routine == &paths.anyKey() ? " any key" : "") << " triangle " << i;
    }
}

std::vector<std::uint32_t> randomPixels(std::mt19937& random, std::uint32_t max) {
    std::uniform_int_distribution<std::uint32_t> value(0, max);
    std::vector<std::uint32_t> pixels(kWidth * kHeight);
    for (auto& p : pixels) p = value(random);
    return pixels;
}

WindowVertex randomVertex(std::mt19937& random, float spread) {
    std::uniform_real_distribution<float> position(-spread, spread), unit(0.0f, 1.0f), w(0.2f, 4.0f);
    WindowVertex v;
    v.x = kWidth / 2.0f + position(random);
    v.y = kHeight / 2.0f + position(random);
    v.z = unit(random) * 1.2f - 0.1f;  // slightly outside [0, 1] to exercise the clamp
    v.invW = 1.0f / w(random);
    v.color = {unit(random) * 1.2f - 0.1f, unit(random), unit(random), unit(random)};
    v.fogCoord = unit(random) * 30.0f;
    v.texCoord = {unit(random) * 3.0f - 1.0f, unit(random) * 3.0f - 1.0f, 0.0f, 0.5f + unit(random)};
    return v;
}

}  // namespace

TEST(FragmentPaths, FastKeysFindTheirPathsAndOtherKeysTheRoutineForAnyKey) {
    for (const FragmentPaths* paths : pathsOfThisCpu()) {
        for (const FragmentPaths::FastPath& fast : paths->fastPaths()) {
            // A key with a level of detail may be served by other paths (AVX-512's by AVX2's).
            const bool elsewhere = paths->lodPaths() && fast.key.samplesLod();
            const FragmentRoutine& expected = elsewhere ? paths->lodPaths()().routine(fast.key) : fast.routine;
            EXPECT_EQ(&paths->routine(fast.key), &expected) << paths->name();
            // A draw of alpha-one colours keeps a fast path.
            EXPECT_NE(&paths->routine(withAlphaOne(fast.key)), &paths->anyKey()) << describe(fast.key);
        }
        const FragmentKey greater = makeFragmentKey(Shading::Perspective, true, CompareFunc::Greater, true);
        EXPECT_EQ(&paths->routine(greater), &paths->anyKey()) << paths->name();
    }
    // Keys are normalized: without the depth test, the function and writes do not matter.
    EXPECT_EQ(makeFragmentKey(Shading::Flat, false, CompareFunc::Less, true),
              makeFragmentKey(Shading::Flat, false, CompareFunc::Greater, false));
    // A flat key that textures takes its linear key's routine (routineKey), keeping its own key.
    const FragmentKey textured = kCommonFragmentKeys[std::size(kCommonFragmentKeys) - 3];
    ASSERT_TRUE(textured.texturesColor() && textured.shading == Shading::Linear);
    FragmentKey flatTextured = textured;
    flatTextured.shading = Shading::Flat;
    const FragmentChoice flat(bestFragmentPaths(), flatTextured);
    EXPECT_EQ(flat.varyingW.routine, &bestFragmentPaths().routine(textured));
    EXPECT_EQ(flat.varyingW.key, flatTextured);
    // A primitive with 1 / w constant 1 takes the key without the division.
    const FragmentChoice choice(scalarFragmentPaths(), makeFragmentKey(Shading::Perspective, false, {}, false));
    EXPECT_EQ(choice.path({1.0f, 0.0f, 0.0f}).key.shading, Shading::Linear);
    EXPECT_EQ(choice.path({1.0f, 0.0f, 1e-9f}).key.shading, Shading::Perspective);
}

TEST(FragmentPaths, EveryPathMatchesTheGeneralPathOnRandomSpans) {
    std::mt19937 random(11);
    const Texture textures[] = {randomTexture(random, true), randomTexture(random, false)};
    std::uniform_int_distribution<int> column(0, kWidth - 1), row(0, kHeight - 1), shortSpan(0, 20);
    std::uniform_int_distribution<std::uint32_t> word;
    int spans = 0;
    for (const NamedRoutine& tested : routinesOfThisCpu()) {
        for (int i = 0; i < 300; ++i) {
            FragmentInputs inputs;
            for (int c = 0; c < 4; ++c) inputs.color.set(c, randomPlane(random, -0.1f, 1.1f));
            for (AttributePlane& c : inputs.secondaryColor) c = randomPlane(random, -0.1f, 1.1f);
            inputs.setInvW(randomPlane(random, 0.25f, 4.0f));
            inputs.setDepth(randomPlane(random, -0.1f, 1.1f));
            inputs.flatColor = word(random);
            inputs.fogCoord = randomPlane(random, -2.0f, 40.0f);
            inputs.fog = randomFog(random);
            inputs.depthOffset = std::uniform_real_distribution<float>(-0.01f, 0.01f)(random);
            inputs.ops = FragmentOpsConstants::of(randomFragmentOps(random));
            for (int k = 0; k < 2; ++k) inputs.texCoord[k] = randomPlane(random, -1.5f, 2.5f);
            inputs.texCoord[2] = randomPlane(random, 0.5f, 2.0f);
            inputs.texture = &textures[i % 2];
            inputs.textureEnvColor = {0.2f, 0.4f, 0.6f, 0.8f};
            inputs.setPath({tested.anyKey ? randomKey(random) : tested.key, tested.routine});
            FragmentInputs general = inputs;
            general.setPath({inputs.key(), &generalFragmentRoutine()});

            const std::vector<std::uint32_t> color = randomPixels(random, 0xFFFFFFFF);
            const std::vector<std::uint32_t> depth = randomPixels(random, kDepthMax24);
            Target expected(color, depth), actual(color, depth);
            // Several spans of the same inputs, short and long, over one another.
            for (int k = 0; k < 6; ++k) {
                const int y = row(random);
                int begin = column(random), end = column(random);
                if (k % 2 == 0) end = std::min(kWidth - 1, begin + shortSpan(random));
                if (begin > end) std::swap(begin, end);
                general.shadeSpan(y, begin, end, expected.framebuffer, expected.counts);
                inputs.shadeSpan(y, begin, end, actual.framebuffer, actual.counts);
                ++spans;
            }
            ASSERT_TRUE(same(expected, actual)) << tested.name << " key " << describe(inputs.key()) << " inputs " << i;
        }
    }
    EXPECT_GT(spans, 10000);
}

namespace {

// Random triangles drawn by the fast exact method of every path against per-pixel coverage.
// `lodTextures`: every triangle samples a texture with a level of detail (the row pairs of
// shadeRowPairs), and every fourth is cut to one or two rows from any row, odd or even.
// `texture`: level 0's size, 8 x 4 unless given.
void checkTrianglesAgainstThePerPixelReference(unsigned seed, bool lodTextures, int textureWidth = 8,
                                               int textureHeight = 4) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> depthFunc(0, 7), coin(0, 1), fourth(0, 3);
    std::uniform_int_distribution<int> column(0, kWidth - 1), row(0, kHeight - 1);
    const std::vector<const FragmentPaths*> allPaths = pathsOfThisCpu();
    const auto texture = std::make_shared<const Texture>(randomTexture(random, textureWidth, textureHeight));
    int drawn = 0;
    for (int i = 0; i < 3000; ++i) {
        const float spread = i % 3 == 0 ? 3.0f : (i % 3 == 1 ? 30.0f : 400.0f);
        WindowVertex vertices[3] = {randomVertex(random, spread), randomVertex(random, spread),
                                    randomVertex(random, spread)};
        const glm::vec4 flatColor{0.3f, 0.6f, 0.9f, 1.0f};
        SetupTriangle setup{{&vertices[0], &vertices[1], &vertices[2]}, {}, 0, &flatColor};
        // Every fourth triangle has w = 1 at every vertex, as orthographic scenes do: its path
        // then skips the division by 1 / w.
        if (i % 4 == 3) {
            for (WindowVertex& v : vertices) v.invW = 1.0f;
        }
        for (int k = 0; k < 3; ++k) setup.fixed[k] = snap(vertices[k]);
        setup.area = fixedArea(setup.fixed[0], setup.fixed[1], setup.fixed[2]);
        if (setup.area == 0) continue;
        DrawState state;
        state.depthTest = coin(random);
        state.depthFunc = static_cast<CompareFunc>(depthFunc(random));
        state.depthWrite = coin(random);
        state.shadeModel = coin(random) ? ShadeModel::Smooth : ShadeModel::Flat;
        Methods methods;
        if (fourth(random) == 0) methods.interpolation = Interpolation::ScreenLinear;
        if (fourth(random) == 0) state.fog = randomFog(random);
        if (fourth(random) == 0) state.polygonOffset = {1.5f, -3.0f, true, false, false};
        state.fragmentOps = randomFragmentOps(random);
        if (lodTextures || fourth(random) == 0) {
            std::uniform_int_distribution<int> env(1, 5), base(0, 5), mip(0, 2), wrap(0, 2);
            state.texture.env = static_cast<TextureEnv>(env(random));
            state.texture.base = static_cast<TextureBase>(base(random));
            state.texture.minFilter = static_cast<TextureFilter>(coin(random));
            state.texture.magFilter = static_cast<TextureFilter>(coin(random));
            state.texture.mipFilter = static_cast<MipmapFilter>(mip(random));
            state.texture.wrapS = static_cast<TextureWrap>(wrap(random));
            state.texture.wrapT = static_cast<TextureWrap>(wrap(random));
            state.texture.borderColor = {0.3f, 0.6f, 0.9f, 0.5f};  // (for GL_CLAMP: the float sampler)
            state.texture.texture = texture;
            if (lodTextures && state.texture.mipFilter == MipmapFilter::None) {
                state.texture.magFilter = static_cast<TextureFilter>(1 - static_cast<int>(state.texture.minFilter));
            }
        }
        // Every other triangle is drawn within a random rectangle, as a tile draws its part.
        PixelRect rect{0, kWidth - 1, 0, kHeight - 1};
        if (i % 2) {
            const int x0 = column(random), x1 = column(random), y0 = row(random), y1 = row(random);
            rect = {std::min(x0, x1), std::max(x0, x1), std::min(y0, y1), std::max(y0, y1)};
            if (lodTextures && i % 4 == 1) rect.maxY = std::min(rect.minY + coin(random), kHeight - 1);
        }
        const std::vector<std::uint32_t> color(kWidth * kHeight, 0);
        const std::vector<std::uint32_t> depth = randomPixels(random, kDepthMax24);
        for (const FragmentPaths* paths : allPaths) {
            RasterTriangle triangle;
            const FragmentChoice choice(*paths, triangleFragmentKey(state, methods), state);
            if (!prepareTriangle(setup, choice, RasterMethod::Exact, {0, kWidth - 1, 0, kHeight - 1}, triangle)) break;
            if (paths == allPaths.front()) ++drawn;
            Target expected(color, depth);
            rasterizeTriangleExact(triangle, rect, expected.framebuffer, expected.counts);
            expectSpansMatch(expected, triangle, rect, *paths, color, depth, i);
        }
    }
    EXPECT_GT(drawn, 2000);
}

}  // namespace

TEST(FragmentPaths, TrianglesMatchThePerPixelReferenceInEveryPath) {
    checkTrianglesAgainstThePerPixelReference(5, false);
}

TEST(FragmentPaths, TrianglesWithALevelOfDetailMatchThePerPixelReferenceInEveryPath) {
    checkTrianglesAgainstThePerPixelReference(6, true);
}

// A draw whose vertex colours all have alpha 1 takes its key's alphaOne paths (FragmentKey::alphaOne),
// which store alpha 255 without interpolating it: the same bits as interpolating the ones, in
// perspective (where alpha / w is the plane of 1 / w) and in the orthographic case, from every
// path, with depth tests, fog and the colour sum that leave alpha alone.
TEST(FragmentPaths, AlphaOneTrianglesMatchTheirInterpolatedAlphaInEveryPath) {
    std::mt19937 random(12);
    std::uniform_int_distribution<int> depthFunc(0, 7), coin(0, 1), fourth(0, 3);
    const std::vector<const FragmentPaths*> allPaths = pathsOfThisCpu();
    const PixelRect whole{0, kWidth - 1, 0, kHeight - 1};
    const glm::vec4 flatColor{0.3f, 0.6f, 0.9f, 1.0f};
    int drawn = 0, fastAlphaOne = 0;
    for (int i = 0; i < 2000; ++i) {
        const float spread = i % 3 == 0 ? 3.0f : (i % 3 == 1 ? 30.0f : 400.0f);
        WindowVertex vertices[3] = {randomVertex(random, spread), randomVertex(random, spread),
                                    randomVertex(random, spread)};
        for (WindowVertex& v : vertices) {
            v.color.a = 1.0f;
            if (i % 4 == 3) v.invW = 1.0f;
        }
        SetupTriangle setup{{&vertices[0], &vertices[1], &vertices[2]}, {}, 0, &flatColor};
        for (int k = 0; k < 3; ++k) setup.fixed[k] = snap(vertices[k]);
        setup.area = fixedArea(setup.fixed[0], setup.fixed[1], setup.fixed[2]);
        if (setup.area == 0) continue;
        DrawState state;
        state.depthTest = coin(random);
        state.depthFunc = coin(random) ? CompareFunc::Less : static_cast<CompareFunc>(depthFunc(random));
        state.depthWrite = state.depthFunc == CompareFunc::Less || coin(random);
        state.secondaryColors = fourth(random) == 0;
        if (fourth(random) == 0) state.fog = randomFog(random);
        const FragmentKey key = triangleFragmentKey(state, Methods{});
        ASSERT_TRUE(withAlphaOne(key).alphaOne) << describe(key);
        const std::vector<std::uint32_t> color = randomPixels(random, 0xFFFFFFFF);
        const std::vector<std::uint32_t> depth = randomPixels(random, kDepthMax24);
        RasterTriangle interpolated;
        if (!prepareTriangle(setup, FragmentChoice(scalarFragmentPaths(), key, state), RasterMethod::Exact, whole,
                             interpolated)) {
            continue;
        }
        ++drawn;
        Target expected(color, depth);
        rasterizeTriangleExact(interpolated, whole, expected.framebuffer, expected.counts);
        for (const FragmentPaths* paths : allPaths) {
            RasterTriangle alphaOne;
            ASSERT_TRUE(prepareTriangle(setup, FragmentChoice(*paths, withAlphaOne(key), state), RasterMethod::Exact,
                                        whole, alphaOne));
            ASSERT_TRUE(alphaOne.fragment.key().alphaOne);
            fastAlphaOne += alphaOne.fragment.routine != &paths->anyKey();
            expectSpansMatch(expected, alphaOne, whole, *paths, color, depth, i);
        }
    }
    EXPECT_GT(drawn, 1500);
    // Fast paths drew a good part (not other depth functions, the colour sum, or most fog).
    EXPECT_GT(fastAlphaOne, drawn * static_cast<int>(allPaths.size()) / 3);
}

// Larger textures, whose levels of detail stay on one pair of levels over most blocks (the
// samplers' path for such blocks) and change level within others; sides of powers of two and
// not, down to levels of one texel.
TEST(FragmentPaths, TrianglesWithALevelOfDetailOnLargerTexturesMatchThePerPixelReferenceInEveryPath) {
    checkTrianglesAgainstThePerPixelReference(7, true, 64, 64);
    checkTrianglesAgainstThePerPixelReference(8, true, 48, 20);
    checkTrianglesAgainstThePerPixelReference(9, true, 1, 32);
}

// Areas up to 16 columns wide (the narrow blocks of AVX2 and AVX-512, the narrow quads of keys
// with a level of detail, and the spans of the others) cut from huge triangles (edge values past 32 bits: the blocks
// step aside), slivers, one-pixel and mesh-sized triangles, from odd and even rows and at the framebuffer's borders:
// every path against per-pixel coverage.
TEST(FragmentPaths, NarrowAreasMatchThePerPixelReferenceInEveryPath) {
    std::mt19937 random(8);
    std::uniform_int_distribution<int> columns(1, 16), column(0, kWidth - 1), row(0, kHeight - 1), coin(0, 1);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const std::vector<const FragmentPaths*> allPaths = pathsOfThisCpu();
    const std::vector<std::uint32_t> color(kWidth * kHeight, 0);
    const glm::vec4 flatColor{0.3f, 0.6f, 0.9f, 1.0f};
    const auto texture = std::make_shared<const Texture>(randomTexture(random, 16, 16));
    std::uint64_t fragments = 0;
    for (int i = 0; i < 4000; ++i) {
        WindowVertex v[3] = {randomVertex(random, 30.0f), randomVertex(random, 30.0f), randomVertex(random, 30.0f)};
        switch (i % 4) {
        case 0:  // huge: up to 2^17 pixels from the framebuffer's center
            for (WindowVertex& vertex : v) {
                vertex.x = kWidth / 2.0f + (vertex.x - kWidth / 2.0f) * 4096.0f;
                vertex.y = kHeight / 2.0f + (vertex.y - kHeight / 2.0f) * 4096.0f;
            }
            break;
        case 1: {  // a sliver along a random direction, a fraction of a pixel thick
            const float dx = unit(random) * 60.0f, dy = unit(random) * 60.0f, thickness = unit(random) * 0.4f;
            v[1].x = v[0].x + dx, v[1].y = v[0].y + dy;
            v[2].x = v[0].x + dx / 2 - dy * thickness / 60.0f, v[2].y = v[0].y + dy / 2 + dx * thickness / 60.0f;
            break;
        }
        case 2:  // about a pixel
            for (WindowVertex& vertex : v) vertex.x = v[0].x + unit(random), vertex.y = v[0].y + unit(random);
            break;
        default:  // a few pixels, as a dense mesh's
            for (WindowVertex& vertex : v)
                vertex.x = v[0].x + 4.0f * unit(random), vertex.y = v[0].y + 4.0f * unit(random);
        }
        SetupTriangle setup{{&v[0], &v[1], &v[2]}, {snap(v[0]), snap(v[1]), snap(v[2])}, 0, &flatColor};
        setup.area = fixedArea(setup.fixed[0], setup.fixed[1], setup.fixed[2]);
        if (setup.area == 0) continue;
        DrawState state;
        state.depthTest = coin(random);
        state.depthWrite = coin(random);
        state.shadeModel = coin(random) ? ShadeModel::Smooth : ShadeModel::Flat;
        if (i % 3 == 0) {  // a level of detail: the 2 x 2 quads' blocks (shadeNarrowQuads)
            state.texture.env = TextureEnv::Modulate;
            state.texture.base = TextureBase::Rgb;
            state.texture.minFilter = state.texture.magFilter = TextureFilter::Linear;
            state.texture.mipFilter = MipmapFilter::Linear;
            state.texture.texture = texture;
        }
        // A narrow area anywhere, the framebuffer's first or last columns now and then.
        int minX = column(random);
        if (i % 8 == 5) minX = 0;
        const int maxX = std::min(kWidth - 1, minX + columns(random) - 1);
        const int y0 = row(random), y1 = row(random);
        const PixelRect rect{i % 8 == 7 ? kWidth - 1 - (maxX - minX) : minX, i % 8 == 7 ? kWidth - 1 : maxX,
                             std::min(y0, y1), std::max(y0, y1)};
        const std::vector<std::uint32_t> depth = randomPixels(random, kDepthMax24);
        for (const FragmentPaths* paths : allPaths) {
            RasterTriangle triangle;
            const FragmentChoice choice(*paths, triangleFragmentKey(state, Methods{}), state);
            if (!prepareTriangle(setup, choice, RasterMethod::Exact, {0, kWidth - 1, 0, kHeight - 1}, triangle)) break;
            Target expected(color, depth);
            rasterizeTriangleExact(triangle, rect, expected.framebuffer, expected.counts);
            if (paths == allPaths.front()) fragments += expected.counts.fragments;
            expectSpansMatch(expected, triangle, rect, *paths, color, depth, i);
        }
    }
    EXPECT_GT(fragments, 20000u);  // the areas reach covered pixels
}

namespace {

// The draw states of the keys whose fast paths pack tiny triangles (FragmentRoutine::packed) and
// of some that do not: the depth test under GL_LESS and GL_LEQUAL (ties between a triangle and
// its copy), none, smooth and flat, linear fog, blending without depth writes, polygon offset,
// textures of `texture` with a level of detail (with fog: bench-fog-textured-terrain's) or
// without.
std::vector<DrawState> tinyTriangleStates(std::mt19937& random, const std::shared_ptr<const Texture>& texture) {
    std::vector<DrawState> states;
    for (const CompareFunc func : {CompareFunc::Less, CompareFunc::LessEqual, CompareFunc::Always}) {
        for (const ShadeModel shading : {ShadeModel::Smooth, ShadeModel::Flat}) {
            DrawState state;
            state.depthTest = func != CompareFunc::Always;
            state.depthFunc = func;
            state.shadeModel = shading;
            states.push_back(state);
        }
    }
    DrawState fogged = states.front();
    fogged.fog = makeFogState(FogMode::Linear, FogDistance::OwnDotProduct, 1.0f, 2.0f, 25.0f, {0.5f, 0.6f, 0.7f, 1.0f});
    states.push_back(fogged);
    states.push_back(fogged);  // twice: a third of the runs alternate its fog colour
    DrawState blended = states.front();
    blended.depthWrite = false;
    blended.fragmentOps.blend = true;
    blended.fragmentOps.blendSrc = BlendFactor::SrcAlpha, blended.fragmentOps.blendDst = BlendFactor::OneMinusSrcAlpha;
    states.push_back(blended);
    DrawState offset = states.front();
    offset.polygonOffset = {1.5f, -3.0f, true, false, false};
    states.push_back(offset);
    DrawState textured = fogged;
    textured.texture.env = TextureEnv::Modulate;
    textured.texture.base = TextureBase::Rgb;
    textured.texture.minFilter = textured.texture.magFilter = TextureFilter::Linear;
    textured.texture.mipFilter = MipmapFilter::Linear;
    textured.texture.texture = texture;
    states.insert(states.end(), {textured, textured});  // twice, as the fog
    textured.fog = {};
    textured.texture.base = TextureBase::Rgba;
    textured.texture.minFilter = textured.texture.magFilter = TextureFilter::Nearest;
    textured.texture.mipFilter = MipmapFilter::None;
    states.push_back(textured);
    std::shuffle(states.begin(), states.end(), random);
    return states;
}

}  // namespace

// Runs of tiny triangles as a dense mesh's, folded over one another (the same pixel many times
// in a run, triangles repeated exactly: depth ties), each with its own colours, depths and flat
// colour, a few larger ones among them, in one state or alternating between two fog colours
// (other draw constants of one key: the packing stops there), cut to a tile:
// the runs of the paths that pack them into shared blocks against per-pixel coverage, triangle
// after triangle.
TEST(FragmentPaths, PackedRunsOfTinyTrianglesMatchThePerPixelReference) {
    std::mt19937 random(12);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), region(-6.0f, 6.0f);
    std::uniform_int_distribution<int> column(0, kWidth - 1), row(0, kHeight - 1), fifth(0, 4);
    const std::vector<std::uint32_t> color(kWidth * kHeight, 0x80808080u);
    const auto texture = std::make_shared<const Texture>(randomTexture(random, 16, 16));
    const std::vector<DrawState> states = tinyTriangleStates(random, texture);
    int packedRuns = 0;
    for (int i = 0; i < 900; ++i) {
        constexpr int kTriangles = 40;
        std::vector<WindowVertex> vertices;
        std::vector<glm::vec4> flatColors;
        for (int k = 0; k < kTriangles; ++k) {
            const WindowVertex center = randomVertex(random, 1.0f);
            const float size = fifth(random) == 0 ? 8.0f : 1.6f;
            const float x = center.x + region(random), y = center.y + region(random);
            for (int corner = 0; corner < 3; ++corner) {
                WindowVertex v = randomVertex(random, 1.0f);
                v.x = x + size * unit(random), v.y = y + size * unit(random);
                vertices.push_back(v);
            }
            flatColors.push_back(vertices.back().color);
            if (fifth(random) == 0 && k + 1 < kTriangles) {  // the same triangle again
                for (int corner = 0; corner < 3; ++corner) vertices.push_back(vertices[vertices.size() - 3]);
                flatColors.push_back(flatColors.back());
                ++k;
            }
        }
        const DrawState& first = states[static_cast<std::size_t>(i) % states.size()];
        DrawState second = first;
        second.fog.color = {0.1f, 0.2f, 0.3f, 1.0f};
        const bool alternate = i % 3 == 0;
        const int x0 = column(random), y0 = row(random);
        const PixelRect rect = i % 2 ? PixelRect{0, kWidth - 1, 0, kHeight - 1}
                                     : PixelRect{std::max(0, x0 - 32), std::min(kWidth - 1, x0 + 31),
                                                 std::max(0, y0 - 32), std::min(kHeight - 1, y0 + 31)};
        const std::vector<std::uint32_t> depth = randomPixels(random, kDepthMax24);
        for (const FragmentPaths* paths : pathsOfThisCpu()) {
            const FragmentChoice choices[2] = {{*paths, triangleFragmentKey(first, Methods{}), first},
                                               {*paths, triangleFragmentKey(second, Methods{}), second}};
            std::vector<RasterTriangle> triangles(kTriangles);
            std::vector<const RasterTriangle*> run;
            for (int k = 0; k < kTriangles; ++k) {
                const WindowVertex* v = &vertices[static_cast<std::size_t>(3 * k)];
                SetupTriangle setup{{&v[0], &v[1], &v[2]}, {snap(v[0]), snap(v[1]), snap(v[2])}, 0, &flatColors[k]};
                setup.area = fixedArea(setup.fixed[0], setup.fixed[1], setup.fixed[2]);
                if (setup.area == 0) continue;
                const FragmentChoice& choice = choices[alternate ? k % 2 : 0];
                if (prepareTriangle(setup, choice, RasterMethod::Exact, {0, kWidth - 1, 0, kHeight - 1},
                                    triangles[static_cast<std::size_t>(k)])) {
                    run.push_back(&triangles[static_cast<std::size_t>(k)]);
                }
            }
            if (run.empty() || !std::all_of(run.begin(), run.end(), [](const RasterTriangle* t) {
                    return t->fragment.routine->packed != nullptr;
                })) {
                continue;
            }
            Target expected(color, depth), actual(color, depth);
            for (const RasterTriangle* t : run) rasterizeTriangleExact(*t, rect, expected.framebuffer, expected.counts);
            rasterizePackedRun(run, rect, actual.framebuffer, actual.counts);
            ASSERT_TRUE(same(expected, actual))
                << paths->name() << " key " << describe(run.front()->fragment.key()) << " run " << i;
            ++packedRuns;
        }
    }
    // Runs of every state but polygon offset's (no fast path), where the CPU has AVX-512.
    if (cpuHasAvx512()) {
        EXPECT_GT(packedRuns, 800);
    }
}
