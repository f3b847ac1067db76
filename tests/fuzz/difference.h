#pragma once
// Compares the two backends' outcomes of a stream and classifies the first difference.
#include <cstdint>
#include <string>

#include "backend_runner.h"

namespace fuzz {

// In order of precedence: a stream is counted under the first class it shows.
enum class FailureClass { None, Crash, Hang, ErrorSequence, GetAnswers, Color, Depth };
constexpr FailureClass kFailureClasses[] = {FailureClass::Crash,      FailureClass::Hang,  FailureClass::ErrorSequence,
                                            FailureClass::GetAnswers, FailureClass::Color, FailureClass::Depth};
const char* className(FailureClass failure);

struct Difference {
    FailureClass failure = FailureClass::None;
    std::string detail;                             // what differs, in one line
    std::uint32_t call = kFinalFrame;               // the call whose answer differs first (kFinalFrame: none)
    std::string mygl, osmesa;                       // each backend's answer or fate, in words
    bool classes[std::size(kFailureClasses)] = {};  // every class the stream shows

    // The same failure for the shrinker: same class, and for a crash or hang the same fates.
    bool sameFailure(const Difference& other) const;
};

Difference compareOutcomes(const Stream& stream, const BothOutcomes& outcomes);

}  // namespace fuzz
