// Pinocchio's joint-space dynamics on a URDF robot, timed in C++ (no Python in the loop):
// forward dynamics (ABA), ABA's analytic derivatives, the mass matrix (CRBA) and the bias
// torques (RNEA at zero acceleration), each the median of repeated batches at one random state.
// Usage: pinocchio_panda MODEL.bin, a model that Pinocchio read from a URDF file and saved
// with `model.saveToBinary` (robots.py setup); the C++ parser needs urdfdom headers that
// the `pin` wheel lacks. Prints `name,seconds_per_call` lines.
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/serialization.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

template <class F> double median_seconds(F f, int calls) {
  std::vector<double> batches;
  for (int b = 0; b < 15; ++b) {
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < calls; ++i) f();
    auto end = std::chrono::steady_clock::now();
    batches.push_back(std::chrono::duration<double>(end - start).count() / calls);
  }
  std::sort(batches.begin(), batches.end());
  return batches[batches.size() / 2];
}

int main(int argc, char **argv) {
  if (argc < 2) return 2;
  pinocchio::Model model;
  model.loadFromBinary(argv[1]);
  pinocchio::Data data(model);
  Eigen::VectorXd q = pinocchio::randomConfiguration(model);
  Eigen::VectorXd v = Eigen::VectorXd::Random(model.nv);
  Eigen::VectorXd tau = Eigen::VectorXd::Random(model.nv);
  const int calls = 20000;
  std::printf("nv,%d\n", model.nv);
  std::printf("aba,%.4e\n", median_seconds([&] { pinocchio::aba(model, data, q, v, tau); }, calls));
  std::printf("aba_derivatives,%.4e\n",
              median_seconds([&] { pinocchio::computeABADerivatives(model, data, q, v, tau); }, calls));
  std::printf("crba,%.4e\n", median_seconds([&] { pinocchio::crba(model, data, q); }, calls));
  std::printf("nonlinear_effects,%.4e\n", median_seconds([&] { pinocchio::nonLinearEffects(model, data, q, v); }, calls));
  return 0;
}
