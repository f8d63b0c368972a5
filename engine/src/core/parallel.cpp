#include "tessera/core/parallel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace tessera {

namespace {
int g_threads = 1;
std::unique_ptr<tbb::global_control> g_control;
constexpr size_t kGrain = 1024;  // items per chunk: also fixes the summation order
}  // namespace

int set_thread_count(int threads) {
  g_threads = std::max(1, threads);
  g_control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<size_t>(g_threads));
  return g_threads;
}

int thread_count() {
  return g_threads;
}

void parallel_for(size_t n, const std::function<void(size_t, size_t)>& body, size_t grain) {
  if (g_threads <= 1 || n <= grain) {
    body(0, n);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain),
                    [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
}

double deterministic_sum(size_t n, const std::function<double(size_t)>& term) {
  const size_t chunks = (n + kGrain - 1) / kGrain;
  std::vector<double> partial(chunks, 0.0);
  parallel_for(
      chunks,
      [&](size_t c0, size_t c1) {
        for (size_t c = c0; c < c1; ++c) {
          double s = 0.0;
          for (size_t i = c * kGrain, e = std::min(n, (c + 1) * kGrain); i < e; ++i) s += term(i);
          partial[c] = s;
        }
      },
      1);
  double total = 0.0;
  for (double p : partial) total += p;
  return total;
}

}  // namespace tessera
