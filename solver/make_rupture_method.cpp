#include "solver/make_rupture_method.hpp"

#include "solver/fe/finite_element_method.hpp"
#include "solver/spectral/spectral_method.hpp"

#include <algorithm>
#include <thread>

namespace slipfront {

std::unique_ptr<RuptureMethod> make_rupture_method(const SimulationParams& params) {
  if (params.method == Method::spectral_bi) {
    const int threads = params.threads > 0 ? params.threads
                                           : int(std::max(1u, std::thread::hardware_concurrency()));
    return std::make_unique<spectral::SpectralMethod>(params, threads);
  }
  return std::make_unique<fe::FiniteElementMethod>(params);
}

} // namespace slipfront
