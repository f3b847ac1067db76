#pragma once
// What a run of streams exercised: entry points, bad-input classes, texture-image paths, errors
// the reference raised.
#include <map>
#include <string>

#include "backend_runner.h"

namespace fuzz {

class Coverage {
public:
    void add(const Stream& stream, const Outcome& reference);
    std::string summary() const;  // a few indented lines

private:
    std::map<std::string, std::size_t> calls_;
    std::map<std::string, std::size_t> badInput_;
    std::map<std::string, std::size_t> textureImages_;
    std::map<unsigned, std::size_t> errors_;
};

}  // namespace fuzz
