#pragma once
// Random values from std::mt19937_64 through our own mappings, so that a seed gives the same
// stream with every standard library (the standard distributions' outputs are unspecified).
#include <cstdint>
#include <initializer_list>
#include <random>

namespace fuzz {

class RandomSource {
public:
    explicit RandomSource(std::uint64_t seed) : engine_(seed) {}

    double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
    double uniform(double low, double high) { return low + (high - low) * unit(); }
    bool chance(double probability) { return unit() < probability; }
    // Uniform in [low, high]; the range may be up to 2^63.
    std::int64_t integer(std::int64_t low, std::int64_t high) {
        const auto span = static_cast<std::uint64_t>(high - low) + 1;
        return low + static_cast<std::int64_t>(span == 0 ? engine_() : engine_() % span);
    }
    template <class T>
    T pick(std::initializer_list<T> values) {
        return values.begin()[integer(0, static_cast<std::int64_t>(values.size()) - 1)];
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace fuzz
