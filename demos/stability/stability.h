#pragma once
// Where each method holds and where it breaks: small drawings made exactly where rasterization
// methods are known to fail, each rendered by MyGL with one method and by OSMesa, compared.
#include <glrenderer/methods.h>

#include <functional>
#include <string>
#include <vector>

namespace stability {

struct Method {
    std::string name;
    glrenderer::Methods methods;
};

struct Check {
    std::string name;
    std::function<void(int width, int height)> draw;  // GL 1.x calls through the table
};

std::vector<Method> allMethods();
std::vector<Check> allChecks();

// A check holds for a method when no pixel differs from OSMesa by more than 1 (two surfaces
// tying in depth excepted), i.e. same coverage, same visible surface, colors within 1.
struct Outcome {
    bool holds;
    long long pixelsOver1;
};
Outcome run(const Check& check, const Method& method);

}  // namespace stability
