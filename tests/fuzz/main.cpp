// mygl-fuzz: differential fuzzing of MyGL against OSMesa. Runs random GL call streams (one per
// seed) on both backends and reports every seed whose outcomes differ, optionally shrunk to a
// minimal C snippet. Exit status 0 only if every seed gave identical outcomes, or with
// --expected, every difference is one listed there.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "coverage.h"
#include "difference.h"
#include "generator.h"
#include "reference_departures.h"
#include "shrinker.h"

namespace {

struct Options {
    std::uint64_t start = 1;
    std::uint64_t seeds = 100;
    bool shrink = false;
    bool printStreams = false;
    fuzz::GeneratorOptions generator;
    fuzz::ShrinkOptions shrinking;
    std::map<std::uint64_t, std::string> expected;  // seed -> the class it is known to show
};

// The differences known and not fixed yet: lines "seed class  # cause" (class as the summary
// names it); '#' starts a comment.
std::map<std::uint64_t, std::string> readExpected(const char* path) {
    std::map<std::uint64_t, std::string> expected;
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "mygl-fuzz: cannot read %s\n", path);
        std::exit(2);
    }
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        std::istringstream fields(line);
        std::uint64_t seed;
        std::string failure;  // the rest of the line: a class name may have a space ("get answers")
        if (!(fields >> seed) || !std::getline(fields >> std::ws, failure)) continue;
        failure.erase(failure.find_last_not_of(" \t") + 1);
        if (!failure.empty()) expected[seed] = failure;
    }
    return expected;
}

[[noreturn]] void usage() {
    std::fprintf(stderr,
                 "usage: mygl-fuzz [--seeds N] [--start S] [--shrink] [--size-max M] [--timeout-ms T]\n"
                 "                 [--shrink-trials N] [--print]\n"
                 "  --seeds N        run seeds S .. S+N-1 (default 100 from 1)\n"
                 "  --shrink         shrink each failing stream and print it as C\n"
                 "  --size-max M     framebuffers up to M x M (default 300)\n"
                 "  --timeout-ms T   a backend running a stream longer is hung (default 20000)\n"
                 "  --print          print every stream as C (with --seeds 1: one stream)\n"
                 "  --expected FILE  differences known and not fixed yet (seed class): the run\n"
                 "                   passes when the others are identical and these show as listed\n");
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto number = [&] {
            if (i + 1 >= argc) usage();
            return std::strtoull(argv[++i], nullptr, 10);
        };
        if (arg == "--seeds")
            o.seeds = number();
        else if (arg == "--start")
            o.start = number();
        else if (arg == "--shrink")
            o.shrink = true;
        else if (arg == "--print")
            o.printStreams = true;
        else if (arg == "--size-max")
            o.generator.sizeMax = static_cast<int>(std::max<unsigned long long>(1, number()));
        else if (arg == "--timeout-ms")
            o.shrinking.timeout = std::chrono::milliseconds(number());
        else if (arg == "--shrink-trials")
            o.shrinking.maxTrials = static_cast<int>(number());
        else if (arg == "--expected" && i + 1 < argc)
            o.expected = readExpected(argv[++i]);
        else
            usage();
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse(argc, argv);
    fuzz::AvoidedCounts avoided;
    fuzz::Coverage coverage;
    std::size_t identical = 0, calls = 0, unexpected = 0;
    std::size_t primary[std::size(fuzz::kFailureClasses)] = {}, shown[std::size(fuzz::kFailureClasses)] = {};
    const auto started = std::chrono::steady_clock::now();

    for (std::uint64_t seed = options.start; seed < options.start + options.seeds; ++seed) {
        const fuzz::Stream stream = fuzz::generateStream(seed, options.generator, avoided);
        calls += stream.calls.size();
        const fuzz::BothOutcomes outcomes = fuzz::runOnBothBackends(stream, options.shrinking.timeout);
        coverage.add(stream, outcomes.osmesa);
        const fuzz::Difference d = fuzz::compareOutcomes(stream, outcomes);
        if (options.printStreams)
            std::printf("/* seed %llu */\n%s", static_cast<unsigned long long>(seed),
                        fuzz::toCSnippet(stream, d).c_str());
        for (std::size_t c = 0; c < std::size(shown); ++c) shown[c] += d.classes[c];
        const auto known = options.expected.find(seed);
        const bool asExpected = known != options.expected.end() && known->second == fuzz::className(d.failure);
        if (known != options.expected.end() && !asExpected) {
            std::printf("seed %llu: listed as %s, now %s: update the expected differences\n",
                        static_cast<unsigned long long>(seed), known->second.c_str(), fuzz::className(d.failure));
        }
        if (d.failure == fuzz::FailureClass::None) {
            unexpected += known != options.expected.end();
            ++identical;
            continue;
        }
        unexpected += !asExpected;
        ++primary[static_cast<std::size_t>(d.failure) - 1];
        std::printf("seed %llu (%dx%d, %zu calls): %s: %s\n", static_cast<unsigned long long>(seed), stream.width,
                    stream.height, stream.calls.size(), fuzz::className(d.failure), d.detail.c_str());
        std::fflush(stdout);
        if (options.shrink) {
            const fuzz::ShrinkResult shrunk = fuzz::shrinkStream(stream, d, options.shrinking);
            std::printf("shrunk in %d runs to %zu calls:\n%s\n", shrunk.trials, shrunk.stream.calls.size(),
                        fuzz::toCSnippet(shrunk.stream, shrunk.difference).c_str());
            std::fflush(stdout);
        }
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::printf("\nmygl-fuzz: %llu seeds (%llu..%llu), %zu calls, framebuffers up to %dx%d, %.1f s\n",
                static_cast<unsigned long long>(options.seeds), static_cast<unsigned long long>(options.start),
                static_cast<unsigned long long>(options.start + options.seeds - 1), calls, options.generator.sizeMax,
                options.generator.sizeMax, seconds);
    std::printf("  identical: %zu\n", identical);
    for (std::size_t c = 0; c < std::size(fuzz::kFailureClasses); ++c) {
        std::printf("  %-15s %zu seeds (%zu show it at all)\n",
                    (std::string(fuzz::className(fuzz::kFailureClasses[c])) + ":").c_str(), primary[c], shown[c]);
    }
    std::printf("%s", coverage.summary().c_str());
    std::printf("  calls the generator left out, by reference-departure rule:\n");
    for (const fuzz::Departure& rule : fuzz::referenceDepartures()) {
        std::printf("    %-28s %zu  (%s)\n", rule.name, avoided[rule.name], rule.reason);
    }
    if (!options.expected.empty()) std::printf("  differences not listed as expected: %zu\n", unexpected);
    return unexpected == 0 ? 0 : 1;
}
