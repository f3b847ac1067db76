#pragma once
// Evaluator state (glMap1/glMap2, glMapGrid, GL_MAPn_* and GL_AUTO_NORMAL), as the reference
// keeps it: control points copied in float, contiguous.
#include <array>
#include <vector>

namespace mygl {

// The attributes a map can give, in the order of GL_MAPn_COLOR_4 ... GL_MAPn_VERTEX_4.
enum class MapTarget { Color4, Index, Normal, Texture1, Texture2, Texture3, Texture4, Vertex3, Vertex4 };
inline constexpr int kMapTargets = 9;
inline constexpr int kMaxEvalOrder = 30;

struct Map {
    int uorder = 1, vorder = 1;
    float u1 = 0, u2 = 1, v1 = 0, v2 = 1;
    float du = 0, dv = 0;  // 1 / (u2 - u1), set by glMap (the initial maps keep 0)
    std::vector<float> points;
};

struct Evaluators {
    Evaluators();
    std::array<Map, kMapTargets> map1, map2;
    std::array<bool, kMapTargets> enabled1{}, enabled2{};
    bool autoNormal = false;
    // glMapGrid: segments, domain and step (du, dv start at 0: the reference does not set them).
    int grid1un = 1;
    float grid1u1 = 0, grid1u2 = 1, grid1du = 0;
    int grid2un = 1, grid2vn = 1;
    float grid2u1 = 0, grid2u2 = 1, grid2du = 0, grid2v1 = 0, grid2v2 = 1, grid2dv = 0;
    bool operator==(const Evaluators&) const = default;
};

}  // namespace mygl
