// The lighting program of every vector width this CPU runs (AVX2, AVX-512) against the scalar
// one: the same lit colours, bit for bit, for random lights, materials and vertices, including
// the values where the approximations take their special cases (zero, negative, NaN and infinite
// dot products and exponents) and batches whose size is not a multiple of the width.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cpu_features.h"
#include "lighting_paths.h"

using namespace glrenderer;

namespace {

using LightFunction = void (*)(const PreparedLighting&, std::span<Vertex>, std::span<LightingOutputs>, bool);

class RandomLighting {
public:
    explicit RandomLighting(unsigned seed) : random_(seed) {}

    float between(float low, float high) { return std::uniform_real_distribution<float>(low, high)(random_); }
    bool chance(double p) { return std::bernoulli_distribution(p)(random_); }
    glm::vec4 color() { return {between(-0.2f, 1.2f), between(0, 1), between(0, 1), between(0, 1)}; }
    glm::vec3 direction() { return {between(-1, 1), between(-1, 1), between(-1, 1)}; }

    // A value where the program's special cases lie, sometimes.
    float edgy(float usual) {
        if (!chance(0.1)) return usual;
        const float edges[] = {0.0f,
                               -0.0f,
                               std::numeric_limits<float>::quiet_NaN(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity(),
                               1e-40f,
                               3e38f};
        return edges[std::uniform_int_distribution<int>(0, 6)(random_)];
    }

    LightingState state() {
        LightingState s;
        const int lights = std::uniform_int_distribution<int>(0, kMaxLights)(random_);
        for (int i = 0; i < lights; ++i) {
            LightSource& l = s.lights[static_cast<std::size_t>(i)];
            l.enabled = true;
            l.ambient = color(), l.diffuse = color(), l.specular = color();
            l.position = glm::vec4(direction() * 4.0f, chance(0.5) ? 1.0f : 0.0f);
            if (chance(0.5)) {
                l.spotDirection = direction();
                l.spotCutoff = between(0, 90);
                l.spotExponent = chance(0.3) ? 0.0f : between(0, 128);
            }
            if (chance(0.5)) {
                l.constantAttenuation = between(0.5f, 2), l.linearAttenuation = between(0, 1);
                l.quadraticAttenuation = between(0, 1);
            }
        }
        s.modelAmbient = color();
        s.localViewer = chance(0.3);
        s.twoSide = chance(0.5);
        for (Material& m : s.materials) {
            m.ambient = color(), m.diffuse = color(), m.specular = color(), m.emission = color();
            m.shininess = chance(0.3) ? 0.0f : edgy(between(0, 128));
        }
        if (chance(0.4)) s.colorMaterial[0].diffuse = s.colorMaterial[0].ambient = true;
        if (chance(0.2)) s.colorMaterial[1].specular = s.colorMaterial[0].emission = true;
        s.normalize = chance(0.5);
        s.rescaleNormal = chance(0.5);
        return s;
    }

    LightingModelview modelview() {
        LightingModelview m{};
        const float scale = chance(0.5) ? 1.0f : between(0.5f, 2.0f);
        for (int i = 0; i < 16; ++i) m.matrix[static_cast<std::size_t>(i)] = i % 5 == 0 ? scale : between(-0.3f, 0.3f);
        m.matrix[15] = 1.0f;
        // Not the true inverse: the program uses whatever it is given, and so do both widths.
        for (int i = 0; i < 16; ++i)
            m.inverse[static_cast<std::size_t>(i)] = i % 5 == 0 ? 1.0f / scale : between(-0.3f, 0.3f);
        m.lengthPreserving = scale == 1.0f && chance(0.5);
        return m;
    }

    std::vector<Vertex> vertices() {
        std::vector<Vertex> out(std::uniform_int_distribution<std::size_t>(1, 53)(random_));
        for (Vertex& v : out) {
            v.position = {edgy(between(-2, 2)), between(-2, 2), between(-2, 2), chance(0.9) ? 1.0f : between(0.5f, 2)};
            v.normal = {edgy(between(-1, 1)), between(-1, 1), edgy(between(-1, 1))};
            v.color = {edgy(between(-0.5f, 1.5f)), between(0, 1), between(0, 1), between(0, 1)};
        }
        return out;
    }

private:
    std::mt19937 random_;
};

std::vector<std::pair<std::string, LightFunction>> widerPathsOfThisCpu() {
    std::vector<std::pair<std::string, LightFunction>> paths;
    if (cpuHasAvx2Fma()) paths.emplace_back("avx2", &lightVerticesAvx2);
    if (cpuHasAvx512()) paths.emplace_back("avx512", &lightVerticesAvx512);
    return paths;
}

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

}  // namespace

TEST(LightingLanes, EveryWidthLightsAsTheScalarProgram) {
    const auto paths = widerPathsOfThisCpu();
    if (paths.empty()) GTEST_SKIP() << "this CPU runs the scalar program only";
    RandomLighting random(20261126);
    int compared = 0;
    for (int round = 0; round < 400; ++round) {
        const LightingState state = random.state();
        const VertexLighting lighting(state, random.modelview());
        const std::vector<Vertex> input = random.vertices();
        const bool twoSided = state.twoSide;
        std::vector<Vertex> scalar = input;
        std::vector<LightingOutputs> scalarOutputs(input.size());
        lightVerticesScalar(lighting.prepared(), scalar, scalarOutputs, twoSided);
        for (const auto& [name, light] : paths) {
            std::vector<Vertex> wide = input;
            std::vector<LightingOutputs> wideOutputs(input.size());
            light(lighting.prepared(), wide, wideOutputs, twoSided);
            for (std::size_t i = 0; i < input.size(); ++i) {
                for (int c = 0; c < 4; ++c) {
                    ASSERT_EQ(bits(wide[i].color[c]), bits(scalar[i].color[c]))
                        << name << " round " << round << " vertex " << i << " channel " << c;
                    ASSERT_EQ(bits(wideOutputs[i].backColor[c]), bits(scalarOutputs[i].backColor[c]))
                        << name << " round " << round << " vertex " << i << " back channel " << c;
                }
                for (int c = 0; c < 3; ++c) {
                    ASSERT_EQ(bits(wideOutputs[i].secondaryColor[c]), bits(scalarOutputs[i].secondaryColor[c]))
                        << name << " round " << round << " vertex " << i << " secondary channel " << c;
                    ASSERT_EQ(bits(wideOutputs[i].backSecondaryColor[c]), bits(scalarOutputs[i].backSecondaryColor[c]))
                        << name << " round " << round << " vertex " << i << " back secondary channel " << c;
                }
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 4000);
}
