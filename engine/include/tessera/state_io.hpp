// Save and restore of the whole model state, bit for bit (binary, versioned).
#pragma once

#include <string>

#include "tessera/model.hpp"

namespace tessera {

// Writes the model; throws std::runtime_error naming the file on failure.
void save_state(const Model& m, const std::string& path);
// Reads a model written by save_state; throws std::runtime_error naming the file on failure.
Model restore_state(const std::string& path);

}  // namespace tessera
