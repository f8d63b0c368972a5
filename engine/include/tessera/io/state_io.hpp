// Save and restore of the whole model state, bit for bit (binary, versioned).
#pragma once

#include <string>

#include "tessera/core/model.hpp"

namespace tessera {

// Writes the model; throws std::runtime_error naming the file on failure.
void save_state(const Model& m, const std::string& path);
// Reads a model written by save_state; throws std::runtime_error naming the file on failure,
// among them a file whose indices or counts do not fit together (state_problem).
Model restore_state(const std::string& path);
// Empty if every array of the model has the size its counts say and every index points into
// what it indexes (state_check.cpp); otherwise what does not.
std::string state_problem(const Model& m);

}  // namespace tessera
