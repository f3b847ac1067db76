// mygl-accuracy: runs the whole generated conformance table outside the test runner and prints,
// per category, how many cases match OSMesa, how many pixels differ and how many observations
// (glGetError after each call, query answers: the API cases) differ.
#include <cstdio>
#include <map>
#include <string>

#include "runner.h"

int main() {
    struct Totals {
        long long cases = 0, passing = 0, pixels = 0, differing = 0, over1 = 0, ties = 0, observations = 0,
                  observationsDiffering = 0;
        int max = 0;
    };
    std::map<std::string, Totals> categories;
    Totals all;
    conformance::Runner runner;
    for (const conformance::Case& c : conformance::allCases()) {
        const conformance::Result r = runner.run(c);
        for (Totals* t : {&categories[c.category], &all}) {
            ++t->cases;
            t->passing += r.passed;
            t->pixels += r.comparison.pixels;
            t->differing += r.comparison.differing;
            t->over1 += r.comparison.differingMoreThan1;
            t->ties += r.depthTies;
            t->observations += static_cast<long long>(r.observations);
            t->observationsDiffering += static_cast<long long>(r.observationsDiffering);
            t->max = std::max(t->max, r.comparison.maxChannelDifference);
        }
        if (!r.passed && r.observations == 0)
            std::printf("differs: %s %s\n", c.name.c_str(), reference::toString(r.comparison).c_str());
        if (!r.passed && r.observations > 0)
            std::printf("differs: %s %s observations differing=%zu/%zu %s\n", c.name.c_str(),
                        reference::toString(r.comparison).c_str(), r.observationsDiffering, r.observations,
                        r.firstObservationDifference.c_str());
    }
    std::printf(
        "| category | cases | passing | pixels | differing | >1 | depth ties | max | observations | differing |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    auto row = [](const std::string& name, const Totals& t) {
        std::printf("| %s | %lld | %lld | %lld | %lld | %lld | %lld | %d | %lld | %lld |\n", name.c_str(), t.cases,
                    t.passing, t.pixels, t.differing, t.over1, t.ties, t.max, t.observations, t.observationsDiffering);
    };
    for (const auto& [name, t] : categories) row(name, t);
    row("**total**", all);
    return all.passing == all.cases ? 0 : 1;
}
