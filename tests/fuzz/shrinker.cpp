#include "shrinker.h"

#include <algorithm>
#include <cmath>

#include "reference_departures.h"

namespace fuzz {
namespace {

bool reachesDeparture(const Stream& stream) {
    StreamContext context;
    for (const Call& call : stream.calls) {
        if (departureFor(call, context)) return true;
        context.update(call);
    }
    return false;
}

class Shrinker {
public:
    Shrinker(const Stream& failing, const Difference& failure, const ShrinkOptions& options)
        : best_(failing), failure_(failure), options_(options), start_(std::chrono::steady_clock::now()) {}

    ShrinkResult run() {
        removeChunks();
        shrinkFramebuffer();
        simplifyArguments();
        removeChunks();  // simpler arguments can make more calls unnecessary
        return {best_, failure_, trials_};
    }

private:
    bool budgetLeft() const {
        return trials_ < options_.maxTrials && std::chrono::steady_clock::now() - start_ < options_.maxTime;
    }

    // Runs the candidate; keeps it if it fails the same way. A candidate that reaches a
    // reference departure is not run: it would fail for the reference's reason.
    bool keepIfFailing(Stream candidate) {
        if (reachesDeparture(candidate)) return false;
        ++trials_;
        const Difference d = compareOutcomes(candidate, runOnBothBackends(candidate, options_.timeout));
        if (!d.sameFailure(failure_)) return false;
        best_ = std::move(candidate);
        failure_ = d;
        return true;
    }

    void removeChunks() {
        for (std::size_t chunk = std::max<std::size_t>(1, best_.calls.size() / 2); chunk >= 1 && budgetLeft();
             chunk /= 2) {
            for (std::size_t at = 0; at < best_.calls.size() && budgetLeft();) {
                Stream candidate = best_;
                const auto first = candidate.calls.begin() + static_cast<std::ptrdiff_t>(at);
                candidate.calls.erase(first,
                                      first + static_cast<std::ptrdiff_t>(std::min(chunk, best_.calls.size() - at)));
                if (!keepIfFailing(std::move(candidate))) at += chunk;
            }
        }
    }

    void shrinkFramebuffer() {
        for (bool smaller = true; smaller && budgetLeft();) {
            smaller = false;
            if (best_.width > 1) {
                Stream candidate = best_;
                candidate.width = (best_.width + 1) / 2;
                smaller |= keepIfFailing(std::move(candidate));
            }
            if (best_.height > 1 && budgetLeft()) {
                Stream candidate = best_;
                candidate.height = (best_.height + 1) / 2;
                smaller |= keepIfFailing(std::move(candidate));
            }
        }
    }

    void simplifyArguments() {
        for (std::size_t c = 0; c < best_.calls.size() && budgetLeft(); ++c) {
            for (std::size_t a = 0; a < best_.calls[c].args.size() && budgetLeft(); ++a) {
                const double value = best_.calls[c].args[a];
                for (double simpler : {0.0, 1.0, std::trunc(value)}) {
                    if (simpler == value || std::isnan(value) != std::isnan(simpler) || !budgetLeft()) continue;
                    Stream candidate = best_;
                    candidate.calls[c].args[a] = simpler;
                    if (keepIfFailing(std::move(candidate))) break;
                }
            }
        }
    }

    Stream best_;
    Difference failure_;
    ShrinkOptions options_;
    std::chrono::steady_clock::time_point start_;
    int trials_ = 0;
};

}  // namespace

ShrinkResult shrinkStream(const Stream& failing, const Difference& failure, const ShrinkOptions& options) {
    return Shrinker(failing, failure, options).run();
}

std::string toCSnippet(const Stream& stream, const Difference& difference) {
    std::string text = "/* framebuffer " + std::to_string(stream.width) + "x" + std::to_string(stream.height) + ", " +
                       className(difference.failure) + ": " + difference.detail + " */\n";
    text +=
        "glClearColor(0, 0, 0, 0); glClearDepth(1); glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | "
        "GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);  /* the runner's prologue */\n";
    for (std::size_t i = 0; i < stream.calls.size(); ++i) {
        text += toC(stream.calls[i]);
        if (i == difference.call && !difference.mygl.empty()) {
            text += "  /* mygl: " + difference.mygl + ", osmesa: " + difference.osmesa + " */";
        }
        text += "\n";
    }
    text +=
        "/* then the runner: glEnd(); glEndList(); glGetError() until GL_NO_ERROR; glFinish(); read colour and depth "
        "*/\n";
    return text;
}

}  // namespace fuzz
