// Deterministic parallel loops: results never depend on the number of threads.
//
// Loops write only to their own index, and sums are taken over fixed-size chunks whose partial
// sums are added in chunk order, so the floating-point result is the same at every thread count.
#pragma once

#include <cstddef>
#include <functional>

namespace tessera {

// Sets the number of worker threads (1 = serial). Returns the number in force.
int set_thread_count(int threads);
int thread_count();

// Runs body(begin, end) over [0, n) in chunks, possibly in parallel.
void parallel_for(size_t n, const std::function<void(size_t, size_t)>& body, size_t grain = 1024);

// Sum of term(i) over [0, n), bit-identical at every thread count.
double deterministic_sum(size_t n, const std::function<double(size_t)>& term);

}  // namespace tessera
