#include "solver/run/probe_recorder.hpp"

#include "solver/run/periodic_line.hpp"

namespace slipfront {

ProbeRecorder::ProbeRecorder(const Probes& probes, double x_min, double dx,
                             const std::vector<double>& x1)
    : arrival_node_(nearest_node(probes.arrival_x1, x_min, dx, int(x1.size()))),
      spectrum_node_(nearest_node(probes.spectrum_x1, x_min, dx, int(x1.size()))) {
  records_.arrival_node_x1 = x1[arrival_node_];
  records_.spectrum_node_x1 = x1[spectrum_node_];
}

void ProbeRecorder::record(const InterfaceFields& f, double t_n) {
  records_.time.push_back(t_n);
  records_.slip_velocity_arrival.push_back(f.velocity[arrival_node_]);
  records_.slip_velocity_spectrum.push_back(f.velocity[spectrum_node_]);
  records_.strength_spectrum.push_back(f.strength[spectrum_node_]);
}

} // namespace slipfront
