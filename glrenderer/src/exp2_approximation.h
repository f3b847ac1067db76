#pragma once
// gallivm's exp2 (lp_build_exp2), which llvmpipe runs for EX2 and POW: 2^floor(x) from the
// exponent bits times a minimax polynomial of the fraction, evaluated as even and odd halves
// with LLVM's fmuladd (fused on CPUs with FMA). Written once over a lane type L (simd_*.h).
namespace glrenderer {

inline constexpr double kExp2Coefficients[] = {1.0,
                                               0.693153073200168932794,
                                               0.240153617044375388211,
                                               0.0558263180532956664775,
                                               0.00898934009049466391101,
                                               0.00187757667519147912699};

template <class L>
typename L::Float exp2Approximation(typename L::Float x) {
    using Float = typename L::Float;
    x = L::max(L::min(x, L::floats(128.0f)), L::floats(-126.99999f));
    const Float whole = L::floor(x);
    const Float fraction = L::sub(x, whole);
    const Float scale = L::fromBits(L::template shiftLeft<23>(L::add(L::roundToInt(whole), L::ints(127))));
    // The polynomial's terms from the highest: c5, c4 on x^2, then odd * x + even.
    const Float x2 = L::mul(fraction, fraction);
    const auto c = [](int i) { return L::floats(static_cast<float>(kExp2Coefficients[i])); };
    const Float odd = L::multiplyAdd(x2, L::multiplyAdd(x2, c(5), c(3)), c(1));
    const Float even = L::multiplyAdd(x2, L::multiplyAdd(x2, c(4), c(2)), c(0));
    return L::mul(scale, L::multiplyAdd(odd, fraction, even));
}

}  // namespace glrenderer
