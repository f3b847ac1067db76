#pragma once
// An attribute plane broadcast to the lanes of a lane type L (fragment_stage.h), evaluated at
// pixel (x, y) with the planes' two fmas, in the same order at every width.
#include "triangle_setup.h"

namespace glrenderer {

// `ColumnsFixed`: for a walk whose blocks all lie on the same columns (shadeNarrowRows), the
// inner fma is done once, by fixColumns, and at() then ignores x: the same value, bit for bit.
template <class L, bool ColumnsFixed = false>
struct PlaneLanes {
    typename L::Float a0, dadx, dady;

    explicit PlaneLanes(const AttributePlane& p)
        : a0(L::floats(p.a0)), dadx(L::floats(p.dadx)), dady(L::floats(p.dady)) {}
    typename L::Float at(typename L::Float x, typename L::Float y) const {
        if constexpr (ColumnsFixed) return L::fma(dady, y, a0);
        return L::fma(dady, y, L::fma(dadx, x, a0));
    }
    // The columns x of every later at() (ColumnsFixed only).
    void fixColumns(typename L::Float x) {
        static_assert(ColumnsFixed);
        a0 = L::fma(dadx, x, a0);
    }
    // The plane p in the lanes `lanes` only (a block of several primitives' fragments).
    void take(const AttributePlane& p, typename L::Mask lanes) {
        a0 = L::select(lanes, L::floats(p.a0), a0);
        dadx = L::select(lanes, L::floats(p.dadx), dadx);
        dady = L::select(lanes, L::floats(p.dady), dady);
    }
};

}  // namespace glrenderer
