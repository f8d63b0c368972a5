// The checks of a model's arrays after each cycle (validation on), for 2D and 3D: a failed one
// throws std::logic_error naming the object; the message is built only then, so a passing check
// costs a comparison (it runs for every block and contact of every cycle).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace tessera {

inline void require(bool ok, const char* what) {
  if (!ok) throw std::logic_error(std::string("validation failed: ") + what);
}

// "validation failed: block 12 has fewer than 3 vertices"
inline void require(bool ok, const char* kind, int64_t number, const char* what) {
  if (!ok)
    throw std::logic_error("validation failed: " + std::string(kind) + " " +
                           std::to_string(number) + " " + what);
}

}  // namespace tessera
