// The C API from C++ (include/interlock.h, the static library with gfortran's runtime in its
// link interface: interlock::interlock_c_static), built against the installed prefix:
//   - the 3D deck's history reproduced step by step through the batched update (as the C test);
//   - 4 std::threads updating disjoint chunks of many points give bitwise the serial results
//     (state, traction, tangent, status, step fraction), 3D (azimuthal RIA, N_a = 3) and 2D,
//     along random separation histories, one material shared by the threads.
// usage: test_c_api_cxx HISTORY_3D.txt
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <fenv.h>

#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <thread>
#include <vector>

#include "c_api_history.h"

namespace {

long failures = 0;

void check(bool ok, const char *what) {
  if (!ok) {
    ++failures;
    std::cerr << "FAILED: " << what << "\n";
  }
}

// Every point's outputs of one step.
struct Outputs {
  std::vector<double> state, traction, tangent, fraction;
  std::vector<int> status;
  Outputs(std::size_t n, int ns, int dim)
      : state(n * ns), traction(n * dim), tangent(n * dim * dim), fraction(n), status(n) {}
  bool operator==(const Outputs &o) const {
    return std::memcmp(state.data(), o.state.data(), state.size() * sizeof(double)) == 0 &&
           std::memcmp(traction.data(), o.traction.data(), traction.size() * sizeof(double)) == 0 &&
           std::memcmp(tangent.data(), o.tangent.data(), tangent.size() * sizeof(double)) == 0 &&
           std::memcmp(fraction.data(), o.fraction.data(), fraction.size() * sizeof(double)) == 0 &&
           status == o.status;
  }
};

// n points along random separation paths (a random walk per point, some steps long enough
// to damage, wear and ask for cuts; a NaN separation on every 97th point), `steps` steps, serially and by 4 threads on disjoint
// chunks of uneven sizes: bitwise the same after every step.
void threads_bitwise(const interlock_material *m, std::size_t n, int steps, const char *what) {
  const int dim = interlock_dim(m), ns = interlock_state_size(m);
  std::mt19937_64 random(20261127);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> start(n * ns), path(n * dim, 0.0), separation(n * dim);
  check(interlock_state_init(m, 0, n, start.data()) == INTERLOCK_OK, "state_init");
  Outputs serial(n, ns, dim), threaded(n, ns, dim);
  std::size_t not_ok = 0, cut = 0;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t p = 0; p < n; ++p) {
      const double size = (p % 7 == 0) ? 0.05 : 0.004;
      path[p * dim] = -0.02 + 0.01 * normal(random);
      for (int c = 1; c < dim; ++c) path[p * dim + c] += size * normal(random);
    }
    // (garbage on some points: refused on every thread alike)
    separation = path;
    for (std::size_t p = step % 5; p < n; p += 97) separation[p * dim + 1] = NAN;
    interlock_update(m, n, separation.data(), start.data(), serial.state.data(),
                     serial.traction.data(), serial.tangent.data(), serial.status.data(),
                     serial.fraction.data());
    // (chunks of uneven sizes: boundaries that are no multiple of anything)
    const std::size_t bounds[5] = {0, n / 5, n / 2 + 3, (3 * n) / 4 + 1, n};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
      threads.emplace_back([&, t] {
        const std::size_t a = bounds[t], b = bounds[t + 1];
        // each thread in chunks of 17 points
        for (std::size_t i = a; i < b; i += 17) {
          const std::size_t k = std::min<std::size_t>(17, b - i);
          interlock_update(m, k, separation.data() + i * dim, start.data() + i * ns,
                           threaded.state.data() + i * ns, threaded.traction.data() + i * dim,
                           threaded.tangent.data() + i * dim * dim, threaded.status.data() + i,
                           threaded.fraction.data() + i);
        }
      });
    }
    for (auto &t : threads) t.join();
    check(serial == threaded, what);
    for (std::size_t p = 0; p < n; ++p) {
      if (serial.status[p] != INTERLOCK_OK) {
        ++not_ok;
        // a refused or failed point keeps its state
        std::memcpy(serial.state.data() + p * ns, start.data() + p * ns, ns * sizeof(double));
      } else if (serial.fraction[p] < 1.0) {
        ++cut;
      }
    }
    start = serial.state;
  }
  std::cout << what << ": " << n << " points x " << steps << " steps, bitwise equal; "
            << not_ok << " point updates not OK, " << cut << " with a suggested cut\n";
  check(cut > 0, "some steps ask for a cut (the random paths reach the accuracy bounds)");
  check(not_ok > 0, "some points are refused");
}

}  // namespace

int main(int argc, char **argv) {
#ifdef INTERLOCK_TEST_TRAPS
  feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
#endif
  if (argc != 2) {
    std::cerr << "usage: test_c_api_cxx HISTORY_3D.txt\n";
    return 2;
  }
  history_t h;
  if (!history_read(argv[1], &h)) {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  interlock_material *m = history_material(&h);
  check(m != nullptr, "the history's material");
  if (!m) return 1;
  double worst = 0.0;
  check(history_replay(m, &h, 4, 0, &worst) == 0, "3D history");
  std::cout << "3D history: " << h.rows << " steps: largest difference " << worst
            << " of the scale\n";
  threads_bitwise(m, 4000, 12, "3D, azimuthal RIA N_a = 3");
  interlock_material_free(m);
  free(h.data);

  const double props[11] = {0.025, 0.025, 0.0005, 0.99, 0.6898538, 4.0, 30.0, 9.0, 6.666, 0.0, 1.0};
  char message[512];
  interlock_material *m2 = nullptr;
  check(interlock_material_from_props(2, 11, props, &m2, message, sizeof message) == INTERLOCK_OK,
        "a 2D material, explicit scheme");
  if (m2) {
    threads_bitwise(m2, 4000, 12, "2D, paper RIA");
    interlock_material_free(m2);
  }
  if (failures) {
    std::cout << failures << " checks FAILED\n";
    return 1;
  }
  std::cout << "all checks passed\n";
  return 0;
}
